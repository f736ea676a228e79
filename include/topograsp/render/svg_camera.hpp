// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The look of a rendering: colours (Rgb, the figures' palette svg_colours) and the orthographic
/// camera with the image settings (SvgCamera).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include <topograsp/core/eigen.hpp>

namespace topograsp {

/// A colour as 8-bit red, green and blue.
struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend constexpr bool operator==(const Rgb&, const Rgb&) = default;
};

/// The colours the figures use: one per kind of body, and the curve palette (the same as
/// SvgLinePlot's series colours, so that gamma_i has one colour in every figure).
namespace svg_colours {
inline constexpr Rgb skin{226, 180, 150};   ///< a human hand
inline constexpr Rgb robot{168, 176, 188};  ///< a robot hand (aluminium)
inline constexpr Rgb wood{200, 150, 90};    ///< a wooden handle
inline constexpr Rgb steel{110, 116, 128};  ///< a steel part
inline constexpr Rgb object{96, 150, 210};  ///< any other object
/// The colour of hand curve \p i (0-based), cycling through 7 colours.
[[nodiscard]] constexpr Rgb curve(std::size_t i) noexcept {
  constexpr Rgb palette[] = {{31, 119, 180},  {214, 39, 40}, {44, 160, 44}, {255, 127, 14},
                             {148, 103, 189}, {140, 86, 75}, {23, 190, 207}};
  return palette[i % 7];
}
}  // namespace svg_colours

/// An orthographic camera and the image settings of one rendering.
///
/// The camera looks along \c direction; \c up (projected) points up in the image. With \c zoom
/// 0 the scene is fitted into the image (minus \c margin, a title and a caption); otherwise
/// \c zoom is pixels per metre and the image is centred on \c target (default: the centre of the
/// scene's projected bounding box).
struct SvgCamera {
  Vec3 direction{-1.0, -0.35, -0.45};  ///< view direction, from the eye into the scene (world)
  Vec3 up = Vec3::UnitZ();             ///< world direction shown upward; not along direction
  double zoom = 0.0;                   ///< pixels per metre; 0 fits the scene
  std::optional<Vec3> target;          ///< world point at the image centre (with zoom > 0)
  int width = 480;                     ///< image width (px, >= 16)
  int height = 400;                    ///< image height (px, >= 16)
  double margin = 16.0;                ///< free border around a fitted scene (px)
  int segments = 16;                   ///< polygons around a round shape (4..128)
  double max_edge = 0.0;         ///< split flat parts longer than this (m); 0: a tenth of the scene
  Vec3 light{-0.45, 0.6, 0.65};  ///< toward the light, in (right, up, toward the eye)
};

}  // namespace topograsp

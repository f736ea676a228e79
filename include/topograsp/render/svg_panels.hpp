// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Several renderings side by side in one SVG document, each with a caption (svg_panels): the
/// figures that compare grasps.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/io/text_file.hpp>
#include <topograsp/render/svg_scene.hpp>

namespace topograsp {

/// One panel of svg_panels(): a scene, its camera and a caption under it.
struct SvgPanel {
  SvgScene scene;
  SvgCamera camera{};
  std::string caption;   ///< under the panel; '\n' starts a new line
  Rgb caption_colour{};  ///< e.g. green for a stable grasp, red for an unstable one
};

/// Several renderings side by side in one SVG document, each with its caption under it and
/// \p title over them all. With \p common_scale, every panel whose camera has zoom 0 is drawn
/// at the smallest of their fitted zooms, so that sizes compare across panels.
/// \throws topograsp::invalid_argument naming the bad camera field of a panel.
[[nodiscard]] inline std::string svg_panels(std::span<const SvgPanel> panels,
                                            std::string_view title = {}, bool common_scale = true) {
  double zoom = std::numeric_limits<double>::infinity();
  if (common_scale)
    for (const SvgPanel& p : panels)
      if (p.camera.zoom == 0.0) {
        const double z = p.scene.fit_zoom(p.camera);
        if (z > 0.0) zoom = std::min(zoom, z);
      }
  const double gap = 12.0, top = title.empty() ? 0.0 : 34.0;
  double width = 0.0, height = 0.0;
  std::size_t caption_lines = 0;
  for (const SvgPanel& p : panels) {
    width += p.camera.width + (width > 0.0 ? gap : 0.0);
    height = std::max(height, static_cast<double>(p.camera.height));
    caption_lines = std::max(caption_lines, SvgScene::split_lines(p.caption).size());
  }
  const double total_h =
      top + height + 18.0 * static_cast<double>(caption_lines) + (caption_lines > 0 ? 10.0 : 0.0);
  const int w = std::max(16, static_cast<int>(std::ceil(width))),
            h = std::max(16, static_cast<int>(std::ceil(total_h)));
  std::string o;
  if (!title.empty()) o += SvgScene::text(0.5 * w, 22.0, title, "middle", 16);
  double x = 0.0;
  for (const SvgPanel& p : panels) {
    SvgCamera c = p.camera;
    if (common_scale && c.zoom == 0.0 && std::isfinite(zoom)) c.zoom = zoom;
    const std::string body = p.scene.svg_body(c);
    o += "<svg x=\"" + detail::svg_number(x) + "\" y=\"" + detail::svg_number(top) + "\" width=\"" +
         std::to_string(c.width) + "\" height=\"" + std::to_string(c.height) + "\" viewBox=\"0 0 " +
         std::to_string(c.width) + " " + std::to_string(c.height) + "\">\n" + body + "</svg>\n";
    const std::vector<std::string> lines = SvgScene::split_lines(p.caption);
    for (std::size_t k = 0; k < lines.size(); ++k)
      o += SvgScene::text(x + 0.5 * c.width, top + c.height + 16.0 + 18.0 * static_cast<double>(k),
                          lines[k], "middle", 14, p.caption_colour);
    x += c.width + gap;
  }
  return SvgScene::svg_document(w, h, o);
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// A recorded human grasp as 21 hand keypoints (the order of MANO-based datasets: DexYCB, HO-3D,
/// OakInk, GRAB) and the winding descriptor straight from them: the hand curves run through the
/// keypoints as the human model's run through its joints. Files: io/keypoint_grasp.hpp; the
/// human model fitted to them: grasp/keypoint_fit.hpp.
///
/// Keypoint order: 0 wrist; 1-4 thumb CMC, MCP, IP, tip; 5-8 index MCP, PIP, DIP, tip; 9-12
/// middle; 13-16 ring; 17-20 little.
#pragma once

#include <array>
#include <string>

#include <topograsp/core/eigen.hpp>
#include <topograsp/task/winding.hpp>

namespace topograsp {

/// The number of hand keypoints of a recorded grasp.
inline constexpr int keypoint_count = 21;

/// A recorded human grasp: its object's name and the 21 keypoints in the object frame (m).
struct KeypointGrasp {
  std::string object;
  /// All at the origin until set (an Eigen vector's `{}` leaves it uninitialised).
  std::array<Vec3, keypoint_count> keypoints = [] {
    std::array<Vec3, keypoint_count> a;
    a.fill(Vec3::Zero());
    return a;
  }();
};

/// The hand curves through the keypoints of \p g, one per finger (index, middle, ring, little),
/// as the human model's hand curves run: thumb tip, IP, MCP, CMC, the palm centre (the centroid
/// of the wrist and the four finger MCPs), then the finger's MCP, PIP, DIP and tip.
[[nodiscard]] inline std::array<std::array<Vec3, 9>, 4> keypoint_curves(const KeypointGrasp& g) {
  const auto& k = g.keypoints;
  const Vec3 palm = (k[0] + k[5] + k[9] + k[13] + k[17]) / 5.0;
  std::array<std::array<Vec3, 9>, 4> curves;
  for (std::size_t f = 0; f < 4; ++f) {
    const std::size_t base = 5 + 4 * f;
    curves[f] = {k[4], k[3], k[2], k[1], palm, k[base], k[base + 1], k[base + 2], k[base + 3]};
  }
  return curves;
}

/// The windings (turns) of the four keypoint curves of \p g around \p p (object frame).
/// \throws topograsp::invalid_argument as winding() for a point that is not finite.
[[nodiscard]] inline Eigen::Vector4d keypoint_windings(const KeypointGrasp& g, const Vec3& p) {
  Eigen::Vector4d w;
  const auto curves = keypoint_curves(g);
  for (std::size_t f = 0; f < 4; ++f) w[static_cast<Eigen::Index>(f)] = winding(curves[f], p);
  return w;
}

}  // namespace topograsp

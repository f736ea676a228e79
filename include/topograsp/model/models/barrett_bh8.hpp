// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Barrett BH8-282 hand: three fingers, 8 joints, 4 motors. One motor spreads fingers 1 and 2
/// symmetrically; each distal joint is coupled to its medial joint. A hand with a structure
/// different from the SDH, to show the methods work on any hand. Sources: docs/models.md.
#pragma once

#include <topograsp/core/constants.hpp>
#include <topograsp/model/model.hpp>

namespace topograsp::models {

/// Lengths of the BH8-282 (m), from the ROS description (docs/models.md).
namespace barrett_dims {
inline constexpr double medial = 0.069936;  ///< medial to distal joint
inline constexpr double distal = 0.055;     ///< distal joint to the fingertip
inline constexpr double coupling = 0.3;     ///< distal = coupling * medial + coupling_offset
inline constexpr double coupling_offset = 0.75;
}  // namespace barrett_dims

/// The Barrett hand with its palm base at the origin and the fingers along +z. Configuration:
/// [spread, finger_1_med, finger_2_med, finger_3_med] (rad). Finger 3 (fixed base) is the thumb;
/// spread 0 puts fingers 1 and 2 side by side opposite it.
inline constexpr auto barrett_bh8 = [] {
  using namespace barrett_dims;
  constexpr std::array<double, 3> ez{0.0, 0.0, 1.0}, mz{0.0, 0.0, -1.0};
  constexpr double h = pi / 2.0;
  return make_model(
      "barrett_bh8",
      links(root("base"),
            revolute("finger_1_prox", "base", at(0.025, 0, 0.0415).rpy(0, 0, -h), mz, 0.0, pi),
            revolute("finger_1_med", "finger_1_prox", at(-0.05, 0, 0.0339).rpy(-h, 0, 0), ez, 0.0,
                     2.44)
                .closes(1),
            revolute("finger_1_dist", "finger_1_med", at(-medial, -0.003, 0), ez, 0.6, 1.57)
                .mimics("finger_1_med", coupling, coupling_offset),
            revolute("finger_2_prox", "base", at(-0.025, 0, 0.0415).rpy(0, 0, -h), ez, 0.0, pi)
                .mimics("finger_1_prox", 1.0, 0.0),
            revolute("finger_2_med", "finger_2_prox", at(-0.05, 0, 0.0339).rpy(-h, 0, 0), ez, 0.0,
                     2.44)
                .closes(1),
            revolute("finger_2_dist", "finger_2_med", at(-0.069917, -0.0034087, 0), ez, 0.6, 1.57)
                .mimics("finger_2_med", coupling, coupling_offset),
            revolute("finger_3_med", "base", at(0, -0.05, 0.0754).rpy(-h, 0, h), ez, 0.0, 2.44)
                .closes(1),
            revolute("finger_3_dist", "finger_3_med", at(-medial, -0.003, 0), ez, 0.6, 1.57)
                .mimics("finger_3_med", coupling, coupling_offset)),
      shapes(cylinder("base", at(0, 0, 0.0375), 0.045, 0.0375),
             capsule("finger_1_prox", {0, 0, 0.02}, {-0.05, 0, 0.0339}, 0.012),
             capsule("finger_1_med", {0, 0, 0}, {-medial, -0.003, 0}, 0.012),
             capsule("finger_1_dist", {0, 0, 0}, {-distal + 0.01, 0, 0}, 0.011),
             capsule("finger_2_prox", {0, 0, 0.02}, {-0.05, 0, 0.0339}, 0.012),
             capsule("finger_2_med", {0, 0, 0}, {-medial, -0.003, 0}, 0.012),
             capsule("finger_2_dist", {0, 0, 0}, {-distal + 0.01, 0, 0}, 0.011),
             capsule("finger_3_med", {0, 0, 0}, {-medial, -0.003, 0}, 0.012),
             capsule("finger_3_dist", {0, 0, 0}, {-distal + 0.01, 0, 0}, 0.011)),
      frames(frame("tip_1", "finger_1_dist", at(-distal, 0, 0)),
             frame("tip_2", "finger_2_dist", at(-distal, 0, 0)),
             frame("thumb_tip", "finger_3_dist", at(-distal, 0, 0)),
             frame("palm_centre", "base", at(0, 0, 0.075))),
      hand("palm_centre", finger("finger_1", {"finger_1_med", "finger_1_dist", "tip_1"}),
           finger("finger_2", {"finger_2_med", "finger_2_dist", "tip_2"}),
           thumb("thumb", {"finger_3_med", "finger_3_dist", "thumb_tip"})));
}();

}  // namespace topograsp::models

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Barrett BH8-282 hand: three fingers, 8 joints, 4 motors. One motor spreads fingers 1 and 2
/// symmetrically; each distal joint is coupled to its medial joint. A hand with a structure
/// different from the SDH, to show the methods work on any hand. Sources: docs/models.md; the
/// actuators (torque, speed, armature) and link masses: docs/models.md, "Actuators and masses".
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

/// Actuators and masses of the BH8-282 (docs/models.md, "Actuators and masses").
namespace barrett_dynamics {
inline constexpr double finger_torque = 1.9;   ///< N m: 15 N at the tip, 0.125 m out (derived)
inline constexpr double spread_torque = 1.0;   ///< N m (assumed: no published figure)
inline constexpr double finger_speed = 2.44;   ///< rad/s: 140 degrees in 1.0 s
inline constexpr double spread_speed = 6.28;   ///< rad/s: 180 degrees in 0.5 s
inline constexpr double armature = 1e-4;       ///< kg m^2 (assumed)
inline constexpr double base_mass = 0.50573;   ///< kg, jhu-lcsr/barrett_model
inline constexpr double prox_mass = 0.14109;   ///< kg, the same
inline constexpr double med_mass = 0.062139;   ///< kg, the same
inline constexpr double dist_mass = 0.041377;  ///< kg, the same
}  // namespace barrett_dynamics

/// The Barrett hand with its palm base at the origin and the fingers along +z. Configuration:
/// [spread, finger_1_med, finger_2_med, finger_3_med] (rad). Finger 3 (fixed base) is the thumb;
/// spread 0 puts fingers 1 and 2 side by side opposite it.
inline constexpr auto barrett_bh8 = [] {
  using namespace barrett_dims;
  using namespace barrett_dynamics;
  constexpr std::array<double, 3> ez{0.0, 0.0, 1.0}, mz{0.0, 0.0, -1.0};
  constexpr std::array<double, 3> prox_com{-0.0231, 0, 0.0005}, med_com{-0.0231, 0, 0},
      dist_com{-0.0228, 0, 0};
  constexpr double h = pi / 2.0;
  return make_model(
      "barrett_bh8",
      links(root("base").inertial(base_mass, {0.0, -0.005, 0.0367}),
            revolute("finger_1_prox", "base", at(0.025, 0, 0.0415).rpy(0, 0, -h), mz, 0.0, pi)
                .actuator(spread_torque, spread_speed, armature)
                .inertial(prox_mass, prox_com),
            revolute("finger_1_med", "finger_1_prox", at(-0.05, 0, 0.0339).rpy(-h, 0, 0), ez, 0.0,
                     2.44)
                .closes(1)
                .actuator(finger_torque, finger_speed, armature)
                .inertial(med_mass, med_com),
            revolute("finger_1_dist", "finger_1_med", at(-medial, -0.003, 0), ez, 0.6, 1.57)
                .mimics("finger_1_med", coupling, coupling_offset)
                .inertial(dist_mass, dist_com),
            revolute("finger_2_prox", "base", at(-0.025, 0, 0.0415).rpy(0, 0, -h), ez, 0.0, pi)
                .mimics("finger_1_prox", 1.0, 0.0)
                .inertial(prox_mass, prox_com),
            revolute("finger_2_med", "finger_2_prox", at(-0.05, 0, 0.0339).rpy(-h, 0, 0), ez, 0.0,
                     2.44)
                .closes(1)
                .actuator(finger_torque, finger_speed, armature)
                .inertial(med_mass, med_com),
            revolute("finger_2_dist", "finger_2_med", at(-0.069917, -0.0034087, 0), ez, 0.6, 1.57)
                .mimics("finger_2_med", coupling, coupling_offset)
                .inertial(dist_mass, dist_com),
            revolute("finger_3_med", "base", at(0, -0.05, 0.0754).rpy(-h, 0, h), ez, 0.0, 2.44)
                .closes(1)
                .actuator(finger_torque, finger_speed, armature)
                .inertial(med_mass, med_com),
            revolute("finger_3_dist", "finger_3_med", at(-medial, -0.003, 0), ez, 0.6, 1.57)
                .mimics("finger_3_med", coupling, coupling_offset)
                .inertial(dist_mass, dist_com)),
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

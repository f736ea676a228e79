// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Schunk SDH (SDH2) three-finger hand: 8 revolute joints, 7 actuated (the knuckle drives
/// fingers 1 and 2 mirror-symmetrically), a fixed thumb base. Sources: docs/models.md; the
/// actuators (torque, speed, armature) and link masses: docs/models.md, "Actuators and masses".
#pragma once

#include <topograsp/model/model.hpp>

namespace topograsp::models {

/// Lengths of the SDH (m), from the Schunk URDF and SDHLibrary (docs/models.md).
namespace sdh_dims {
inline constexpr double base_height = 0.0745;     ///< palm flange to the finger bases
inline constexpr double knuckle_height = 0.0165;  ///< finger base to the proximal flexion axis
inline constexpr double proximal = 0.0865;        ///< proximal to distal flexion axis
inline constexpr double distal = 0.0685;          ///< distal flexion axis to the fingertip
inline constexpr double finger_x = 0.01905;       ///< finger bases 1 and 2 (x, +-y)
inline constexpr double finger_y = 0.033;
inline constexpr double thumb_x = -0.03811;       ///< thumb base (x, 0)
inline constexpr double phalanx_radius = 0.014;   ///< capsule radius of a phalanx
inline constexpr double distal_capsule = 0.0545;  ///< capsule segment of the distal link
}  // namespace sdh_dims

/// Actuators and masses of the SDH (docs/models.md, "Actuators and masses").
namespace sdh_dynamics {
inline constexpr double proximal_torque = 2.1;  ///< N m, SDH2 datasheet
inline constexpr double distal_torque = 1.4;    ///< N m, SDH2 datasheet
inline constexpr double knuckle_torque = 1.4;   ///< N m (assumed: no published figure)
inline constexpr double knuckle_speed = 1.396;  ///< rad/s, SDHLibrary: 80 deg/s (axis 0)
inline constexpr double finger_speed = 1.745;   ///< rad/s, SDHLibrary: 100 deg/s (axes 1-6)
inline constexpr double armature = 1e-4;        ///< kg m^2 (assumed)
inline constexpr double palm_mass = 1.0288;     ///< kg, Schunk URDF
inline constexpr double knuckle_mass = 0.047;   ///< kg, Schunk URDF
inline constexpr double proximal_mass = 0.167;  ///< kg, Schunk URDF
inline constexpr double distal_mass = 0.0929;   ///< kg, Schunk URDF
}  // namespace sdh_dynamics

/// The SDH with its palm flange at the origin and the fingers along +z. Configuration:
/// [knuckle, finger_12, finger_13, finger_22, finger_23, thumb_2, thumb_3] (rad); positive
/// flexion closes toward the opposing finger(s); knuckle 0 = fingers 1, 2 face the thumb,
/// pi/3 = all three 120 degrees apart, pi/2 = fingers 1 and 2 face each other.
inline constexpr auto schunk_sdh = [] {
  using namespace sdh_dims;
  using namespace sdh_dynamics;
  constexpr double h = pi / 2.0;
  constexpr std::array<double, 3> knuckle_com{0, 0, 0.0153}, proximal_com{0, 0, proximal / 2},
      distal_com{0, 0, distal_capsule / 2};
  constexpr std::array<double, 3> ey{0.0, 1.0, 0.0};
  return make_model(
      "schunk_sdh",
      links(
          root("palm").inertial(palm_mass, {-0.0101, 0.0, 0.0357}),
          revolute("knuckle", "palm", at(finger_x, finger_y, base_height).rpy(0, 0, pi), {0, 0, 1},
                   0.0, h)
              .actuator(knuckle_torque, knuckle_speed, armature)
              .inertial(knuckle_mass, knuckle_com),
          revolute("finger_12", "knuckle", at(0, 0, knuckle_height), ey, -h, h)
              .closes(1)
              .actuator(proximal_torque, finger_speed, armature)
              .inertial(proximal_mass, proximal_com),
          revolute("finger_13", "finger_12", at(0, 0, proximal), ey, -h, h)
              .closes(1)
              .actuator(distal_torque, finger_speed, armature)
              .inertial(distal_mass, distal_com),
          revolute("knuckle_2", "palm", at(finger_x, -finger_y, base_height).rpy(0, 0, pi),
                   {0, 0, -1}, 0.0, h)
              .mimics("knuckle", 1.0, 0.0)
              .inertial(knuckle_mass, knuckle_com),
          revolute("finger_22", "knuckle_2", at(0, 0, knuckle_height), ey, -h, h)
              .closes(1)
              .actuator(proximal_torque, finger_speed, armature)
              .inertial(proximal_mass, proximal_com),
          revolute("finger_23", "finger_22", at(0, 0, proximal), ey, -h, h)
              .closes(1)
              .actuator(distal_torque, finger_speed, armature)
              .inertial(distal_mass, distal_com),
          fixed("thumb_1", "palm", at(thumb_x, 0, base_height)).inertial(knuckle_mass, knuckle_com),
          revolute("thumb_2", "thumb_1", at(0, 0, knuckle_height), ey, -h, h)
              .closes(1)
              .actuator(proximal_torque, finger_speed, armature)
              .inertial(proximal_mass, proximal_com),
          revolute("thumb_3", "thumb_2", at(0, 0, proximal), ey, -h, h)
              .closes(1)
              .actuator(distal_torque, finger_speed, armature)
              .inertial(distal_mass, distal_com)),
      shapes(cylinder("palm", at(-0.0101, 0.0, 0.0357), 0.060, 0.0385),
             cylinder("knuckle", at(0, 0, 0.0153), 0.0225, 0.0152),
             cylinder("knuckle_2", at(0, 0, 0.0153), 0.0225, 0.0152),
             cylinder("thumb_1", at(0, 0, 0.0153), 0.0225, 0.0152),
             capsule("finger_12", {0, 0, 0}, {0, 0, proximal}, phalanx_radius),
             capsule("finger_13", {0, 0, 0}, {0, 0, distal_capsule}, phalanx_radius),
             capsule("finger_22", {0, 0, 0}, {0, 0, proximal}, phalanx_radius),
             capsule("finger_23", {0, 0, 0}, {0, 0, distal_capsule}, phalanx_radius),
             capsule("thumb_2", {0, 0, 0}, {0, 0, proximal}, phalanx_radius),
             capsule("thumb_3", {0, 0, 0}, {0, 0, distal_capsule}, phalanx_radius)),
      frames(frame("tip_1", "finger_13", at(0, 0, distal)),
             frame("tip_2", "finger_23", at(0, 0, distal)),
             frame("thumb_tip", "thumb_3", at(0, 0, distal)),
             frame("palm_centre", "palm", at(0, 0, base_height)),
             frame("grasp_centre", "palm", at(0, 0, 0.15))),
      hand("palm_centre", finger("finger_1", {"finger_12", "finger_13", "tip_1"}),
           finger("finger_2", {"finger_22", "finger_23", "tip_2"}),
           thumb("thumb", {"thumb_2", "thumb_3", "thumb_tip"})));
}();

}  // namespace topograsp::models

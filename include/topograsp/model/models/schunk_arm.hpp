// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The 7-DOF Schunk arm of the Toussaint lab (PowerCube PRL modules), as in its ORS model, which is
/// most probably the paper's robot. Every joint is a hinge about its local x axis. Sources and the
/// assumed joint limits: docs/models.md.
#pragma once

#include <topograsp/core/constants.hpp>
#include <topograsp/model/model.hpp>

namespace topograsp::models {

namespace detail {
// ORS transforms: t(x y z) a translation, d(deg ax ay az) a rotation in degrees.
constexpr Pose t(double x, double y, double z) { return translation(x, y, z); }
constexpr Pose d(double degrees, double ax, double ay, double az) {
  return rotation_axis_angle(ax, ay, az, deg(degrees));
}
// The joint origins (ORS "A" transforms) of modules m3..m9, composed exactly as the file writes
// them; the arm's base body stands 0.25 m above the floor.
inline constexpr Pose arm_a1 = t(0, 0, 0.25) * t(0, .25, 0) * d(25, 0, 0, 1) * d(15, 1, 0, 0) *
                               t(0, 0, .85) * d(180, 0, 0, 1) * t(0, 0, 0.120) * d(90, 0, 1, 0);
inline constexpr Pose arm_a2 = d(90, 0, 1, 0) * t(-0.175, 0, 0) * d(-105, 1, 0, 0);
inline constexpr Pose arm_a3 = t(-0.175, 0, 0) * d(-90, 0, 1, 0) * d(90, 1, 0, 0);
inline constexpr Pose arm_a4 = d(90, 0, 1, 0) * t(-0.1515, 0, 0) * d(-90, 1, 0, 0);
inline constexpr Pose arm_a5 = t(-0.1515, 0, 0) * d(-90, 0, 1, 0) * d(-90, 1, 0, 0);
inline constexpr Pose arm_a6 = d(-90, 0, 1, 0) * t(-0.12575, 0, 0) * d(-90, 1, 0, 0);
inline constexpr Pose arm_a7 = t(-0.12575, 0, 0) * d(90, 0, 1, 0);
// m9 to the SDH palm flange: 0.1024 m out along the hand axis (0.1074 to the hand root, 0.086 more
// to the flexion plane, which the URDF palm puts 0.091 above its flange), thumb toward -x.
inline constexpr Pose arm_flange = d(180, 1, 0, 0) * t(0, 0, 0.1024) * d(-90, 0, 0, 1);
}  // namespace detail

/// The Schunk 7-DOF arm, base on the floor at the origin, with a "flange" frame where the SDH's
/// palm goes. Configuration: [arm_1 .. arm_7] (rad). Limits +-pi (odd joints) and +-1.97 rad
/// (even joints), taken from the Schunk LWA (the ORS file has none).
inline constexpr auto schunk_arm = [] {
  using namespace detail;
  constexpr std::array<double, 3> ex{1.0, 0.0, 0.0};
  constexpr double odd = pi, even = 1.97;
  return make_model(
      "schunk_arm",
      links(root("arm_base"), revolute("arm_1", "arm_base", arm_a1, ex, -odd, odd),
            revolute("arm_2", "arm_1", arm_a2, ex, -even, even),
            revolute("arm_3", "arm_2", arm_a3, ex, -odd, odd),
            revolute("arm_4", "arm_3", arm_a4, ex, -even, even),
            revolute("arm_5", "arm_4", arm_a5, ex, -odd, odd),
            revolute("arm_6", "arm_5", arm_a6, ex, -even, even),
            revolute("arm_7", "arm_6", arm_a7, ex, -odd, odd)),
      // Each module as a capsule from its joint to the next, radii of the PRL modules.
      shapes(
          cylinder("arm_base", at(0, 0, 0.125), 0.12, 0.125),
          capsule("arm_1", {0, 0, 0}, arm_a2.p, 0.08), capsule("arm_2", {0, 0, 0}, arm_a3.p, 0.08),
          capsule("arm_3", {0, 0, 0}, arm_a4.p, 0.07), capsule("arm_4", {0, 0, 0}, arm_a5.p, 0.07),
          capsule("arm_5", {0, 0, 0}, arm_a6.p, 0.06), capsule("arm_6", {0, 0, 0}, arm_a7.p, 0.06),
          capsule("arm_7", {0, 0, 0}, (arm_flange * t(0, 0, -0.03)).p, 0.05)),
      frames(frame("flange", "arm_7", arm_flange)));
}();

}  // namespace topograsp::models

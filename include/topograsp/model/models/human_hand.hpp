// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// A 20-DOF human right hand: GraspIt!'s HumanHand20DOF kinematics (CyberGlove lineage), converted
/// to link frames aligned with the hand frame H and scaled by 0.75 to an average adult hand (wrist
/// to middle fingertip 0.189 m). Sources, the conversion and the collision radii: docs/models.md;
/// the joint torques of a comfortable holding grasp, speeds, armature and segment masses:
/// docs/models.md, "Actuators and masses".
#pragma once

#include <topograsp/core/constants.hpp>
#include <topograsp/model/model.hpp>

namespace topograsp::models {

/// The uniform scale applied to GraspIt!'s hand, whose meshes are 1.149 times a 37 mm thumb
/// phalanx model and whose wrist-to-middle-tip length is 0.252 m.
inline constexpr double human_hand_scale = 0.75;

namespace detail {
constexpr double hs(double x) { return human_hand_scale * x; }
constexpr Pose hat(double x, double y, double z) { return at(hs(x), hs(y), hs(z)); }
// A human joint's actuator: holding torque (N m), the assumed speed and armature.
constexpr LinkSpec muscle(LinkSpec l, double torque) {
  return l.actuator(torque, 3.0, 1e-5);  // rad/s and kg m^2, both assumed (docs/models.md)
}
// A finger segment of length hs(len) along z with mass m (kg): its centre halfway.
constexpr LinkSpec segment(LinkSpec l, double len, double m) {
  return l.inertial(m, {0.0, 0.0, hs(len) / 2.0});
}

}  // namespace detail

/// The human right hand in the frame H: origin at the wrist, +z wrist to fingertips, +x out of the
/// palm, +y from the pinky to the thumb. Configuration (GraspIt! order, rad): index abd, MCP, PIP,
/// DIP; middle; ring; pinky (the same four); thumb CMC1 (radial abduction), CMC2 (negative =
/// palmar abduction), MCP, IP. Positive flexion closes; finger abduction toward the thumb side.
inline constexpr auto human_hand = [] {
  using namespace detail;
  constexpr std::array<double, 3> ex{-1.0, 0.0, 0.0}, ey{0.0, 1.0, 0.0};
  constexpr double flex_lo = -deg(10), flex_hi = deg(90);
  constexpr std::array<double, 3> cmc1{-0.2418, 0.1862, 0.9522};
  constexpr std::array<double, 3> cmc2{0.3618, -0.8933, 0.2665};
  constexpr std::array<double, 3> flex{0.8449, -0.5106, -0.1594};
  return make_model(
      "human_hand",
      links(
          root("palm").inertial(0.2381, {-0.001, -0.002, 0.055}),
          // index
          muscle(revolute("index_abd", "palm", hat(-0.0112, 0.0364, 0.1401), ex, -deg(20), deg(20)),
                 0.294),
          segment(
              muscle(revolute("index_mcp", "index_abd", {}, ey, flex_lo, flex_hi).closes(1), 0.589),
              0.0432, 0.0158),
          segment(muscle(revolute("index_pip", "index_mcp", hat(0, 0, 0.0432), ey, flex_lo, flex_hi)
                             .closes(1),
                         0.330),
                  0.0296, 0.0096),
          segment(muscle(revolute("index_dip", "index_pip", hat(0, 0, 0.0296), ey, flex_lo, flex_hi)
                             .closes(1),
                         0.152),
                  0.0253, 0.0066),
          // middle
          muscle(
              revolute("middle_abd", "palm", hat(-0.0112, 0.0084, 0.1457), ex, -deg(10), deg(10)),
              0.319),
          segment(muscle(revolute("middle_mcp", "middle_abd", {}, ey, flex_lo, flex_hi).closes(1),
                         0.638),
                  0.0462, 0.0185),
          segment(
              muscle(revolute("middle_pip", "middle_mcp", hat(0, 0, 0.0462), ey, flex_lo, flex_hi)
                         .closes(1),
                     0.361),
              0.031, 0.0112),
          segment(
              muscle(revolute("middle_dip", "middle_pip", hat(0, 0, 0.0310), ey, flex_lo, flex_hi)
                         .closes(1),
                     0.175),
              0.0292, 0.0072),
          // ring
          muscle(revolute("ring_abd", "palm", hat(-0.0056, -0.0196, 0.1457), ex, -deg(20), deg(20)),
                 0.207),
          segment(
              muscle(revolute("ring_mcp", "ring_abd", {}, ey, flex_lo, flex_hi).closes(1), 0.413),
              0.0391, 0.0147),
          segment(muscle(revolute("ring_pip", "ring_mcp", hat(0, 0, 0.0391), ey, flex_lo, flex_hi)
                             .closes(1),
                         0.238),
                  0.0283, 0.0093),
          segment(muscle(revolute("ring_dip", "ring_pip", hat(0, 0, 0.0283), ey, flex_lo, flex_hi)
                             .closes(1),
                         0.110),
                  0.0245, 0.0055),
          // pinky
          muscle(revolute("pinky_abd", "palm", hat(0.0084, -0.0420, 0.1345), ex, -deg(30), deg(30)),
                 0.111),
          segment(
              muscle(revolute("pinky_mcp", "pinky_abd", {}, ey, flex_lo, flex_hi).closes(1), 0.222),
              0.0299, 0.0096),
          segment(muscle(revolute("pinky_pip", "pinky_mcp", hat(0, 0, 0.0299), ey, flex_lo, flex_hi)
                             .closes(1),
                         0.133),
                  0.0211, 0.0059),
          segment(muscle(revolute("pinky_dip", "pinky_pip", hat(0, 0, 0.0211), ey, flex_lo, flex_hi)
                             .closes(1),
                         0.070),
                  0.0232, 0.0045),
          // thumb
          muscle(
              revolute("thumb_cmc1", "palm", hat(0.0115, 0.0189, 0.0506), cmc1, -deg(10), deg(70)),
              0.705),
          muscle(revolute("thumb_cmc2", "thumb_cmc1", {}, cmc2, -deg(50), deg(25)).closes(-1),
                 1.411)
              .inertial(0.0330, {hs(0.0209) / 2, hs(0.0212) / 2, hs(0.0428) / 2}),
          muscle(
              revolute("thumb_mcp", "thumb_cmc2", hat(0.0209, 0.0212, 0.0428), flex, 0.0, deg(90))
                  .closes(1),
              0.824)
              .inertial(0.0189, {hs(0.0150) / 2, hs(0.0138) / 2, hs(0.0353) / 2}),
          muscle(revolute("thumb_ip", "thumb_mcp", hat(0.0150, 0.0138, 0.0353), flex, 0.0, deg(100))
                     .closes(1),
                 0.366)
              .inertial(0.0116, {hs(0.0130) / 2, hs(0.0132) / 2, hs(0.0267) / 2})),
      shapes(box("palm", at(-0.001, -0.002, 0.055), {0.019, 0.040, 0.052}),
             capsule("index_mcp", {0, 0, 0}, {0, 0, hs(0.0432)}, 0.010),
             capsule("index_pip", {0, 0, 0}, {0, 0, hs(0.0296)}, 0.009),
             capsule("index_dip", {0, 0, 0}, {0, 0, hs(0.0253)}, 0.008),
             capsule("middle_mcp", {0, 0, 0}, {0, 0, hs(0.0462)}, 0.0105),
             capsule("middle_pip", {0, 0, 0}, {0, 0, hs(0.0310)}, 0.0095),
             capsule("middle_dip", {0, 0, 0}, {0, 0, hs(0.0292)}, 0.008),
             capsule("ring_mcp", {0, 0, 0}, {0, 0, hs(0.0391)}, 0.010),
             capsule("ring_pip", {0, 0, 0}, {0, 0, hs(0.0283)}, 0.009),
             capsule("ring_dip", {0, 0, 0}, {0, 0, hs(0.0245)}, 0.0075),
             capsule("pinky_mcp", {0, 0, 0}, {0, 0, hs(0.0299)}, 0.009),
             capsule("pinky_pip", {0, 0, 0}, {0, 0, hs(0.0211)}, 0.008),
             capsule("pinky_dip", {0, 0, 0}, {0, 0, hs(0.0232)}, 0.007),
             capsule("thumb_cmc2", {0, 0, 0}, {hs(0.0209), hs(0.0212), hs(0.0428)}, 0.013),
             capsule("thumb_mcp", {0, 0, 0}, {hs(0.0150), hs(0.0138), hs(0.0353)}, 0.011),
             capsule("thumb_ip", {0, 0, 0}, {hs(0.0130), hs(0.0132), hs(0.0267)}, 0.0095)),
      frames(frame("index_tip", "index_dip", hat(0, 0, 0.0253)),
             frame("middle_tip", "middle_dip", hat(0, 0, 0.0292)),
             frame("ring_tip", "ring_dip", hat(0, 0, 0.0245)),
             frame("pinky_tip", "pinky_dip", hat(0, 0, 0.0232)),
             frame("thumb_tip", "thumb_ip", hat(0.0130, 0.0132, 0.0267)),
             frame("palm_centre", "palm", hat(0.0, 0.0, 0.0900)),
             frame("grasp_centre", "palm", hat(0.0400, 0.0, 0.1250))),
      hand("palm_centre", finger("index", {"index_mcp", "index_pip", "index_dip", "index_tip"}),
           finger("middle", {"middle_mcp", "middle_pip", "middle_dip", "middle_tip"}),
           finger("ring", {"ring_mcp", "ring_pip", "ring_dip", "ring_tip"}),
           finger("pinky", {"pinky_mcp", "pinky_pip", "pinky_dip", "pinky_tip"}),
           thumb("thumb", {"thumb_cmc1", "thumb_mcp", "thumb_ip", "thumb_tip"})));
}();

}  // namespace topograsp::models

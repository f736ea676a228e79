// SPDX-License-Identifier: BSD-3-Clause
// The worked example of docs/models.md: describe a new hand, then use its kinematics.
#include <cstdio>

#include <topograsp/topograsp.hpp>

using namespace topograsp;

inline constexpr auto my_gripper = make_model(
    "my_gripper",
    links(root("palm"),
          // name, parent, origin in the parent frame, axis, lower, upper (rad)
          revolute("finger_1", "palm", at(0.03, 0, 0.05), {0, 1, 0}, -0.2, 1.6).closes(-1),
          revolute("finger_2", "finger_1", at(0, 0, 0.05), {0, 1, 0}, 0.0, 1.6).closes(-1),
          revolute("thumb_1", "palm", at(-0.03, 0, 0.05).rpy(0, 0, pi), {0, 1, 0}, -0.2, 1.6)
              .mimics("finger_1", 1.0, 0.0)),  // value = 1.0 * finger_1 + 0.0
    shapes(box("palm", at(0, 0, 0.025), {0.045, 0.02, 0.025}),
           capsule("finger_1", {0, 0, 0}, {0, 0, 0.05}, 0.01),
           capsule("finger_2", {0, 0, 0}, {0, 0, 0.04}, 0.009),
           capsule("thumb_1", {0, 0, 0}, {0, 0, 0.06}, 0.01)),
    frames(frame("finger_tip", "finger_2", at(0, 0, 0.045)),
           frame("thumb_tip", "thumb_1", at(0, 0, 0.065)),
           frame("palm_centre", "palm", at(0, 0, 0.05))),
    hand("palm_centre",  // the centre of the base of the hand
         finger("finger", {"finger_1", "finger_2", "finger_tip"}),  // base to tip
         thumb("thumb", {"thumb_1", "thumb_tip"})));

static_assert(my_gripper.nq == 2);  // finger_1, finger_2; the thumb follows finger_1

int main() {
  KinematicsData<my_gripper> data;
  const Vec<my_gripper.nq> q(0.3, 0.5);
  forward_kinematics(data, q);
  const Vec3 tip = data.frame_p[my_gripper.frame("finger_tip")];
  const Mat<6, my_gripper.nq> J = frame_jacobian(data, my_gripper.frame("finger_tip"));
  std::printf("finger tip at (%.4f, %.4f, %.4f) m\n", tip.x(), tip.y(), tip.z());
  std::printf("d tip / d finger_1 = (%.4f, %.4f, %.4f) m/rad\n", J(0, 0), J(1, 0), J(2, 0));
  // A hand on an arm's flange, and on a free 6-DOF base, are compile-time compositions too.
  static constexpr auto arm_hand = attach(models::schunk_arm, "flange", my_gripper);
  static constexpr auto free_gripper = on_free_base(my_gripper);
  static_assert(arm_hand.nq == 9 && free_gripper.nq == 8);
  return 0;
}

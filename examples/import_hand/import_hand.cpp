// SPDX-License-Identifier: BSD-3-Clause
// Bring your own hand (docs/models.md): a gripper from its MJCF file (gripper.xml) and its hand
// description (gripper.json: which chains are the fingers and the thumb, the palm centre, which
// way each joint closes, the motors' speed, which the MJCF file cannot say), imported at build time
// by the CMake function topograsp_import_hand() into gripper_file.hpp as the model gripper::model,
// checked while it compiles like a shipped model; then what the library does with any hand: its
// kinematics, its hand curves' windings around a ball, the grasp closed by its motors in the
// built-in simulation and judged by the stability suite. Exit status 0 if the gripper holds the
// ball.
#include <cstdio>
#include <string>

#include <topograsp/evaluation/close_hand.hpp>
#include <topograsp/evaluation/stability_suite.hpp>
#include <topograsp/grasp/check_hand.hpp>
#include <topograsp/task/winding_descriptor.hpp>

#include "gripper_file.hpp"  // gripper::model, from gripper.xml and gripper.json

using namespace topograsp;

constexpr auto& my_gripper = gripper::model;

int main() {
  static_assert(my_gripper.nq == 6);
  // First the self-check every new hand should pass before any transfer: the palm centre frame's
  // axes, the closing directions, motors and masses, and the hand closed on a ball and a cylinder
  // at its palm (docs/models.md, "Check a hand before transferring").
  const HandCheck check = check_hand<my_gripper>();
  for (const std::string& p : check.problems) std::printf("problem: %s\n", p.c_str());
  for (const HandTrial& t : check.trials)
    std::printf("check_hand: %-8s %s%s%s\n", t.object.c_str(), t.stable ? "held" : "not held",
                t.stable ? "" : ": ", t.reason.c_str());
  if (!check.ok()) return 1;
  // Kinematics: the tips with the hand open.
  const Vec<my_gripper.nq> open = Vec<my_gripper.nq>::Zero();
  KinematicsData<my_gripper> d;
  forward_kinematics(d, open);
  for (const char* tip : {"finger_1_tip", "finger_2_tip", "thumb_tip"}) {
    const Vec3 p = d.frame_p[static_cast<std::size_t>(my_gripper.find_frame(tip))];
    std::printf("%-13s at (%7.4f, %7.4f, %7.4f) m, open\n", tip, p.x(), p.y(), p.z());
  }
  // A 100 g ball of 3 cm radius resting on the palm between the fingers and the thumb.
  ObjectSpec ball;
  ball.shapes = {sphere("", {0, 0, 0}, 0.03)};
  ball.pose = at(0, 0, 0.045);
  ball.mass = 0.1;
  HandScene<my_gripper> scene(Eigen::Isometry3d::Identity(), open, ball);
  const auto closed = close_hand(scene);
  std::printf("closed: %s, joints (rad):", to_string(closed.status).data());
  for (int i = 0; i < my_gripper.nq; ++i) std::printf(" %.3f", closed.q_closed[i]);
  std::printf("\n");
  // The topological descriptor of the grasp: the windings of the two hand curves (thumb tip
  // through the palm to each finger's tip) around the ball's centre.
  forward_kinematics(d, closed.q_closed);
  const WindingDescriptor y = winding_descriptor(d, scene.object_pose().translation());
  std::printf("windings around the ball: %.3f (curve %d), %.3f (curve %d)\n", y.values[0],
              y.curves[0], y.values[1], y.curves[1]);
  // The stability suite: a shake and gravity along the six directions of the hand frame.
  const StabilityResult judged = stability_suite(scene);
  // (It stops at the first failed test: the later ones say "not run".)
  for (const StabilityRecord& t : judged.tests)
    if (t.steps == 0)
      std::printf("  %-11s %s\n", t.name.data(), t.reason.data());
    else
      std::printf("  %-11s %s (moved %.1f mm, turned %.1f deg)\n", t.name.data(),
                  t.passed ? "held" : "lost", 1e3 * t.translation, t.rotation * 180.0 / pi);
  std::printf("the gripper %s the ball\n", judged.stable ? "holds" : "does not hold");
  return judged.stable ? 0 : 1;
}

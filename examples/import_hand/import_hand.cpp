// SPDX-License-Identifier: BSD-3-Clause
// Bring your own hand (docs/models.md): a gripper from its MJCF file (gripper.xml, imported at
// build time by the CMake function topograsp_import_hand() into gripper_file.hpp), the few lines
// the file cannot say (which chains are the fingers and the thumb, which way each joint closes, the
// motors' speed), then what the library does with any hand: its kinematics, its hand curves'
// windings around a ball, the grasp closed by its motors in the built-in simulation and judged by
// the stability suite. Exit status 0 if the gripper holds the ball.
#include <cstdio>

#include <topograsp/evaluation/close_hand.hpp>
#include <topograsp/evaluation/stability_suite.hpp>
#include <topograsp/task/winding_descriptor.hpp>

#include "gripper_file.hpp"  // gripper::links, gripper::shapes, gripper::frames (the file's)

using namespace topograsp;

// What the file cannot say: every finger joint closes by increasing; the motors' speed limit (the
// file gives their torque, 1 N m, but no speed). Checked while it compiles, like a shipped model.
constexpr auto gripper_links = [] {
  auto links = with_closing(gripper::links, {{"finger_1_proximal", 1},
                                             {"finger_1_distal", 1},
                                             {"finger_2_proximal", 1},
                                             {"finger_2_distal", 1},
                                             {"thumb_proximal", 1},
                                             {"thumb_distal", 1}});
  for (LinkSpec& l : links)
    if (l.type != JointType::fixed) l.velocity = 3.0;  // rad/s
  return links;
}();

constexpr auto my_gripper =
    make_model("my_gripper", gripper_links, gripper::shapes, gripper::frames,
               hand("palm_centre",  // the file's sites name the palm centre and the tips
                    finger("finger_1", {"finger_1_proximal", "finger_1_distal", "finger_1_tip"}),
                    finger("finger_2", {"finger_2_proximal", "finger_2_distal", "finger_2_tip"}),
                    thumb("thumb", {"thumb_proximal", "thumb_distal", "thumb_tip"})));

int main() {
  static_assert(my_gripper.nq == 6);
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

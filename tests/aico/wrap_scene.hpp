// SPDX-License-Identifier: BSD-3-Clause
// The wrap scene of examples/wrap.cpp for the tests: the SDH on the 7-DOF arm, a cylinder in
// front of it, collision, joint limits and a weak posture term (the library's tasks) as the base.
#pragma once

#include <array>

#include <topograsp/geometry/composite.hpp>
#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task/collision_task.hpp>
#include <topograsp/task/joint_limit_task.hpp>
#include <topograsp/task/posture_task.hpp>
#include <topograsp/task/task_set.hpp>
#include <topograsp/task/winding_task.hpp>

namespace topograsp::test {

inline constexpr const auto& wrap_robot = models::schunk_arm_sdh;
constexpr int wrap_nq = wrap_robot.nq;

/// The library's tasks the wrap scene (and examples/wrap.cpp) plans with besides the windings.
using WrapBaseSet =
    TaskSet<CollisionTask<wrap_robot>, JointLimitTask<wrap_robot>, PostureTask<wrap_robot>>;

/// Collision with the object (target 0, precision 1e3), the joint limits (target 0, 1e4) and a
/// weak pull toward the posture (1e-2), constant over the plan; AICO reports their costs as three
/// tasks. The collision task is also kept by name, to measure distances.
struct WrapBase : WrapBaseSet {
  static constexpr std::array<int, 3> task_dims{1, wrap_nq, wrap_nq};
  CollisionTask<wrap_robot> collision;

  WrapBase(const CollisionTask<wrap_robot>& collision_task, const Vec<wrap_nq>& posture)
      : WrapBaseSet(
            scheduled(collision_task, constant_target(Vec<1>(0.0)), constant_precision(1e3)),
            scheduled(JointLimitTask<wrap_robot>(),
                      constant_target(Vec<wrap_nq>(Vec<wrap_nq>::Zero())), constant_precision(1e4)),
            scheduled(PostureTask<wrap_robot>(), constant_target(posture),
                      constant_precision(1e-2))),
        collision(collision_task) {}
};

/// The scene: a cylinder (radius 2 cm, 20 cm long) 10 cm in front of the palm at a reachable arm
/// pose, its axis across the fingers' flexion plane; the winding centre is the cylinder's centre.
struct WrapScene {
  static constexpr double k_offset = 0.10, k_radius = 0.02;
  Vec3 centre = Vec3::Zero();
  Composite object;
  Vec<wrap_nq> home = Vec<wrap_nq>::Zero();
  static Vec<wrap_nq> make_home() {
    Vec<wrap_nq> h = Vec<wrap_nq>::Zero();
    h[1] = 0.2;
    h[3] = 0.3;
    h[5] = 0.2;
    return h;
  }
  Vec2 goal = Vec2(0.8, 0.8);

  WrapScene() {
    home = make_home();
    KinematicsData<wrap_robot> d;
    Vec<wrap_nq> q = Vec<wrap_nq>::Zero();
    q[1] = 0.5;
    q[3] = 0.8;
    q[5] = 0.5;
    forward_kinematics(d, q);
    const auto palm = static_cast<std::size_t>(wrap_robot.frame("palm_centre"));
    const Mat3& R = d.frame_R[palm];
    centre = d.frame_p[palm] + k_offset * R.col(2);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = centre;
    // Cylinder axis (local z) along the palm's y axis, across the flexion plane of the fingers.
    pose.linear() << R.col(0), R.col(2), R.col(1);
    pose.linear().col(1) = pose.linear().col(2).cross(pose.linear().col(0));
    object = Composite({Primitive::cylinder(pose, k_radius, 0.1)});
  }

  [[nodiscard]] WrapBase base() const {
    return WrapBase{CollisionTask<wrap_robot>(object, 0.02), home};
  }
  [[nodiscard]] WindingTask<wrap_robot, 2> windings() const {
    return WindingTask<wrap_robot, 2>({0, 1}, centre);
  }
};

}  // namespace topograsp::test

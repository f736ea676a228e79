// SPDX-License-Identifier: BSD-3-Clause
// The wrap scene of examples/wrap.cpp for the tests: the SDH on the 7-DOF arm, a cylinder in
// front of it, collision, joint limits and a weak posture term as the base tasks.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <topograsp/geometry/composite.hpp>
#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task/collision_task.hpp>
#include <topograsp/task/winding_task.hpp>

namespace topograsp::test {

inline constexpr const auto& wrap_robot = models::schunk_arm_sdh;
constexpr int wrap_nq = wrap_robot.nq;

/// Collision with the object (target 0), a hinge on the joint limits and a weak posture term.
struct WrapBase {
  using Kinematics = KinematicsData<wrap_robot>;
  static constexpr int dim = 1 + 2 * wrap_nq;
  static constexpr std::array<int, 3> task_dims{1, wrap_nq, wrap_nq};
  CollisionTask<wrap_robot> collision;
  Vec<wrap_nq> posture = Vec<wrap_nq>::Zero();
  double rho_collision = 1e3, rho_limits = 1e4, rho_posture = 1e-2;

  void residual(const Kinematics& d, int, int, Vec<dim>& e, Mat<dim, wrap_nq>& J) const noexcept {
    Vec<1> phi;
    Mat<1, wrap_nq> Jc;
    collision.evaluate(d, phi, Jc);
    const double sc = std::sqrt(rho_collision), sl = std::sqrt(rho_limits);
    e[0] = sc * phi[0];
    J.row(0) = sc * Jc;
    static const Vec<wrap_nq> lo = lower_limits<wrap_robot>(), hi = upper_limits<wrap_robot>();
    J.block<wrap_nq, wrap_nq>(1, 0).setZero();
    for (int i = 0; i < wrap_nq; ++i) {
      const double over = std::max(0.0, d.q[i] - hi[i]) + std::min(0.0, d.q[i] - lo[i]);
      e[1 + i] = sl * over;
      J(1 + i, i) = over != 0.0 ? sl : 0.0;
    }
    const double sp = std::sqrt(rho_posture);
    e.tail<wrap_nq>() = sp * (d.q - posture);
    J.bottomRows<wrap_nq>() = sp * Mat<wrap_nq, wrap_nq>::Identity();
  }
};

/// The scene: a cylinder (radius 3 cm, 20 cm long) 7 cm in front of the palm at a reachable arm
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

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The paper's setting: the object fixed in front of the Schunk arm, and whether the arm reaches a
/// hand pose without striking the object (arm_reach: inverse kinematics of the arm's 7 joints,
/// then the arm's clearance from the object). docs/transfer.md, "The arm setting".
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <topograsp/core/random.hpp>
#include <topograsp/grasp/object.hpp>
#include <topograsp/grasp/placement.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/kinematics/jacobian.hpp>
#include <topograsp/kinematics/least_squares.hpp>
#include <topograsp/model/models/schunk_arm.hpp>

namespace topograsp {

/// Where the arm setting puts an object (world frame, the arm's: its base at the origin, z up,
/// the shoulder 1.19 m high): upright as modelled, its centre of mass at this point, 45 cm in
/// front of the arm's base axis and 95 cm high. Chosen before any transfer was run, for the arm
/// alone, on a grid of points (x 0.3 to 0.7 m, z 0.3 to 1.15 m): the arm puts the SDH's grasp
/// centre at this point in 198 of 200 random orientations, at 75 cm high in about 40 %
/// (docs/transfer.md, "The arm setting"). The same for every object and every method.
inline const Vec3 arm_setting_object_point{0.45, 0.0, 0.95};

/// The pose (world) at which the arm setting puts \p object: its frame unturned, its centre of
/// mass at arm_setting_object_point.
[[nodiscard]] inline Eigen::Isometry3d arm_setting_object_pose(const GraspObject& object) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = arm_setting_object_point - object.centre_of_mass();
  return T;
}

/// Tolerances of arm_reach().
struct ArmReachOptions {
  double position_tolerance = 1e-3;  ///< m: the flange's distance from the asked pose
  double rotation_tolerance = 1e-2;  ///< rad: its angle from the asked orientation
  /// m: the arm's links (not the hand's) must stay this far from the object (0: not inside it).
  double clearance = 0.0;
  int iterations = 200;  ///< Levenberg-Marquardt trial steps per start
  /// Starts after the ready pose: configurations drawn uniformly within the arm's limits from a
  /// fixed seed (the same for every call), tried in turn until one reaches.
  int restarts = 31;
};

/// Whether the arm reached a hand pose (arm_reach()).
struct ArmReach {
  bool reached = false;           ///< within tolerance and clear of the object
  Vec<7> q_arm = Vec<7>::Zero();  ///< the arm's joints (the best found, reached or not)
  double position_error = std::numeric_limits<double>::infinity();  ///< m
  double rotation_error = std::numeric_limits<double>::infinity();  ///< rad
  /// m: the smallest signed distance of the arm's links from the object at q_arm (negative:
  /// inside).
  double clearance = std::numeric_limits<double>::infinity();
  std::string reason;  ///< why not reached (empty when reached)
};

/// Whether the Schunk arm puts its flange, where every hand's root link is attached (OnArm), at
/// \p hand_root (object frame) when the object is at \p world_object (world), without its links
/// entering the object. Inverse kinematics of the arm's 7 joints within their limits by bounded
/// Levenberg-Marquardt (bounded_least_squares) on the flange's position (m) and rotation (rad,
/// the rotation vector of the error), from the arm's pose \p ready and, if that fails, from
/// options.restarts configurations drawn within the arm's limits from a fixed seed; the first
/// solution within tolerance whose arm links clear the object is taken (on random poses the arm
/// can reach, 99.5 % are found: tests/grasp/test_arm_reach.cpp). The hand's links are not
/// checked (the transfer checks the hand), so one function serves every hand: the arm's model
/// alone, compiled once where it is called. reason says why not reached: "the arm cannot reach
/// the hand pose (... mm, ... deg off)" or "the arm strikes the object (... mm inside)". A
/// non-finite pose is not reached.
template <class = void>
[[nodiscard]] ArmReach arm_reach(const GraspObject& object, const Eigen::Isometry3d& world_object,
                                 const Eigen::Isometry3d& hand_root, const Vec<7>& ready,
                                 const ArmReachOptions& options = {}) {
  constexpr auto& A = models::schunk_arm;
  constexpr int flange = A.find_frame("flange");
  ArmReach out;
  const Eigen::Isometry3d target = world_object * hand_root;
  if (!target.matrix().allFinite() || !ready.allFinite()) {
    out.reason = "the arm cannot reach the hand pose (not finite)";
    return out;
  }
  const Vec<7> lo = lower_limits<models::schunk_arm>(), hi = upper_limits<models::schunk_arm>();
  KinematicsData<models::schunk_arm> d;
  const auto residual = [&](const Vec<7>& x, Vec<6>& e) {
    forward_kinematics(d, x);
    const Eigen::Isometry3d T = frame_pose(d, flange);
    e.template head<3>() = T.translation() - target.translation();
    const Eigen::AngleAxisd r(T.linear() * target.linear().transpose());
    e.template tail<3>() = r.angle() * r.axis();
    return e.squaredNorm();
  };
  const auto jacobian = [&](Mat<6, 7>& J) {
    J.template topRows<3>() = frame_position_jacobian(d, flange);
    J.template bottomRows<3>() = frame_rotation_jacobian(d, flange);
  };
  const Composite shape = object.composite(world_object);
  BoundedLeastSquaresOptions lm;
  lm.iterations = options.iterations;
  lm.settled = 1e-16;
  detail::SplitMix64 draws{0x5eed'a7a1'0000'0001ull};
  double best_error = std::numeric_limits<double>::infinity();
  for (int start = 0; start <= options.restarts; ++start) {
    Vec<7> x = ready;
    if (start > 0)
      for (int i = 0; i < 7; ++i) x[i] = lo[i] + draws.uniform() * (hi[i] - lo[i]);
    x = x.cwiseMax(lo).cwiseMin(hi);
    Vec<6> e;
    Mat<6, 7> J;
    const double cost = residual(x, e);
    (void)bounded_least_squares<7, 6>(x, e, cost, lo, hi, residual, jacobian, J, lm);
    const double pos = e.template head<3>().norm(), rot = e.template tail<3>().norm();
    const bool within = pos <= options.position_tolerance && rot <= options.rotation_tolerance;
    const double clearance = within ? hand_object_distance(d, shape) : out.clearance;
    const double error = pos + 0.1 * rot;  // 1 rad weighs as 10 cm, for the report only
    if ((within && clearance >= options.clearance) || error < best_error) {
      best_error = error;
      out.q_arm = x;
      out.position_error = pos;
      out.rotation_error = rot;
      out.clearance = clearance;
    }
    if (within && clearance >= options.clearance) {
      out.reached = true;
      return out;
    }
  }
  char buf[96];
  if (out.position_error <= options.position_tolerance &&
      out.rotation_error <= options.rotation_tolerance)
    std::snprintf(buf, sizeof buf, "the arm strikes the object (%.0f mm inside)",
                  -1000.0 * out.clearance);
  else
    std::snprintf(buf, sizeof buf, "the arm cannot reach the hand pose (%.0f mm, %.0f deg off)",
                  1000.0 * out.position_error, out.rotation_error * 180.0 / pi);
  out.reason = buf;
  return out;
}

#ifdef TOPOGRASP_EXTERN_HAND_INDEPENDENT
// Compiled once, in the one translation unit that includes grasp/hand_independent.hpp
// (docs/benchmarks.md, "Compiling the transfer once per program").
extern template ArmReach arm_reach<void>(const GraspObject&, const Eigen::Isometry3d&,
                                         const Eigen::Isometry3d&, const Vec<7>&,
                                         const ArmReachOptions&);
#endif

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Placing a hand on a free base: the base configuration that puts a frame at a pose, the
/// distance between a hand and an object, and moving a hand along a direction until it touches.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <topograsp/geometry/composite.hpp>
#include <topograsp/geometry/model_shapes.hpp>
#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/kinematics/forward.hpp>

namespace topograsp {

/// The angles (rz, ry, rx) with R = Rz(rz) Ry(ry) Rx(rx), the order of a free base's joints.
/// At the singularity (ry = +-pi/2) rx is 0.
[[nodiscard]] inline Vec3 zyx_angles(const Mat3& R) noexcept {
  const double ry = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  if (std::abs(R(2, 0)) > 1.0 - 1e-12) return {std::atan2(-R(0, 1), R(1, 1)), ry, 0.0};
  return {std::atan2(R(1, 0), R(0, 0)), ry, std::atan2(R(2, 1), R(2, 2))};
}

/// The configuration of the free-base model \p M (built by on_free_base(), so its first six
/// entries are x, y, z, rz, ry, rx) that puts its frame \p frame at \p T_world_frame, with the
/// hand's own joints at \p q_hand (dim M.nq - 6).
template <const auto& M, EigenDense D>
[[nodiscard]] Vec<M.nq> place_frame(const Eigen::Isometry3d& T_world_frame, int frame,
                                    const D& q_hand) {
  static_assert(M.nq >= 6, "M must be a model on a free base");
  Vec<M.nq> q = Vec<M.nq>::Zero();
  q.template tail<M.nq - 6>() = q_hand;
  KinematicsData<M> d;
  forward_kinematics(d, q);
  const Eigen::Isometry3d base = T_world_frame * frame_pose(d, frame).inverse();
  q.template head<3>() = base.translation();
  q.template segment<3>(3) = zyx_angles(base.linear());
  return q;
}

/// The smallest signed distance (m) between any shape of the model and any part of \p object;
/// +infinity if either has no shapes. Requires forward_kinematics(d, q) first.
template <const auto& M>
[[nodiscard]] double hand_object_distance(const KinematicsData<M>& d, const Composite& object) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < M.n_shapes; ++i) {
    const Primitive s = world_shape(d, i);
    for (const Primitive& part : object.parts())
      best = std::min(best, signed_distance(s, part).distance);
  }
  return best;
}

/// Moves the free-base model \p M from configuration \p q along the world direction \p direction
/// (translating its base) until its shapes are \p gap from \p object, by conservative advancement:
/// each step moves by the current distance, which cannot overshoot. Returns the moved
/// configuration, or nothing if the hand travels \p max_travel without coming within gap (it
/// misses), or starts closer than gap.
template <const auto& M>
[[nodiscard]] std::optional<Vec<M.nq>> approach_until_contact(Vec<M.nq> q, const Vec3& direction,
                                                              const Composite& object,
                                                              double gap = 0.001,
                                                              double max_travel = 0.5) {
  const Vec3 u = direction.normalized();
  KinematicsData<M> d;
  double travelled = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    forward_kinematics(d, q);
    const double dist = hand_object_distance(d, object);
    if (!(dist >= gap)) return iteration == 0 ? std::nullopt : std::optional<Vec<M.nq>>(q);
    if (dist - gap < 1e-5) return q;
    const double step = dist - gap;
    if (travelled + step > max_travel) return std::nullopt;
    q.template head<3>() += step * u;
    travelled += step;
  }
  return q;
}

}  // namespace topograsp

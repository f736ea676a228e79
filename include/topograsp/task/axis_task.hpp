// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// AxisTask: the world direction of an axis fixed to a named frame, for aligning it with a
/// direction (the approach direction of a grasp).
#pragma once

#include <string_view>

#include <topograsp/kinematics/jacobian.hpp>
#include <topograsp/task/detail/frame_lookup.hpp>

namespace topograsp {

/// phi(q) = R_f(q) a (dim 3): the unit axis a of frame f of \p M in the world frame. With the
/// target a unit direction v, the cost rho |R_f a - v|^2 = 2 rho (1 - v . R_f a) is zero exactly
/// when the axis points along v (v = -R_f a is the only other stationary point, a maximum).
/// Jacobian: d(R a)/d q_j = w_j x (R a), so J = -[R a]_x J_w with J_w the frame's rotation
/// Jacobian.
template <const auto& M>
class AxisTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = 3;
  static constexpr int nq = Kinematics::nq;

  /// The axis \p axis (in the frame; normalised here) of frame \p frame (by name).
  /// \throws topograsp::invalid_argument naming "frame" or "axis" (zero or not finite).
  AxisTask(std::string_view frame, const Vec3& axis)
      : AxisTask(detail::require_frame<M>(frame), axis) {}
  /// The same by frame index.
  AxisTask(int frame, const Vec3& axis) : frame_(frame) {
    detail::require_frame_index<M>(frame);
    require_finite(axis, "axis");
    require_positive(axis.norm(), "axis");
    axis_ = axis.normalized();
  }

  [[nodiscard]] int frame() const noexcept { return frame_; }
  [[nodiscard]] const Vec3& axis() const noexcept { return axis_; }

  /// phi(q) (unit vector). Requires forward_kinematics(d, q) first.
  [[nodiscard]] Vec3 value(const Kinematics& d) const noexcept {
    return d.frame_R[static_cast<std::size_t>(frame_)] * axis_;
  }
  /// phi(q) and its Jacobian (3 x nq). Requires forward_kinematics(d, q) first.
  void evaluate(const Kinematics& d, Vec3& phi, Mat<3, nq>& J) const noexcept {
    phi = value(d);
    J.noalias() = -skew(phi) * frame_rotation_jacobian(d, frame_);
  }

 private:
  int frame_ = 0;
  Vec3 axis_ = Vec3::UnitZ();
};

}  // namespace topograsp

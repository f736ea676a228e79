// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// OrientationTask: the full world orientation of a named frame.
#pragma once

#include <string_view>

#include <topograsp/kinematics/jacobian.hpp>
#include <topograsp/task/detail/frame_lookup.hpp>

namespace topograsp {

/// The target of an OrientationTask for the rotation \p R: its columns stacked (dim 9).
[[nodiscard]] inline Vec<9> orientation_target(const Mat3& R) noexcept {
  return Eigen::Map<const Vec<9>>(R.data());
}

/// phi(q) = vec(R_f(q)) (dim 9): the world rotation of frame f of \p M, columns stacked. With the
/// target vec(R*), the cost rho |R_f - R*|_F^2 = 2 rho (3 - tr(R*' R_f)) = 4 rho (1 - cos theta),
/// theta the angle between the two orientations. Jacobian: column k of R_f moves as w x r_k, so
/// rows 3k..3k+2 of J are -[r_k]_x J_w.
template <const auto& M>
class OrientationTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = 9;
  static constexpr int nq = Kinematics::nq;

  /// The orientation of frame \p frame (by name).
  /// \throws topograsp::invalid_argument naming "frame".
  explicit OrientationTask(std::string_view frame)
      : OrientationTask(detail::require_frame<M>(frame)) {}
  /// The same by frame index.
  explicit OrientationTask(int frame) : frame_(frame) { detail::require_frame_index<M>(frame); }

  [[nodiscard]] int frame() const noexcept { return frame_; }

  /// phi(q). Requires forward_kinematics(d, q) first.
  [[nodiscard]] Vec<9> value(const Kinematics& d) const noexcept {
    return orientation_target(d.frame_R[static_cast<std::size_t>(frame_)]);
  }
  /// phi(q) and its Jacobian (9 x nq). Requires forward_kinematics(d, q) first.
  void evaluate(const Kinematics& d, Vec<9>& phi, Mat<9, nq>& J) const noexcept {
    phi = value(d);
    const Mat<3, nq> Jw = frame_rotation_jacobian(d, frame_);
    const Mat3& R = d.frame_R[static_cast<std::size_t>(frame_)];
    for (int k = 0; k < 3; ++k) J.template middleRows<3>(3 * k).noalias() = -skew(R.col(k)) * Jw;
  }

 private:
  int frame_ = 0;
};

}  // namespace topograsp

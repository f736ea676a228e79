// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// LineTask: how far a point fixed to a named frame lies off a world line, for keeping a hand on
/// an approach line while leaving it free to move along it.
#pragma once

#include <string_view>

#include <topograsp/task/position_task.hpp>

namespace topograsp {

/// phi(q) = B (x(q) - c) (dim 2): the offset of the point x = p_f + R_f o (the point at offset o in
/// frame f of \p M) from the world line through c along the unit direction a, in the orthonormal
/// basis B (2 x 3, rows u and a x u, u orthogonal to a) of the plane across the line. |phi| is the
/// distance of x from the line; the usual target is 0, which puts x on the line and says nothing
/// about where along it. Jacobian: B J_p(x).
template <const auto& M>
class LineTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = 2;
  static constexpr int nq = Kinematics::nq;

  /// The point at \p offset (m) in frame \p frame (by name) of \p M, measured from the line
  /// through \p point (m, world) along \p direction (normalised here).
  /// \throws topograsp::invalid_argument naming "frame" (unknown), "point", "direction" (zero or
  /// not finite) or "offset" (not finite).
  LineTask(std::string_view frame, const Vec3& point, const Vec3& direction,
           const Vec3& offset = Vec3::Zero())
      : LineTask(detail::require_frame<M>(frame), point, direction, offset) {}
  /// The same by frame index.
  LineTask(int frame, const Vec3& point, const Vec3& direction, const Vec3& offset = Vec3::Zero())
      : position_(frame, offset) {
    require_finite(point, "point");
    require_finite(direction, "direction");
    require_positive(direction.norm(), "direction");
    point_ = point;
    const Vec3 a = direction.normalized();
    const Vec3 u = a.unitOrthogonal();
    basis_.row(0) = u.transpose();
    basis_.row(1) = a.cross(u).transpose();
  }

  [[nodiscard]] int frame() const noexcept { return position_.frame(); }
  /// The rows u and a x u spanning the plane across the line.
  [[nodiscard]] const Mat<2, 3>& basis() const noexcept { return basis_; }

  /// phi(q) (m). Requires forward_kinematics(d, q) first.
  [[nodiscard]] Vec2 value(const Kinematics& d) const noexcept {
    return basis_ * (position_.value(d) - point_);
  }
  /// phi(q) and its Jacobian (2 x nq). Requires forward_kinematics(d, q) first.
  void evaluate(const Kinematics& d, Vec2& phi, Mat<2, nq>& J) const noexcept {
    Vec3 x;
    Mat<3, nq> Jp;
    position_.evaluate(d, x, Jp);
    phi = basis_ * (x - point_);
    J.noalias() = basis_ * Jp;
  }

 private:
  PositionTask<M> position_;  // the point x and its Jacobian
  Vec3 point_ = Vec3::Zero();
  Mat<2, 3> basis_ = Mat<2, 3>::Zero();
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// PositionTask: the world position of a point fixed to a named frame.
#pragma once

#include <string_view>

#include <topograsp/kinematics/jacobian.hpp>
#include <topograsp/task/detail/frame_lookup.hpp>

namespace topograsp {

/// phi(q) = p_f(q) + R_f(q) o (dim 3): the world position (m) of the point at offset o in frame f
/// of \p M. Jacobian: the point Jacobian of that point on the frame's link,
/// J = sum over joints j above the link of a_j x (x - p_j) (revolute) or a_j (prismatic).
template <const auto& M>
class PositionTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = 3;
  static constexpr int nq = Kinematics::nq;

  /// The position of frame \p frame (by name) of \p M, or of the point at \p offset in it (m).
  /// \throws topograsp::invalid_argument naming "frame" (unknown) or "offset" (not finite).
  explicit PositionTask(std::string_view frame, const Vec3& offset = Vec3::Zero())
      : PositionTask(detail::require_frame<M>(frame), offset) {}
  /// The same by frame index.
  explicit PositionTask(int frame, const Vec3& offset = Vec3::Zero()) : frame_(frame) {
    detail::require_frame_index<M>(frame);
    require_finite(offset, "offset");
    offset_ = offset;
  }

  [[nodiscard]] int frame() const noexcept { return frame_; }

  /// phi(q) (m). Requires forward_kinematics(d, q) first.
  [[nodiscard]] Vec3 value(const Kinematics& d) const noexcept {
    const auto f = static_cast<std::size_t>(frame_);
    return d.frame_p[f] + d.frame_R[f] * offset_;
  }
  /// phi(q) and its Jacobian (3 x nq). Requires forward_kinematics(d, q) first.
  void evaluate(const Kinematics& d, Vec3& phi, Mat<3, nq>& J) const noexcept {
    phi = value(d);
    J.setZero();
    add_point_jacobian(d, M.frames[static_cast<std::size_t>(frame_)].link, phi, J);
  }

 private:
  int frame_ = 0;
  Vec3 offset_ = Vec3::Zero();
};

}  // namespace topograsp

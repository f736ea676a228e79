// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Frame and point Jacobians in the world frame, with mimic joints folded in by the chain rule.
/// All of them read a KinematicsData filled by forward_kinematics() at the same configuration, and
/// walk the link's support (Model::support(): the joints that move it, computed at compile time).
#pragma once

#include <topograsp/kinematics/forward.hpp>

namespace topograsp {

/// Adds the Jacobian of the world point \p p_world, rigidly attached to link \p link, to \p J_pos
/// (3 x nq): d p / d q. Mimic joints add multiplier times their column to their source's column.
/// Requires forward_kinematics(d, q) first.
template <const auto& M, class Derived>
void add_point_jacobian(const KinematicsData<M>& d, int link, const Vec3& p_world,
                        Eigen::MatrixBase<Derived> const& J_pos_) noexcept {
  auto& J_pos = const_cast<Eigen::MatrixBase<Derived>&>(J_pos_);
  for (const SupportJoint& j : M.support(link)) {
    const auto u = static_cast<std::size_t>(j.link);
    if (j.type == JointType::revolute)
      J_pos.col(j.q) += j.multiplier * d.axis[u].cross(p_world - d.p[u]);
    else
      J_pos.col(j.q) += j.multiplier * d.axis[u];
  }
}

/// The position Jacobian (3 x nq) of the world point \p p_world attached to link \p link.
template <const auto& M>
[[nodiscard]] Mat<3, M.nq> point_jacobian(const KinematicsData<M>& d, int link,
                                          const Vec3& p_world) noexcept {
  Mat<3, M.nq> J = Mat<3, M.nq>::Zero();
  add_point_jacobian(d, link, p_world, J);
  return J;
}

/// The rotation Jacobian (3 x nq) of link \p link: angular velocity in the world frame per q-dot.
template <const auto& M>
[[nodiscard]] Mat<3, M.nq> link_rotation_jacobian(const KinematicsData<M>& d, int link) noexcept {
  Mat<3, M.nq> J = Mat<3, M.nq>::Zero();
  for (const SupportJoint& j : M.support(link))
    if (j.type == JointType::revolute)
      J.col(j.q) += j.multiplier * d.axis[static_cast<std::size_t>(j.link)];
  return J;
}

/// The position Jacobian (3 x nq) of named frame \p f, in the world frame.
template <const auto& M>
[[nodiscard]] Mat<3, M.nq> frame_position_jacobian(const KinematicsData<M>& d, int f) noexcept {
  const auto u = static_cast<std::size_t>(f);
  return point_jacobian(d, M.frames[u].link, d.frame_p[u]);
}

/// The rotation Jacobian (3 x nq) of named frame \p f, in the world frame.
template <const auto& M>
[[nodiscard]] Mat<3, M.nq> frame_rotation_jacobian(const KinematicsData<M>& d, int f) noexcept {
  return link_rotation_jacobian(d, M.frames[static_cast<std::size_t>(f)].link);
}

/// The full Jacobian (6 x nq) of named frame \p f: rows 0-2 the linear velocity of the frame
/// origin, rows 3-5 the angular velocity, both in the world frame.
template <const auto& M>
[[nodiscard]] Mat<6, M.nq> frame_jacobian(const KinematicsData<M>& d, int f) noexcept {
  const auto u = static_cast<std::size_t>(f);
  const int link = M.frames[u].link;
  Mat<6, M.nq> J = Mat<6, M.nq>::Zero();
  for (const SupportJoint& j : M.support(link)) {
    const auto v = static_cast<std::size_t>(j.link);
    if (j.type == JointType::revolute) {
      J.template block<3, 1>(0, j.q) += j.multiplier * d.axis[v].cross(d.frame_p[u] - d.p[v]);
      J.template block<3, 1>(3, j.q) += j.multiplier * d.axis[v];
    } else {
      J.template block<3, 1>(0, j.q) += j.multiplier * d.axis[v];
    }
  }
  return J;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Chain rule from a world point to the joints: adds g . (d x / d q) to a row of a Jacobian.
#pragma once

#include <topograsp/kinematics/data.hpp>

namespace topograsp::detail {

/// Adds \p g' * (d x / d q) to the 1 x nq row \p row_, where x = \p x_world is a point rigidly
/// attached to link \p link and \p g is a gradient with respect to x. Mimic joints add their
/// multiplier times their contribution to their source's entry. Requires forward_kinematics()
/// first. Cheaper than forming the 3 x nq point Jacobian.
template <const auto& M, class Derived>
inline void add_point_gradient(const KinematicsData<M>& d, int link, const Vec3& x_world,
                               const Vec3& g, Eigen::MatrixBase<Derived> const& row_) noexcept {
  auto& row = const_cast<Eigen::MatrixBase<Derived>&>(row_);
  for (const SupportJoint& j : M.support(link)) {
    const auto u = static_cast<std::size_t>(j.link);
    if (j.type == JointType::revolute)
      row(0, j.q) += j.multiplier * g.dot(d.axis[u].cross(x_world - d.p[u]));
    else
      row(0, j.q) += j.multiplier * g.dot(d.axis[u]);
  }
}

}  // namespace topograsp::detail

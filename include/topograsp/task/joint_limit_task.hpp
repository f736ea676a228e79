// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// JointLimitTask: a penalty on joint values beyond their limits (less a safety margin).
#pragma once

#include <topograsp/core/error.hpp>
#include <topograsp/kinematics/data.hpp>

namespace topograsp {

/// phi_i(q) = min(0, q_i - (lo_i + delta)) + max(0, q_i - (hi_i - delta)) (dim nq, rad or m): how
/// far each configuration entry is below its lower or above its upper limit of \p M, tightened
/// by the margin delta; zero inside. With target 0 the cost rho |phi|^2 is a one-sided quadratic
/// penalty, C1 at the limits. Jacobian: diagonal, 1 where an entry is beyond a limit, else 0.
/// (Mimic joints follow their source's entry and have no entry of their own.)
template <const auto& M>
class JointLimitTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int nq = Kinematics::nq;
  static constexpr int dim = nq;

  /// Limits tightened by \p margin (rad or m; at most half the narrowest range).
  /// \throws topograsp::invalid_argument naming "margin" if it is negative, not finite, or more
  ///         than half of a joint's range.
  explicit JointLimitTask(double margin = 0.0)
      : lower_(lower_limits<M>()), upper_(upper_limits<M>()) {
    require_finite(margin, "margin");
    if (margin < 0.0 || 2.0 * margin > (upper_ - lower_).minCoeff())
      detail::throw_invalid_argument("margin", "expected 0 <= margin <= half the narrowest range");
    lower_.array() += margin;
    upper_.array() -= margin;
  }

  /// phi(q). Reads d.q (forward_kinematics(d, q) stores it).
  [[nodiscard]] Vec<nq> value(const Kinematics& d) const noexcept {
    return (d.q - lower_).cwiseMin(0.0) + (d.q - upper_).cwiseMax(0.0);
  }
  /// phi(q) and its Jacobian (nq x nq).
  void evaluate(const Kinematics& d, Vec<nq>& phi, Mat<nq, nq>& J) const noexcept {
    phi = value(d);
    J.setZero();
    for (int i = 0; i < nq; ++i)
      if (d.q[i] < lower_[i] || d.q[i] > upper_[i]) J(i, i) = 1.0;
  }

 private:
  Vec<nq> lower_, upper_;
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
// Central finite differences of kinematic quantities, the oracle for every analytic Jacobian.
#pragma once

#include <topograsp/kinematics/forward.hpp>

namespace topograsp::test {

/// Central differences of a vector function f(q) -> Vec<R> with step h.
template <int R, int N, class F>
Mat<R, N> central_difference(const Vec<N>& q, F&& f, double h = 1e-6) {
  Mat<R, N> J;
  for (int i = 0; i < q.size(); ++i) {
    Vec<N> qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    J.col(i) = (f(qp) - f(qm)) / (2.0 * h);
  }
  return J;
}

/// The angular velocity per unit q-dot of a rotation R(q), by central differences:
/// column i is vee((R(q + h e_i) - R(q - h e_i)) / 2h * R(q)^T).
template <int N, class F>
Mat<3, N> rotation_difference(const Vec<N>& q, F&& rotation, double h = 1e-6) {
  Mat<3, N> J;
  const Mat3 R0 = rotation(q);
  for (int i = 0; i < q.size(); ++i) {
    Vec<N> qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    const Mat3 S = (rotation(qp) - rotation(qm)) / (2.0 * h) * R0.transpose();
    J.col(i) << S(2, 1), S(0, 2), S(1, 0);
  }
  return J;
}

}  // namespace topograsp::test

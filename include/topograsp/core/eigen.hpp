// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Eigen aliases used throughout topograsp. Every size the model knows at compile time is fixed.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topograsp {

/// Column vector of fixed size \p N (Eigen::Dynamic for a run-time size) over the scalar \p S
/// (the stepper and the narrow phase are templates over it; everything else is double).
template <int N, class S = double>
using Vec = Eigen::Matrix<S, N, 1>;

/// Matrix of fixed size \p R x \p C over the scalar \p S.
template <int R, int C, class S = double>
using Mat = Eigen::Matrix<S, R, C>;

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;
using Vec6 = Vec<6>;
using Mat3 = Mat<3, 3>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

namespace detail {
template <class D>
void probe_matrix_base(const Eigen::MatrixBase<D>&);
}  // namespace detail

/// Any dense Eigen matrix expression (Matrix, Map, Block, products...), not arrays or scalars.
template <class T>
concept EigenDense = requires(const T& t) { detail::probe_matrix_base(t); };

/// The skew-symmetric matrix with skew(a) * b == a.cross(b).
[[nodiscard]] inline Mat3 skew(const Vec3& a) noexcept {
  Mat3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace topograsp

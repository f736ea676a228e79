// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Small fixed-size helpers of the physics module, templated over the scalar type (internal):
/// rotations and the inverse of an inertia matrix. clamp() and the closest-point kernel come from
/// geometry/detail/closest.hpp, a Pose in the scalar type from core/pose.hpp.
#pragma once

#include <cmath>
#include <limits>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/pose.hpp>
#include <topograsp/geometry/detail/closest.hpp>

namespace topograsp::detail {

template <class S>
using Quat = Eigen::Quaternion<S>;

/// The unit quaternion of the rotation by the rotation vector \p v (angle |v| about v / |v|).
template <class S>
[[nodiscard]] Quat<S> exp_rotation(const Vec<3, S>& v) noexcept {
  const S angle = v.norm();
  if (angle < S(1e-6)) {
    // Second-order series of (cos(a/2), sin(a/2)/a * v), normalised below.
    Quat<S> q(S(1) - angle * angle / S(8), S(0.5) * v.x(), S(0.5) * v.y(), S(0.5) * v.z());
    q.normalize();
    return q;
  }
  const S half = S(0.5) * angle;
  const S s = std::sin(half) / angle;
  return Quat<S>(std::cos(half), s * v.x(), s * v.y(), s * v.z());
}

/// The rotation vector (axis times angle in [0, pi]) of the rotation matrix \p R.
template <class S>
[[nodiscard]] Vec<3, S> log_rotation(const Mat<3, 3, S>& R) noexcept {
  const Eigen::AngleAxis<S> aa(R);
  return aa.axis() * aa.angle();
}

/// The angle (rad, in [0, pi]) of the rotation matrix \p R.
template <class S>
[[nodiscard]] S rotation_angle(const Mat<3, 3, S>& R) noexcept {
  S c = (R.trace() - S(1)) * S(0.5);
  if (c > S(1)) c = S(1);
  if (c < S(-1)) c = S(-1);
  // acos loses precision near 0; atan2 of |axial part| and cos does not.
  const Vec<3, S> axial(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
  return std::atan2(S(0.5) * axial.norm(), c);
}

/// The inverse of the symmetric positive definite 3x3 matrix \p A. Eigen's closed-form inverse
/// forms products of three entries, which overflow or underflow for entries beyond about 1e100 (or
/// 1e12 in float): outside [2^-k, 2^k], k a sixth of the exponent range of S, the matrix is first
/// scaled by an exact power of two, inv(A) = 2^-e inv(A 2^-e). Inside, the plain inverse.
template <class S>
[[nodiscard]] Mat<3, 3, S> inverse_in_range(const Mat<3, 3, S>& A) {
  using M3 = Mat<3, 3, S>;
  const S m = A.cwiseAbs().maxCoeff();
  constexpr int k = std::numeric_limits<S>::max_exponent / 6;
  if (!(m > S(0)) || !std::isfinite(m) || (m >= std::ldexp(S(1), -k) && m <= std::ldexp(S(1), k)))
    return A.inverse();
  int e = 0;
  (void)std::frexp(m, &e);
  return M3(M3(A * std::ldexp(S(1), -e)).inverse() * std::ldexp(S(1), -e));
}

}  // namespace topograsp::detail

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Small fixed-size helpers of the physics module, templated over the scalar type (internal).
#pragma once

#include <cmath>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/pose.hpp>

namespace topograsp::physics_detail {

template <class S>
using V3 = Eigen::Matrix<S, 3, 1>;
template <class S>
using M3 = Eigen::Matrix<S, 3, 3>;
template <class S>
using Quat = Eigen::Quaternion<S>;

/// The rotation of a Pose converted to the scalar type S.
template <class S>
[[nodiscard]] M3<S> rotation_of(const Pose& p) noexcept {
  return p.rotation().template cast<S>();
}

/// The translation of a Pose converted to the scalar type S.
template <class S>
[[nodiscard]] V3<S> translation_of(const Pose& p) noexcept {
  return p.translation().template cast<S>();
}

/// Two unit vectors t1, t2 with (t1, t2, n) right-handed and orthonormal, a deterministic function
/// of the unit vector n (Duff et al. 2017, "Building an orthonormal basis, revisited").
template <class S>
void tangent_basis(const V3<S>& n, V3<S>& t1, V3<S>& t2) noexcept {
  const S sign = std::copysign(S(1), n.z());
  const S a = S(-1) / (sign + n.z());
  const S b = n.x() * n.y() * a;
  t1 = V3<S>(S(1) + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  t2 = V3<S>(b, sign + n.y() * n.y() * a, -n.y());
}

/// The unit quaternion of the rotation by the rotation vector \p v (angle |v| about v / |v|).
template <class S>
[[nodiscard]] Quat<S> exp_rotation(const V3<S>& v) noexcept {
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
[[nodiscard]] V3<S> log_rotation(const M3<S>& R) noexcept {
  const Eigen::AngleAxis<S> aa(R);
  return aa.axis() * aa.angle();
}

/// The angle (rad, in [0, pi]) of the rotation matrix \p R.
template <class S>
[[nodiscard]] S rotation_angle(const M3<S>& R) noexcept {
  S c = (R.trace() - S(1)) * S(0.5);
  if (c > S(1)) c = S(1);
  if (c < S(-1)) c = S(-1);
  // acos loses precision near 0; atan2 of |axial part| and cos does not.
  const V3<S> axial(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
  return std::atan2(S(0.5) * axial.norm(), c);
}

/// Clamps x into [lo, hi].
template <class S>
[[nodiscard]] constexpr S clamp(S x, S lo, S hi) noexcept {
  return x < lo ? lo : (x > hi ? hi : x);
}

/// The parameters (s, t) in [0, 1]^2 of the closest points a0 + s (a1 - a0) and b0 + t (b1 - b0)
/// of two segments (either may have zero length). For parallel segments, s is the middle of the
/// overlap of A with the projection of B (so the answer is a symmetric, stable choice).
template <class S>
void closest_segment_params(const V3<S>& a0, const V3<S>& a1, const V3<S>& b0, const V3<S>& b1,
                            S& s, S& t) noexcept {
  const V3<S> d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
  const S a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const S eps = S(1e-18);
  if (a <= eps && e <= eps) {
    s = t = S(0);
    return;
  }
  if (a <= eps) {
    s = S(0);
    t = clamp(f / e, S(0), S(1));
    return;
  }
  const S c = d1.dot(r);
  if (e <= eps) {
    t = S(0);
    s = clamp(-c / a, S(0), S(1));
    return;
  }
  const S b = d1.dot(d2);
  const S denom = a * e - b * b;
  if (denom > S(1e-10) * a * e) {
    s = clamp((b * f - c * e) / denom, S(0), S(1));
  } else {
    // Parallel: the middle of the part of A that faces B.
    const S u0 = clamp(-c / a, S(0), S(1));
    const S u1 = clamp((d2.dot(d1) - c) / a, S(0), S(1));
    s = S(0.5) * (u0 + u1);
  }
  t = (b * s + f) / e;
  if (t < S(0)) {
    t = S(0);
    s = clamp(-c / a, S(0), S(1));
  } else if (t > S(1)) {
    t = S(1);
    s = clamp((b - c) / a, S(0), S(1));
  }
}

}  // namespace topograsp::physics_detail

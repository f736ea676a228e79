// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The closest-point kernel shared by the geometry and physics modules, templated over the scalar
/// type S: segment-segment closest points, a perpendicular and an orthonormal basis of a
/// direction, the closest point of a box or cylinder to a point in its frame, and the signed
/// distance of a point to a posed box or cylinder with the nearest surface point and normal.
#pragma once

#include <cmath>

#include <topograsp/core/eigen.hpp>

namespace topograsp::detail {

/// Clamps x into [lo, hi].
template <class S>
[[nodiscard]] constexpr S clamp(S x, S lo, S hi) noexcept {
  return x < lo ? lo : (x > hi ? hi : x);
}

/// Two unit vectors t1, t2 with (t1, t2, n) right-handed and orthonormal, a deterministic function
/// of the unit vector n (Duff et al. 2017, "Building an orthonormal basis, revisited").
template <class S>
void tangent_basis(const Vec<3, S>& n, Vec<3, S>& t1, Vec<3, S>& t2) noexcept {
  const S sign = std::copysign(S(1), n.z());
  const S a = S(-1) / (sign + n.z());
  const S b = n.x() * n.y() * a;
  t1 = Vec<3, S>(S(1) + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  t2 = Vec<3, S>(b, sign + n.y() * n.y() * a, -n.y());
}

/// A unit vector perpendicular to \p u (which need not be unit): the first vector of
/// tangent_basis() of u / |u|; the z axis if |u| < 1e-12.
template <class S>
[[nodiscard]] Vec<3, S> any_perpendicular(const Vec<3, S>& u) noexcept {
  const S n = u.norm();
  if (n < S(1e-12)) return Vec<3, S>::UnitZ();
  Vec<3, S> t1, t2;
  tangent_basis<S>(u / n, t1, t2);
  return t1;
}

/// The parameters (s, t) in [0, 1]^2 of the closest points a0 + s (a1 - a0) and b0 + t (b1 - b0)
/// of two segments. A segment shorter than 1e-9 (squared length <= 1e-18) counts as a point.
/// Segments count as parallel when sin^2 of their angle is at most 1e-10; then s is the middle of
/// the overlap of A with the projection of B (a symmetric, stable choice; for disjoint
/// projections, the end of A nearest B), and t the matching point of B.
template <class S>
void closest_segment_params(const Vec<3, S>& a0, const Vec<3, S>& a1, const Vec<3, S>& b0,
                            const Vec<3, S>& b1, S& s, S& t) noexcept {
  const Vec<3, S> d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
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

/// The closest points \p ca on the segment (a0, a1) and \p cb on (b0, b1) (see
/// closest_segment_params()).
template <class S>
void closest_segment_points(const Vec<3, S>& a0, const Vec<3, S>& a1, const Vec<3, S>& b0,
                            const Vec<3, S>& b1, Vec<3, S>& ca, Vec<3, S>& cb) noexcept {
  S s, t;
  closest_segment_params<S>(a0, a1, b0, b1, s, t);
  ca = a0 + s * (a1 - a0);
  cb = b0 + t * (b1 - b0);
}

/// The closest point of the box with half extents \p h (centred, in its own axes) to the point
/// \p x in those axes; \p inside is set when x is in the closed box (the point is then x).
template <class S>
[[nodiscard]] Vec<3, S> closest_on_box(const Vec<3, S>& h, const Vec<3, S>& x,
                                       bool& inside) noexcept {
  const Vec<3, S> q(clamp<S>(x.x(), -h.x(), h.x()), clamp<S>(x.y(), -h.y(), h.y()),
                    clamp<S>(x.z(), -h.z(), h.z()));
  inside = q == x;
  return q;
}

/// The closest point of the solid cylinder of \p radius and half height \p half_height (centred,
/// axis z, in its own axes) to the point \p x in those axes; \p inside is set when x is in it.
template <class S>
[[nodiscard]] Vec<3, S> closest_on_cylinder(S radius, S half_height, const Vec<3, S>& x,
                                            bool& inside) noexcept {
  const S rho = std::sqrt(x.x() * x.x() + x.y() * x.y());
  const S z = clamp<S>(x.z(), -half_height, half_height);
  if (rho <= radius) {
    inside = z == x.z();
    return Vec<3, S>(x.x(), x.y(), z);
  }
  inside = false;
  const S k = radius / rho;
  return Vec<3, S>(k * x.x(), k * x.y(), z);
}

/// Signed distance of point \p x to a solid with its nearest surface point \p y and the outward
/// unit normal \p n there, so that x = y + sd * n.
template <class S>
struct BasicPointSolid {
  S sd = S(0);
  Vec<3, S> y = Vec<3, S>::Zero();
  Vec<3, S> n = Vec<3, S>::UnitZ();
};
using PointSolid = BasicPointSolid<double>;

/// Signed distance from \p x to the box (R, p, half extents \p h). Inside, the nearest face.
template <class S>
[[nodiscard]] BasicPointSolid<S> point_box(const Vec<3, S>& x, const Mat<3, 3, S>& R,
                                           const Vec<3, S>& p, const Vec<3, S>& h) noexcept {
  const Vec<3, S> l = R.transpose() * (x - p);
  bool inside;
  const Vec<3, S> c = closest_on_box<S>(h, l, inside);
  const Vec<3, S> out = l - c;
  const S dout = out.norm();
  BasicPointSolid<S> r;
  if (dout > S(0)) {
    r.sd = dout;
    r.n = R * (out / dout);
    r.y = p + R * c;
    return r;
  }
  // Inside (or on the surface): the face with the largest (least negative) l_k - h_k.
  int k = 0;
  S best = std::abs(l[0]) - h[0];
  for (int i = 1; i < 3; ++i) {
    const S q = std::abs(l[i]) - h[i];
    if (q > best) {
      best = q;
      k = i;
    }
  }
  const S sign = l[k] >= S(0) ? S(1) : S(-1);
  Vec<3, S> yl = l;
  yl[k] = sign * h[k];
  r.sd = best;
  r.n = sign * R.col(k);
  r.y = p + R * yl;
  return r;
}

/// Signed distance from \p x to the cylinder (R, p, radius \p rad, half height \p hh, axis the
/// third column of R). Inside, the nearest of the side and the caps.
template <class S>
[[nodiscard]] BasicPointSolid<S> point_cylinder(const Vec<3, S>& x, const Mat<3, 3, S>& R,
                                                const Vec<3, S>& p, S rad, S hh) noexcept {
  const Vec<3, S> l = R.transpose() * (x - p);
  bool inside;
  const Vec<3, S> c = closest_on_cylinder<S>(rad, hh, l, inside);
  const S rho = std::sqrt(l.x() * l.x() + l.y() * l.y());
  const Vec<3, S> u =
      rho > S(0) ? Vec<3, S>(l.x() / rho, l.y() / rho, S(0)) : Vec<3, S>(Vec<3, S>::UnitX());
  const S zs = l.z() >= S(0) ? S(1) : S(-1);
  const S dr = rho - rad, dz = std::abs(l.z()) - hh;
  BasicPointSolid<S> r;
  Vec<3, S> yl, nl;
  if (dr > S(0) && dz > S(0)) {
    // Outside beyond the rim: the rim point closest_on_cylinder() found.
    yl = c;
    r.sd = std::sqrt(dr * dr + dz * dz);
    nl = (l - yl) / r.sd;
  } else if (dr > S(0)) {
    // Outside through the side: the side point closest_on_cylinder() found.
    yl = c;
    r.sd = dr;
    nl = u;
  } else if (dz <= S(0) && dr > dz) {
    // Inside nearer the side than a cap.
    yl = Vec<3, S>(rad * u.x(), rad * u.y(), l.z());
    r.sd = dr;
    nl = u;
  } else {
    yl = Vec<3, S>(l.x(), l.y(), zs * hh);
    r.sd = dz;
    nl = Vec<3, S>(S(0), S(0), zs);
  }
  r.y = p + R * yl;
  r.n = R * nl;
  return r;
}

}  // namespace topograsp::detail

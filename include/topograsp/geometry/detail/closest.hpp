// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Closed-form closest points: segment-segment, and signed distance of a point to a box or a
/// cylinder with the nearest surface point and the outward normal.
#pragma once

#include <algorithm>
#include <cmath>

#include <topograsp/core/eigen.hpp>

namespace topograsp::detail {

/// The closest points s(t) = a0 + t (a1 - a0) and u(r) = b0 + r (b1 - b0) between two segments
/// (either may have zero length). Writes them to \p ca and \p cb.
inline void closest_segment_segment(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                                    Vec3& ca, Vec3& cb) noexcept {
  const Vec3 d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double tiny = 1e-300;
  double s = 0.0, t = 0.0;
  if (a <= tiny && e <= tiny) {
    s = t = 0.0;
  } else if (a <= tiny) {
    s = 0.0;
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= tiny) {
      t = 0.0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      // Parallel segments (denom ~ 0): any s works; take 0 and let the clamps below fix t.
      s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  ca = a0 + s * d1;
  cb = b0 + t * d2;
}

/// A unit vector perpendicular to \p u (any, if u is zero).
[[nodiscard]] inline Vec3 any_perpendicular(const Vec3& u) noexcept {
  const Vec3 axis = std::abs(u.x()) < 0.57   ? Vec3::UnitX()
                    : std::abs(u.y()) < 0.57 ? Vec3::UnitY()
                                             : Vec3::UnitZ();
  const Vec3 v = u.cross(axis);
  const double n = v.norm();
  return n > 0.0 ? Vec3(v / n) : Vec3::UnitX();
}

/// Signed distance of point \p x to a solid with its nearest surface point \p y and the outward
/// unit normal \p n there, so that x = y + sd * n.
struct PointSolid {
  double sd = 0.0;
  Vec3 y = Vec3::Zero();
  Vec3 n = Vec3::UnitZ();
};

/// Signed distance from \p x to the box (R, p, half extents \p h). Inside, the nearest face.
[[nodiscard]] inline PointSolid point_box(const Vec3& x, const Mat3& R, const Vec3& p,
                                          const Vec3& h) noexcept {
  const Vec3 l = R.transpose() * (x - p);
  const Vec3 c = l.cwiseMax(-h).cwiseMin(h);
  const Vec3 out = l - c;
  const double dout = out.norm();
  PointSolid r;
  if (dout > 0.0) {
    r.sd = dout;
    r.n = R * (out / dout);
    r.y = p + R * c;
    return r;
  }
  // Inside (or on the surface): the face with the largest (least negative) l_k - h_k.
  int k = 0;
  double best = std::abs(l[0]) - h[0];
  for (int i = 1; i < 3; ++i) {
    const double q = std::abs(l[i]) - h[i];
    if (q > best) {
      best = q;
      k = i;
    }
  }
  const double sign = l[k] >= 0.0 ? 1.0 : -1.0;
  Vec3 yl = l;
  yl[k] = sign * h[k];
  r.sd = best;
  r.n = sign * R.col(k);
  r.y = p + R * yl;
  return r;
}

/// Signed distance from \p x to the cylinder (R, p, radius \p rad, half height \p hh, axis the
/// third column of R). Inside, the nearest of the side and the caps.
[[nodiscard]] inline PointSolid point_cylinder(const Vec3& x, const Mat3& R, const Vec3& p,
                                               double rad, double hh) noexcept {
  const Vec3 l = R.transpose() * (x - p);
  const double rho = std::sqrt(l.x() * l.x() + l.y() * l.y());
  const Vec3 u = rho > 0.0 ? Vec3(l.x() / rho, l.y() / rho, 0.0) : Vec3::UnitX();
  const double zs = l.z() >= 0.0 ? 1.0 : -1.0;
  const double dr = rho - rad, dz = std::abs(l.z()) - hh;
  PointSolid r;
  Vec3 yl, nl;
  if (dr > 0.0 && dz > 0.0) {
    yl = rad * u + Vec3(0, 0, zs * hh);
    r.sd = std::sqrt(dr * dr + dz * dz);
    nl = (l - yl) / r.sd;
  } else if (dr > 0.0 || (dz <= 0.0 && dr > dz)) {
    // Outside through the side, or inside nearer the side than a cap.
    yl = Vec3(rad * u.x(), rad * u.y(), l.z());
    r.sd = dr;
    nl = u;
  } else {
    yl = Vec3(l.x(), l.y(), zs * hh);
    r.sd = dz;
    nl = Vec3(0, 0, zs);
  }
  r.y = p + R * yl;
  r.n = R * nl;
  return r;
}

}  // namespace topograsp::detail

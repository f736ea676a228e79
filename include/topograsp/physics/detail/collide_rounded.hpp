// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The narrow phase for rounded shapes (internal): sphere or capsule against sphere or capsule
/// (closest points of the core segments) and against a box or cylinder (exact, by a search along
/// the core segment and clipping against faces, sides and caps).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <topograsp/geometry/detail/closest.hpp>
#include <topograsp/geometry/primitive.hpp>
#include <topograsp/model/spec.hpp>
#include <topograsp/physics/contact_set.hpp>

namespace topograsp::detail {

// Sphere/capsule against sphere/capsule: closest points of the core segments; two points when
// two capsules lie side by side.
template <class S>
void collide_rounded_rounded(const ShapeView<S>& A, const ShapeView<S>& B, S margin,
                             ContactSet<S>& out) noexcept {
  Vec<3, S> a0, a1, b0, b1, pa, pb;
  core_segment<S>(A, a0, a1);
  core_segment<S>(B, b0, b1);
  const S ra = A.size[0], rb = B.size[0];
  closest_segment_points<S>(a0, a1, b0, b1, pa, pb);
  const Vec<3, S> d = pb - pa;
  const S dist = d.norm();
  if (dist > ra + rb + margin) return;
  Vec<3, S> n = dist > S(1e-9) ? Vec<3, S>(d / dist) : any_perpendicular<S>(a1 - a0);
  const Vec<3, S> ua = a1 - a0, ub = b1 - b0;
  const S la = ua.norm(), lb = ub.norm();
  if (la > S(1e-9) && lb > S(1e-9)) {
    const Vec<3, S> da = ua / la, db = ub / lb;
    if (da.cross(db).norm() < S(0.05)) {
      // Side by side: contacts at both ends of the overlap of B's projection onto A.
      const S t0 = (b0 - a0).dot(da), t1 = (b1 - a0).dot(da);
      const S lo = std::max(S(0), std::min(t0, t1)), hi = std::min(la, std::max(t0, t1));
      if (hi - lo > S(1e-6)) {
        const S ends[2] = {lo, hi};
        for (int i = 0; i < 2; ++i) {
          const Vec<3, S> qa = a0 + ends[i] * da;
          const S tb = clamp<S>((qa - b0).dot(db), S(0), lb);
          const Vec<3, S> qb = b0 + tb * db;
          const Vec<3, S> e = qb - qa;
          const S de = e.norm();
          const Vec<3, S> ni = de > S(1e-9) ? Vec<3, S>(e / de) : n;
          const S sep = de - ra - rb;
          if (sep < margin)
            out.add(S(0.5) * (qa + ra * ni + qb - rb * ni), ni, sep, static_cast<std::uint32_t>(i));
        }
        if (out.count > 0) return;
      }
    }
  }
  out.add(S(0.5) * (pa + ra * n + pb - rb * n), n, dist - ra - rb, 2u);
}

// The closest point of a box (half extents h) or exact cylinder (radius, half height) to the
// local point x; sets inside when x is in the solid.
template <class S>
Vec<3, S> closest_on_solid(ShapeType type, const Vec<3, S>& size, const Vec<3, S>& x,
                           bool& inside) noexcept {
  return type == ShapeType::box ? closest_on_box<S>(size, x, inside)
                                : closest_on_cylinder<S>(size[0], size[1], x, inside);
}

// Clips the parameter interval [t0, t1] of x0 + t d to the slab |x_j| <= h (Liang-Barsky step).
template <class S>
bool clip_slab(S x0, S d, S h, S& t0, S& t1) noexcept {
  if (std::abs(d) < S(1e-15)) return std::abs(x0) <= h;
  S ta = (-h - x0) / d, tb = (h - x0) / d;
  if (ta > tb) std::swap(ta, tb);
  t0 = std::max(t0, ta);
  t1 = std::min(t1, tb);
  return t0 <= t1;
}

// Sphere/capsule A against box or cylinder B (exact). The distance from the core segment to the
// solid is convex along the segment, so a golden-section search finds the closest point; faces,
// cylinder sides and caps give two points for a capsule lying on them. If the core enters the
// solid, the shallowest way out through a face (box) or the cap or side (cylinder) is used.
template <class S>
void collide_rounded_solid(const ShapeView<S>& A, const ShapeView<S>& B, S margin,
                           ContactSet<S>& out) noexcept {
  Vec<3, S> w0, w1;
  S r;
  core_segment<S>(A, w0, w1);
  r = A.size[0];
  const Mat<3, 3, S> Rt = B.R.transpose();
  const Vec<3, S> P0 = Rt * (w0 - B.p), P1 = Rt * (w1 - B.p), D = P1 - P0;
  const Vec<3, S>& h = B.size;
  const bool box = B.type == ShapeType::box;
  const bool segment = D.squaredNorm() > S(1e-18);
  const auto emit = [&](const Vec<3, S>& point_local, const Vec<3, S>& normal_local, S sep,
                        std::uint32_t id) {
    out.add(B.R * point_local + B.p, B.R * normal_local, sep, id);
  };
  // Quick rejections by slabs: the box's faces, the cylinder's caps and its axis line.
  const S reach = r + margin;
  for (int k = 0; k < (box ? 3 : 1); ++k) {
    const int j = box ? k : 2;
    const S hj = box ? h[j] : h[1];
    if (std::min(P0[j], P1[j]) > hj + reach || std::max(P0[j], P1[j]) < -hj - reach) return;
  }
  if (!box) {
    const S a = D.x() * D.x() + D.y() * D.y();
    const S tm = a > S(1e-18) ? clamp<S>(-(P0.x() * D.x() + P0.y() * D.y()) / a, S(0), S(1)) : S(0);
    const S xm = P0.x() + tm * D.x(), ym = P0.y() + tm * D.y();
    if (std::sqrt(xm * xm + ym * ym) > h[0] + reach) return;
  }
  bool inside = false;
  const auto dist2 = [&](S t) {
    const Vec<3, S> x = P0 + t * D;
    bool in;
    return (closest_on_solid<S>(B.type, h, x, in) - x).squaredNorm();
  };
  S t = S(0);
  if (segment) {
    // Golden-section search on the convex function dist2(t), t in [0, 1].
    constexpr S g = S(0.6180339887498949);
    S lo = S(0), hi = S(1);
    S x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    S f1 = dist2(x1), f2 = dist2(x2);
    // Down to 1e-5 m along the segment: the distance is flat at its minimum (an error of
    // dt in t changes it by O(dt^2)), and faces and sides get their points by exact clipping.
    const S tol = S(1e-5) / std::sqrt(D.squaredNorm());
    for (int it = 0; it < 48 && hi - lo > tol; ++it) {
      if (f1 <= f2) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = dist2(x1);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = dist2(x2);
      }
    }
    t = S(0.5) * (lo + hi);
    // The ends themselves are candidates (the search never evaluates them exactly).
    if (dist2(S(0)) <= dist2(t)) t = S(0);
    if (dist2(S(1)) < dist2(t)) t = S(1);
  }
  const Vec<3, S> pc = P0 + t * D;
  const Vec<3, S> q = closest_on_solid<S>(B.type, h, pc, inside);
  const S dist = (q - pc).norm();
  if (!inside && dist > r + margin) return;
  if (!inside && dist > S(1e-9)) {
    const Vec<3, S> n = (q - pc) / dist;  // from the capsule into the solid
    if (segment) {
      if (box) {
        // A face region: exactly one coordinate clamped.
        int k = -1, clamped = 0;
        for (int j = 0; j < 3; ++j)
          if (std::abs(pc[j]) > h[j]) {
            k = j;
            ++clamped;
          }
        if (clamped == 1) {
          const S sgn = pc[k] > S(0) ? S(1) : S(-1);
          S ta = S(0), tb = S(1);
          bool ok = true;
          for (int j = 0; j < 3 && ok; ++j)
            if (j != k) ok = clip_slab<S>(P0[j], D[j], h[j], ta, tb);
          if (ok && tb - ta > S(1e-6)) {
            Vec<3, S> nf = Vec<3, S>::Zero();
            nf[k] = -sgn;
            const S ends[2] = {ta, tb};
            const int before = out.count;
            for (int i = 0; i < 2; ++i) {
              Vec<3, S> x = P0 + ends[i] * D;
              const S sep = sgn * x[k] - h[k] - r;
              if (sep >= margin) continue;
              // The midpoint between the face (sgn h_k) and the capsule surface (sgn h_k + sep).
              x[k] = sgn * (h[k] + S(0.5) * sep);
              emit(x, nf, sep, static_cast<std::uint32_t>(i));
            }
            if (out.count > before) return;
          }
        }
      } else {
        const S H = h[1], R = h[0];
        const Vec<3, S> u = D.normalized();
        if (std::abs(pc.z()) < H && std::abs(u.z()) > S(0.998)) {
          // Along the side: both ends of the part of the segment level with the cylinder.
          S ta = S(0), tb = S(1);
          if (clip_slab<S>(P0.z(), D.z(), H, ta, tb) && tb - ta > S(1e-6)) {
            const S ends[2] = {ta, tb};
            const int before = out.count;
            for (int i = 0; i < 2; ++i) {
              const Vec<3, S> x = P0 + ends[i] * D;
              const S rho = std::sqrt(x.x() * x.x() + x.y() * x.y());
              if (rho < S(1e-9)) continue;
              const S sep = rho - R - r;
              if (sep >= margin) continue;
              const Vec<3, S> radial(x.x() / rho, x.y() / rho, S(0));
              emit(x - radial * (r + S(0.5) * sep), -radial, sep, static_cast<std::uint32_t>(i));
            }
            if (out.count > before) return;
          }
        } else if (std::abs(pc.z()) > H) {
          const S rho_c = std::sqrt(pc.x() * pc.x() + pc.y() * pc.y());
          if (rho_c < R) {
            // On a cap: clip the segment to the disc, |P0_xy + t D_xy| <= R.
            const S sgn = pc.z() > S(0) ? S(1) : S(-1);
            const S a = D.x() * D.x() + D.y() * D.y();
            const S b = P0.x() * D.x() + P0.y() * D.y();
            const S c = P0.x() * P0.x() + P0.y() * P0.y() - R * R;
            S ta = S(0), tb = S(1);
            bool ok = true;
            if (a > S(1e-18)) {
              const S disc = b * b - a * c;
              ok = disc > S(0);
              if (ok) {
                const S sq = std::sqrt(disc);
                ta = std::max(ta, (-b - sq) / a);
                tb = std::min(tb, (-b + sq) / a);
              }
            } else {
              ok = c <= S(0);
            }
            if (ok && tb - ta > S(1e-6)) {
              const S ends[2] = {ta, tb};
              const int before = out.count;
              for (int i = 0; i < 2; ++i) {
                Vec<3, S> x = P0 + ends[i] * D;
                const S sep = sgn * x.z() - H - r;
                if (sep >= margin) continue;
                x.z() = sgn * (H + S(0.5) * sep);
                emit(x, Vec<3, S>(S(0), S(0), -sgn), sep, static_cast<std::uint32_t>(i));
              }
              if (out.count > before) return;
            }
          }
        }
      }
    }
    emit(S(0.5) * (pc + r * n + q), n, dist - r, 2u);
    return;
  }
  // The core segment enters the solid: leave by the shallowest face (box) or cap/side (cylinder).
  // push(k, sgn): how far the capsule must move along sgn e_k to clear the face k.
  S best = std::numeric_limits<S>::max();
  int best_k = 0;
  S best_sgn = S(1);
  const int n_axes = box ? 3 : 1;
  for (int j = 0; j < n_axes; ++j) {
    const int k = box ? j : 2;
    const S half = box ? h[k] : h[1];
    for (int si = 0; si < 2; ++si) {
      const S sgn = si ? S(1) : S(-1);
      const S push = half + r - std::min(sgn * P0[k], sgn * P1[k]);
      if (push < best) {
        best = push;
        best_k = k;
        best_sgn = sgn;
      }
    }
  }
  if (!box) {
    // The side: from the point of the segment nearest the axis, radially out.
    const S a = D.x() * D.x() + D.y() * D.y();
    const S tm = a > S(1e-18) ? clamp<S>(-(P0.x() * D.x() + P0.y() * D.y()) / a, S(0), S(1)) : S(0);
    const Vec<3, S> x = P0 + tm * D;
    const S rho = std::sqrt(x.x() * x.x() + x.y() * x.y());
    const S push = h[0] + r - rho;
    if (push < best) {
      const Vec<3, S> radial = rho > S(1e-9) ? Vec<3, S>(x.x() / rho, x.y() / rho, S(0))
                                             : any_perpendicular<S>(Vec<3, S>(D.x(), D.y(), S(0)));
      const S sep = -push;
      emit(x - radial * (r + S(0.5) * sep), -radial, sep, 3u);
      return;
    }
  }
  const S half = box ? h[best_k] : h[1];
  Vec<3, S> nf = Vec<3, S>::Zero();
  nf[best_k] = -best_sgn;
  const Vec<3, S> ends[2] = {P0, P1};
  for (int i = 0; i < (segment ? 2 : 1); ++i) {
    Vec<3, S> x = ends[i];
    const S sep = best_sgn * x[best_k] - half - r;
    if (sep >= margin) continue;
    x[best_k] = best_sgn * (half + S(0.5) * sep);
    emit(x, nf, sep, static_cast<std::uint32_t>(4 + i));
  }
}

}  // namespace topograsp::detail

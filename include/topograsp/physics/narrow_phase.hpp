// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The narrow phase: contact points, normals, separations and stable feature ids for every pair of
/// sphere, capsule, box and cylinder, up to 4 points a pair.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <topograsp/model/spec.hpp>
#include <topograsp/physics/detail/math.hpp>
#include <topograsp/physics/polytope.hpp>

namespace topograsp {

/// One contact point found by the narrow phase, in the world frame.
template <class S = double>
struct ContactFeature {
  physics_detail::V3<S> point;   ///< midway between the two surfaces (m)
  physics_detail::V3<S> normal;  ///< unit, pointing from shape A into shape B
  S separation = S(0);           ///< gap along the normal (m); negative when overlapping
  std::uint32_t id = 0;          ///< feature id, stable while the touching features stay the same
};

/// The contact points of one pair of shapes (at most 4).
template <class S = double>
struct ContactSet {
  int count = 0;
  std::array<ContactFeature<S>, 4> points{};
  void add(const physics_detail::V3<S>& point, const physics_detail::V3<S>& normal, S separation,
           std::uint32_t id) noexcept {
    if (count < 4) points[static_cast<std::size_t>(count++)] = {point, normal, separation, id};
  }
};

/// A shape placed in the world: what the narrow phase reads.
template <class S = double>
struct ShapeView {
  ShapeType type = ShapeType::sphere;
  physics_detail::V3<S> size = physics_detail::V3<S>::Zero();   ///< as ShapeSpec::size
  physics_detail::M3<S> R = physics_detail::M3<S>::Identity();  ///< world rotation
  physics_detail::V3<S> p = physics_detail::V3<S>::Zero();      ///< world position (m)
  const Polytope<S>* polytope = nullptr;  ///< local polytope for boxes and cylinders
};

namespace physics_detail {

template <class S>
constexpr bool is_rounded(ShapeType t) noexcept {
  return t == ShapeType::sphere || t == ShapeType::capsule;
}

// The core segment (a0, a1) and radius of a sphere or capsule.
template <class S>
void core_segment(const ShapeView<S>& v, V3<S>& a0, V3<S>& a1, S& r) noexcept {
  r = v.size[0];
  if (v.type == ShapeType::capsule) {
    const V3<S> h = v.R.col(2) * v.size[1];
    a0 = v.p - h;
    a1 = v.p + h;
  } else {
    a0 = a1 = v.p;
  }
}

// Any unit vector perpendicular to u (which may be zero).
template <class S>
V3<S> any_perpendicular(const V3<S>& u) noexcept {
  const S n = u.norm();
  if (n < S(1e-12)) return V3<S>::UnitZ();
  V3<S> t1, t2;
  tangent_basis<S>(u / n, t1, t2);
  return t1;
}

// Sphere/capsule against sphere/capsule: closest points of the core segments; two points when
// two capsules lie side by side.
template <class S>
void collide_rounded_rounded(const ShapeView<S>& A, const ShapeView<S>& B, S margin,
                             ContactSet<S>& out) noexcept {
  V3<S> a0, a1, b0, b1;
  S ra, rb;
  core_segment(A, a0, a1, ra);
  core_segment(B, b0, b1, rb);
  S s, t;
  closest_segment_params<S>(a0, a1, b0, b1, s, t);
  const V3<S> pa = a0 + s * (a1 - a0), pb = b0 + t * (b1 - b0);
  const V3<S> d = pb - pa;
  const S dist = d.norm();
  if (dist > ra + rb + margin) return;
  V3<S> n = dist > S(1e-9) ? V3<S>(d / dist) : any_perpendicular<S>(a1 - a0);
  const V3<S> ua = a1 - a0, ub = b1 - b0;
  const S la = ua.norm(), lb = ub.norm();
  if (la > S(1e-9) && lb > S(1e-9)) {
    const V3<S> da = ua / la, db = ub / lb;
    if (da.cross(db).norm() < S(0.05)) {
      // Side by side: contacts at both ends of the overlap of B's projection onto A.
      const S t0 = (b0 - a0).dot(da), t1 = (b1 - a0).dot(da);
      const S lo = std::max(S(0), std::min(t0, t1)), hi = std::min(la, std::max(t0, t1));
      if (hi - lo > S(1e-6)) {
        const S ends[2] = {lo, hi};
        for (int i = 0; i < 2; ++i) {
          const V3<S> qa = a0 + ends[i] * da;
          const S tb = clamp<S>((qa - b0).dot(db), S(0), lb);
          const V3<S> qb = b0 + tb * db;
          const V3<S> e = qb - qa;
          const S de = e.norm();
          const V3<S> ni = de > S(1e-9) ? V3<S>(e / de) : n;
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
V3<S> closest_on_solid(ShapeType type, const V3<S>& size, const V3<S>& x, bool& inside) noexcept {
  if (type == ShapeType::box) {
    const V3<S> q(clamp<S>(x.x(), -size.x(), size.x()), clamp<S>(x.y(), -size.y(), size.y()),
                  clamp<S>(x.z(), -size.z(), size.z()));
    inside = q == x;
    return q;
  }
  const S R = size[0], H = size[1];
  const S rho = std::sqrt(x.x() * x.x() + x.y() * x.y());
  const S z = clamp<S>(x.z(), -H, H);
  if (rho <= R) {
    inside = z == x.z();
    return V3<S>(x.x(), x.y(), z);
  }
  inside = false;
  const S k = R / rho;
  return V3<S>(k * x.x(), k * x.y(), z);
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
  V3<S> w0, w1;
  S r;
  core_segment(A, w0, w1, r);
  const M3<S> Rt = B.R.transpose();
  const V3<S> P0 = Rt * (w0 - B.p), P1 = Rt * (w1 - B.p), D = P1 - P0;
  const V3<S>& h = B.size;
  const bool box = B.type == ShapeType::box;
  const bool segment = D.squaredNorm() > S(1e-18);
  const auto emit = [&](const V3<S>& point_local, const V3<S>& normal_local, S sep,
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
    const V3<S> x = P0 + t * D;
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
  const V3<S> pc = P0 + t * D;
  const V3<S> q = closest_on_solid<S>(B.type, h, pc, inside);
  const S dist = (q - pc).norm();
  if (!inside && dist > r + margin) return;
  if (!inside && dist > S(1e-9)) {
    const V3<S> n = (q - pc) / dist;  // from the capsule into the solid
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
            V3<S> nf = V3<S>::Zero();
            nf[k] = -sgn;
            const S ends[2] = {ta, tb};
            const int before = out.count;
            for (int i = 0; i < 2; ++i) {
              V3<S> x = P0 + ends[i] * D;
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
        const V3<S> u = D.normalized();
        if (std::abs(pc.z()) < H && std::abs(u.z()) > S(0.998)) {
          // Along the side: both ends of the part of the segment level with the cylinder.
          S ta = S(0), tb = S(1);
          if (clip_slab<S>(P0.z(), D.z(), H, ta, tb) && tb - ta > S(1e-6)) {
            const S ends[2] = {ta, tb};
            const int before = out.count;
            for (int i = 0; i < 2; ++i) {
              const V3<S> x = P0 + ends[i] * D;
              const S rho = std::sqrt(x.x() * x.x() + x.y() * x.y());
              if (rho < S(1e-9)) continue;
              const S sep = rho - R - r;
              if (sep >= margin) continue;
              const V3<S> radial(x.x() / rho, x.y() / rho, S(0));
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
                V3<S> x = P0 + ends[i] * D;
                const S sep = sgn * x.z() - H - r;
                if (sep >= margin) continue;
                x.z() = sgn * (H + S(0.5) * sep);
                emit(x, V3<S>(S(0), S(0), -sgn), sep, static_cast<std::uint32_t>(i));
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
    const V3<S> x = P0 + tm * D;
    const S rho = std::sqrt(x.x() * x.x() + x.y() * x.y());
    const S push = h[0] + r - rho;
    if (push < best) {
      const V3<S> radial = rho > S(1e-9) ? V3<S>(x.x() / rho, x.y() / rho, S(0))
                                         : any_perpendicular<S>(V3<S>(D.x(), D.y(), S(0)));
      const S sep = -push;
      emit(x - radial * (r + S(0.5) * sep), -radial, sep, 3u);
      return;
    }
  }
  const S half = box ? h[best_k] : h[1];
  V3<S> nf = V3<S>::Zero();
  nf[best_k] = -best_sgn;
  const V3<S> ends[2] = {P0, P1};
  for (int i = 0; i < (segment ? 2 : 1); ++i) {
    V3<S> x = ends[i];
    const S sep = best_sgn * x[best_k] - half - r;
    if (sep >= margin) continue;
    x[best_k] = best_sgn * (half + S(0.5) * sep);
    emit(x, nf, sep, static_cast<std::uint32_t>(4 + i));
  }
}

// Box/cylinder against box/cylinder: separating axes (face normals of both, cross products of edge
// directions; for two prisms the cap-edge by cap-edge products are skipped), then either the
// closest points of two edges or the incident face clipped against the reference face.
template <class S>
void collide_polytopes(const ShapeView<S>& A, const ShapeView<S>& B, S margin,
                       ContactSet<S>& out) noexcept {
  const Polytope<S>& PA = *A.polytope;
  const Polytope<S>& PB = *B.polytope;
  std::array<V3<S>, Polytope<S>::max_vertices> va, vb;
  for (int i = 0; i < PA.n_vertices; ++i) {
    const auto u = static_cast<std::size_t>(i);
    va[u] = A.R * PA.vertices[u] + A.p;
  }
  for (int i = 0; i < PB.n_vertices; ++i) {
    const auto u = static_cast<std::size_t>(i);
    vb[u] = B.R * PB.vertices[u] + B.p;
  }
  const auto min_dot = [](const auto& v, int n, const V3<S>& axis) {
    S m = std::numeric_limits<S>::max();
    for (int i = 0; i < n; ++i) m = std::min(m, axis.dot(v[static_cast<std::size_t>(i)]));
    return m;
  };
  const auto max_dot = [](const auto& v, int n, const V3<S>& axis) {
    S m = std::numeric_limits<S>::lowest();
    for (int i = 0; i < n; ++i) m = std::max(m, axis.dot(v[static_cast<std::size_t>(i)]));
    return m;
  };
  // Faces of A.
  S sep_a = std::numeric_limits<S>::lowest();
  int face_a = 0;
  for (int f = 0; f < PA.n_faces; ++f) {
    const auto u = static_cast<std::size_t>(f);
    const V3<S> n = A.R * PA.normals[u];
    const S s = min_dot(vb, PB.n_vertices, n) - (PA.offsets[u] + n.dot(A.p));
    if (s > margin) return;
    if (s > sep_a) {
      sep_a = s;
      face_a = f;
    }
  }
  S sep_b = std::numeric_limits<S>::lowest();
  int face_b = 0;
  for (int f = 0; f < PB.n_faces; ++f) {
    const auto u = static_cast<std::size_t>(f);
    const V3<S> n = B.R * PB.normals[u];
    const S s = min_dot(va, PA.n_vertices, n) - (PB.offsets[u] + n.dot(B.p));
    if (s > margin) return;
    if (s > sep_b) {
      sep_b = s;
      face_b = f;
    }
  }
  // Edge pairs.
  S sep_e = std::numeric_limits<S>::lowest();
  int dir_a = -1, dir_b = -1;
  V3<S> axis_e = V3<S>::Zero();
  for (int i = 0; i < PA.n_directions; ++i) {
    const V3<S> ea = A.R * PA.directions[static_cast<std::size_t>(i)];
    for (int j = 0; j < PB.n_directions; ++j) {
      if (PA.prism && PB.prism && i > 0 && j > 0) continue;
      const V3<S> eb = B.R * PB.directions[static_cast<std::size_t>(j)];
      V3<S> axis = ea.cross(eb);
      const S len = axis.norm();
      if (len < S(1e-6)) continue;
      axis /= len;
      const S amin = min_dot(va, PA.n_vertices, axis), amax = max_dot(va, PA.n_vertices, axis);
      const S bmin = min_dot(vb, PB.n_vertices, axis), bmax = max_dot(vb, PB.n_vertices, axis);
      S s = bmin - amax;
      if (amin - bmax > s) {
        s = amin - bmax;
        axis = -axis;
      }
      if (s > margin) return;
      if (s > sep_e) {
        sep_e = s;
        dir_a = i;
        dir_b = j;
        axis_e = axis;
      }
    }
  }
  const S sep_face = std::max(sep_a, sep_b);
  const S tol = S(1e-4) + S(0.05) * std::abs(sep_face);
  if (dir_a >= 0 && sep_e > sep_face + tol) {
    // Edge against edge: the supporting edges of each along the axis.
    int ea = -1, eb = -1;
    S best_a = std::numeric_limits<S>::lowest(), best_b = std::numeric_limits<S>::max();
    for (int e = 0; e < PA.n_edges; ++e) {
      const auto u = static_cast<std::size_t>(e);
      if (PA.edge_direction[u] != dir_a) continue;
      const S m = axis_e.dot(va[static_cast<std::size_t>(PA.edges[u][0])] +
                             va[static_cast<std::size_t>(PA.edges[u][1])]);
      if (m > best_a) {
        best_a = m;
        ea = e;
      }
    }
    for (int e = 0; e < PB.n_edges; ++e) {
      const auto u = static_cast<std::size_t>(e);
      if (PB.edge_direction[u] != dir_b) continue;
      const S m = axis_e.dot(vb[static_cast<std::size_t>(PB.edges[u][0])] +
                             vb[static_cast<std::size_t>(PB.edges[u][1])]);
      if (m < best_b) {
        best_b = m;
        eb = e;
      }
    }
    const auto& EA = PA.edges[static_cast<std::size_t>(ea)];
    const auto& EB = PB.edges[static_cast<std::size_t>(eb)];
    const V3<S>& a0 = va[static_cast<std::size_t>(EA[0])];
    const V3<S>& a1 = va[static_cast<std::size_t>(EA[1])];
    const V3<S>& b0 = vb[static_cast<std::size_t>(EB[0])];
    const V3<S>& b1 = vb[static_cast<std::size_t>(EB[1])];
    S s, t;
    closest_segment_params<S>(a0, a1, b0, b1, s, t);
    const V3<S> pa = a0 + s * (a1 - a0), pb = b0 + t * (b1 - b0);
    out.add(S(0.5) * (pa + pb), axis_e, sep_e,
            (1u << 30) | (static_cast<std::uint32_t>(ea) << 8) | static_cast<std::uint32_t>(eb));
    return;
  }
  // Face contact: reference face on A unless B's face separates clearly better.
  const bool flip = sep_b > sep_a + tol;
  const ShapeView<S>& RefV = flip ? B : A;
  const ShapeView<S>& IncV = flip ? A : B;
  const Polytope<S>& Ref = flip ? PB : PA;
  const Polytope<S>& Inc = flip ? PA : PB;
  const auto& vref = flip ? vb : va;
  const auto& vinc = flip ? va : vb;
  const int rf = flip ? face_b : face_a;
  const auto rfu = static_cast<std::size_t>(rf);
  const V3<S> n_ref = RefV.R * Ref.normals[rfu];
  const S d_ref = Ref.offsets[rfu] + n_ref.dot(RefV.p);
  int inc_face = 0;
  S most = std::numeric_limits<S>::max();
  for (int f = 0; f < Inc.n_faces; ++f) {
    const S c = (IncV.R * Inc.normals[static_cast<std::size_t>(f)]).dot(n_ref);
    if (c < most) {
      most = c;
      inc_face = f;
    }
  }
  constexpr int cap = 2 * Polytope<S>::max_vertices + 4;
  std::array<V3<S>, cap> poly, next;
  std::array<std::uint32_t, cap> ids, next_ids;
  const auto ifu = static_cast<std::size_t>(inc_face);
  int count = Inc.face_size[ifu];
  for (int i = 0; i < count; ++i) {
    const auto u = static_cast<std::size_t>(i);
    poly[u] = vinc[static_cast<std::size_t>(
        Inc.face_indices[static_cast<std::size_t>(Inc.face_begin[ifu] + i)])];
    ids[u] = static_cast<std::uint32_t>(i);
  }
  const int nr = Ref.face_size[rfu];
  for (int e = 0; e < nr && count > 0; ++e) {
    const V3<S>& r0 = vref[static_cast<std::size_t>(
        Ref.face_indices[static_cast<std::size_t>(Ref.face_begin[rfu] + e)])];
    const V3<S>& r1 = vref[static_cast<std::size_t>(
        Ref.face_indices[static_cast<std::size_t>(Ref.face_begin[rfu] + (e + 1) % nr)])];
    const V3<S> m = (r1 - r0).cross(n_ref);  // outward side normal of the loop edge
    const S off = m.dot(r0);
    int k = 0;
    for (int i = 0; i < count; ++i) {
      const auto u = static_cast<std::size_t>(i), w = static_cast<std::size_t>((i + 1) % count);
      const S da = m.dot(poly[u]) - off, db = m.dot(poly[w]) - off;
      if (da <= S(0) && k < cap) {
        next[static_cast<std::size_t>(k)] = poly[u];
        next_ids[static_cast<std::size_t>(k++)] = ids[u];
      }
      if (((da < S(0) && db > S(0)) || (da > S(0) && db < S(0))) && k < cap) {
        next[static_cast<std::size_t>(k)] = poly[u] + (poly[w] - poly[u]) * (da / (da - db));
        next_ids[static_cast<std::size_t>(k++)] =
            0x100u + static_cast<std::uint32_t>(e) * 64u + (ids[u] & 63u);
      }
    }
    count = k;
    poly.swap(next);
    ids.swap(next_ids);
  }
  // Keep the points under the reference face (within the margin).
  std::array<V3<S>, cap> pts;
  std::array<S, cap> seps;
  std::array<std::uint32_t, cap> pid;
  int np = 0;
  for (int i = 0; i < count; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const S s = n_ref.dot(poly[u]) - d_ref;
    if (s >= margin) continue;
    const auto w = static_cast<std::size_t>(np++);
    pts[w] = poly[u] - S(0.5) * s * n_ref;
    seps[w] = s;
    pid[w] = ids[u];
  }
  if (np == 0) return;
  const V3<S> normal = flip ? V3<S>(-n_ref) : n_ref;
  const std::uint32_t base = (flip ? 1u << 31 : 0u) | (static_cast<std::uint32_t>(rf) << 21) |
                             (static_cast<std::uint32_t>(inc_face) << 16);
  // Reduce to at most 4 points: the deepest, the farthest from it, then the two that span the
  // largest area on either side of the line between them.
  std::array<int, 4> keep{-1, -1, -1, -1};
  int nk = 0;
  if (np <= 4) {
    for (int i = 0; i < np; ++i) keep[static_cast<std::size_t>(nk++)] = i;
  } else {
    int i0 = 0;
    for (int i = 1; i < np; ++i)
      if (seps[static_cast<std::size_t>(i)] < seps[static_cast<std::size_t>(i0)]) i0 = i;
    int i1 = -1;
    S far = S(-1);
    for (int i = 0; i < np; ++i) {
      const S d2 =
          (pts[static_cast<std::size_t>(i)] - pts[static_cast<std::size_t>(i0)]).squaredNorm();
      if (i != i0 && d2 > far) {
        far = d2;
        i1 = i;
      }
    }
    const V3<S> e = pts[static_cast<std::size_t>(i1)] - pts[static_cast<std::size_t>(i0)];
    int i2 = -1, i3 = -1;
    S amax = S(0), amin = S(0);
    for (int i = 0; i < np; ++i) {
      if (i == i0 || i == i1) continue;
      const S a =
          e.cross(pts[static_cast<std::size_t>(i)] - pts[static_cast<std::size_t>(i0)]).dot(n_ref);
      if (a > amax) {
        amax = a;
        i2 = i;
      }
      if (a < amin) {
        amin = a;
        i3 = i;
      }
    }
    keep[static_cast<std::size_t>(nk++)] = i0;
    keep[static_cast<std::size_t>(nk++)] = i1;
    if (i2 >= 0) keep[static_cast<std::size_t>(nk++)] = i2;
    if (i3 >= 0) keep[static_cast<std::size_t>(nk++)] = i3;
  }
  for (int k = 0; k < nk; ++k) {
    const auto u = static_cast<std::size_t>(keep[static_cast<std::size_t>(k)]);
    out.add(pts[u], normal, seps[u], base | (pid[u] & 0xffffu));
  }
}

}  // namespace physics_detail

/// Finds the contacts between two shapes whose surfaces are closer than \p margin (m): up to 4
/// points with normals from \p a into \p b, separations (negative when overlapping) and feature
/// ids. Appends to \p out (which the caller clears). Exact for pairs of spheres and capsules and
/// for those against boxes and cylinders; box and cylinder pairs use the cylinder's prism
/// (cylinder_prism_sides). Never produces a NaN for finite input.
template <class S>
void collide(const ShapeView<S>& a, const ShapeView<S>& b, S margin, ContactSet<S>& out) noexcept {
  using namespace physics_detail;
  const bool ra = is_rounded<S>(a.type), rb = is_rounded<S>(b.type);
  if (ra && rb) {
    collide_rounded_rounded<S>(a, b, margin, out);
  } else if (ra) {
    collide_rounded_solid<S>(a, b, margin, out);
  } else if (rb) {
    const int before = out.count;
    collide_rounded_solid<S>(b, a, margin, out);
    for (int i = before; i < out.count; ++i)
      out.points[static_cast<std::size_t>(i)].normal *= S(-1);
  } else {
    collide_polytopes<S>(a, b, margin, out);
  }
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// GJK (distance between separated convex shapes) and EPA (penetration depth of overlapping
/// ones) on the support functions of the primitives' cores: a capsule's segment, a box, a
/// cylinder. Fixed-size storage, no allocation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <utility>

#include <topograsp/core/constants.hpp>
#include <topograsp/geometry/contact.hpp>
#include <topograsp/geometry/detail/closest.hpp>
#include <topograsp/geometry/primitive.hpp>

namespace topograsp::detail {

/// The support point of the core of \p s (sphere: its centre; capsule: its segment; box and
/// cylinder: themselves) in direction \p d: a point of the core maximising d . x.
[[nodiscard]] inline Vec3 core_support(const Primitive& s, const Vec3& d) noexcept {
  switch (s.type) {
    case ShapeType::sphere:
      return s.p;
    case ShapeType::capsule: {
      const double dz = d.dot(s.R.col(2));
      return dz >= 0.0 ? Vec3(s.p + s.size[1] * s.R.col(2)) : Vec3(s.p - s.size[1] * s.R.col(2));
    }
    case ShapeType::box: {
      const Vec3 l = s.R.transpose() * d;
      return s.p + s.R * Vec3(l.x() >= 0.0 ? s.size[0] : -s.size[0],
                              l.y() >= 0.0 ? s.size[1] : -s.size[1],
                              l.z() >= 0.0 ? s.size[2] : -s.size[2]);
    }
    case ShapeType::cylinder: {
      // In local coordinates, so that the radial part is exactly perpendicular to the axis even
      // when d is nearly parallel to it.
      const Vec3 l = s.R.transpose() * d;
      const double rn = std::sqrt(l.x() * l.x() + l.y() * l.y());
      const double k = rn > 0.0 ? s.size[0] / rn : 0.0;
      return s.p + s.R * Vec3(k * l.x(), k * l.y(), l.z() >= 0.0 ? s.size[1] : -s.size[1]);
    }
  }
  return s.p;
}

/// A point of the Minkowski difference A - B with the points of A and B it came from.
struct SupportPoint {
  Vec3 w = Vec3::Zero();  ///< a - b
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();
};

[[nodiscard]] inline SupportPoint minkowski_support(const Primitive& A, const Primitive& B,
                                                    const Vec3& d) noexcept {
  SupportPoint s;
  s.a = core_support(A, d);
  s.b = core_support(B, -d);
  s.w = s.a - s.b;
  return s;
}

/// A simplex of up to 4 support points with the barycentric weights of its point nearest the
/// origin.
struct Simplex {
  std::array<SupportPoint, 4> v{};
  std::array<double, 4> lambda{};
  int n = 0;

  void keep(std::initializer_list<std::pair<int, double>> kept) noexcept {
    std::array<SupportPoint, 4> nv{};
    std::array<double, 4> nl{};
    int k = 0;
    for (const auto& [i, l] : kept) {
      nv[static_cast<std::size_t>(k)] = v[static_cast<std::size_t>(i)];
      nl[static_cast<std::size_t>(k)] = l;
      ++k;
    }
    v = nv;
    lambda = nl;
    n = k;
  }
  [[nodiscard]] Vec3 point() const noexcept {
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < n; ++i)
      p += lambda[static_cast<std::size_t>(i)] * v[static_cast<std::size_t>(i)].w;
    return p;
  }
  [[nodiscard]] const Vec3& w(int i) const noexcept { return v[static_cast<std::size_t>(i)].w; }
};

/// Reduces \p s to the smallest sub-simplex whose affine hull holds the point of \p s nearest the
/// origin (Voronoi-region tests on the triangle, as in Ericson's Real-Time Collision Detection
/// 5.1.5), and sets its weights. Returns false if the origin is inside the tetrahedron.
inline void reduce_triangle(Simplex& s, int ia, int ib, int ic) noexcept {
  const Vec3 &a = s.w(ia), &b = s.w(ib), &c = s.w(ic);
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = -ab.dot(a), d2 = -ac.dot(a);
  if (d1 <= 0.0 && d2 <= 0.0) return s.keep({{ia, 1.0}});
  const double d3 = -ab.dot(b), d4 = -ac.dot(b);
  if (d3 >= 0.0 && d4 <= d3) return s.keep({{ib, 1.0}});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return s.keep({{ia, 1.0 - t}, {ib, t}});
  }
  const double d5 = -ab.dot(c), d6 = -ac.dot(c);
  if (d6 >= 0.0 && d5 <= d6) return s.keep({{ic, 1.0}});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return s.keep({{ia, 1.0 - t}, {ic, t}});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return s.keep({{ib, 1.0 - t}, {ic, t}});
  }
  const double den = 1.0 / (va + vb + vc);
  const double tv = vb * den, tw = vc * den;
  s.keep({{ia, 1.0 - tv - tw}, {ib, tv}, {ic, tw}});
}

/// Reduces \p s (1 to 4 points) to the face nearest the origin; returns true if the origin is
/// inside the tetrahedron (s is then left unchanged).
inline bool reduce_simplex(Simplex& s) noexcept {
  switch (s.n) {
    case 1:
      s.lambda[0] = 1.0;
      return false;
    case 2: {
      const Vec3 &a = s.w(0), &b = s.w(1);
      const Vec3 ab = b - a;
      const double den = ab.squaredNorm();
      const double t = den > 0.0 ? -a.dot(ab) / den : 0.0;
      if (t <= 0.0)
        s.keep({{0, 1.0}});
      else if (t >= 1.0)
        s.keep({{1, 1.0}});
      else
        s.keep({{0, 1.0 - t}, {1, t}});
      return false;
    }
    case 3:
      reduce_triangle(s, 0, 1, 2);
      return false;
    default: {
      // Barycentric coordinates of the origin in the tetrahedron from signed volumes; a nearly
      // flat tetrahedron is never taken to hold the origin (rounding could put it either side).
      const Vec3 &a = s.w(0), &b = s.w(1), &c = s.w(2), &d = s.w(3);
      const double det = (b - a).cross(c - a).dot(d - a);
      const double scale = std::max({(b - a).norm(), (c - a).norm(), (d - a).norm()});
      const bool solid = std::abs(det) > 1e-10 * scale * scale * scale;
      if (solid) {
        const double l1 = (-a).cross(c - a).dot(d - a) / det;  // weight of b
        const double l2 = (b - a).cross(-a).dot(d - a) / det;  // weight of c
        const double l3 = (b - a).cross(c - a).dot(-a) / det;  // weight of d
        const double l0 = 1.0 - l1 - l2 - l3;
        if (l0 >= 0.0 && l1 >= 0.0 && l2 >= 0.0 && l3 >= 0.0) {
          s.lambda = {l0, l1, l2, l3};
          return true;
        }
      }
      // Outside: the nearest of the faces the origin is beyond (all four if flat).
      constexpr std::array<std::array<int, 4>, 4> faces{
          {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}}};
      double best = -1.0;
      Simplex best_s;
      Simplex t;
      for (const auto& f : faces) {
        const Vec3 &fa = s.w(f[0]), &fb = s.w(f[1]), &fc = s.w(f[2]), &fd = s.w(f[3]);
        const Vec3 nrm = (fb - fa).cross(fc - fa);
        const bool beyond = -fa.dot(nrm) * (fd - fa).dot(nrm) <= 0.0;
        if (solid && !beyond) continue;
        t.v = s.v;
        t.n = 4;
        reduce_triangle(t, f[0], f[1], f[2]);
        const double dist = t.point().squaredNorm();
        if (best < 0.0 || dist < best) {
          best = dist;
          best_s = t;
        }
      }
      s = best_s;
      return false;
    }
  }
}

/// The witness points of simplex \p s: sum lambda_i a_i and sum lambda_i b_i.
inline void simplex_witness(const Simplex& s, Vec3& a, Vec3& b) noexcept {
  a.setZero();
  b.setZero();
  for (int i = 0; i < s.n; ++i) {
    a += s.lambda[static_cast<std::size_t>(i)] * s.v[static_cast<std::size_t>(i)].a;
    b += s.lambda[static_cast<std::size_t>(i)] * s.v[static_cast<std::size_t>(i)].b;
  }
}

/// Result of gjk(): whether the cores overlap (within 1e-12 m), and if not their distance and
/// closest points; the final simplex seeds epa().
struct GjkResult {
  bool overlap = false;
  double distance = 0.0;
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();
  Simplex simplex;
};

/// The distance between the cores of \p A and \p B by GJK; stops when the gap between the upper
/// bound |v| and the lower bound v.w/|v| is below 1e-13 |v| (exact for polytopes, which GJK
/// reaches in finitely many steps).
[[nodiscard]] inline GjkResult gjk(const Primitive& A, const Primitive& B) noexcept {
  GjkResult r;
  Simplex& s = r.simplex;
  Vec3 d = A.p - B.p;
  if (d.squaredNorm() == 0.0) d = Vec3::UnitX();
  s.v[0] = minkowski_support(A, B, d);
  s.n = 1;
  s.lambda[0] = 1.0;
  Vec3 v = s.v[0].w;
  double vv = v.squaredNorm();
  constexpr double eps_overlap = 1e-24;  // (1e-12 m)^2
  for (int iter = 0; iter < 128; ++iter) {
    if (vv <= eps_overlap) {
      r.overlap = true;
      return r;
    }
    const SupportPoint w = minkowski_support(A, B, -v);
    if (vv - v.dot(w.w) <= 1e-13 * vv) break;
    // GJK stalls below (a repeated vertex, or rounding that stops |v| decreasing). That ends it
    // with a distance only if v separates: the support along -v lies on the far side of the
    // origin. Otherwise the origin is inside, or on the boundary within rounding (a flat simplex,
    // e.g. boxes with coinciding faces and centres): overlap, and EPA finds the depth.
    const bool separating = v.dot(w.w) > 0.0;
    // A repeated vertex means no progress is possible.
    bool repeated = false;
    for (int i = 0; i < s.n; ++i)
      if (s.w(i) == w.w) repeated = true;
    if (repeated) {
      r.overlap = !separating;
      if (r.overlap) return r;
      break;
    }
    Simplex trial = s;
    trial.v[static_cast<std::size_t>(trial.n++)] = w;
    if (reduce_simplex(trial)) {
      s = trial;
      r.overlap = true;
      return r;
    }
    const Vec3 nv = trial.point();
    const double nvv = nv.squaredNorm();
    if (nvv >= vv) {  // rounding: the previous simplex is as good as it gets
      r.overlap = !separating;
      if (r.overlap) return r;
      break;
    }
    s = trial;
    v = nv;
    vv = nvv;
  }
  r.distance = std::sqrt(vv);
  simplex_witness(s, r.a, r.b);
  return r;
}

/// Penetration of the cores of \p A and \p B by EPA, seeded with GJK's final simplex (which holds
/// the origin). Writes the depth (>= 0), the unit normal (moving B along it separates the
/// shapes) and the witness points; returns false if the polytope degenerated (the caller then
/// falls back to a cruder answer).
// g++ cannot follow that epa() reads only the polytope entries it wrote (its storage is left
// uninitialised on purpose, see there) and warns.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
inline bool epa(const Primitive& A, const Primitive& B, Simplex s, double& depth, Vec3& normal,
                Vec3& pa, Vec3& pb) noexcept {
  constexpr int max_vertices = 1024;
  constexpr int max_faces = 2 * max_vertices;
  // The polytope's storage is left uninitialised (about 190 KB; only what is written is read):
  // zeroing it took longer than most expansions.
  struct Vertex {
    Vec3 w, a, b;
    Vertex& operator=(const SupportPoint& p) noexcept {
      w = p.w;
      a = p.a;
      b = p.b;
      return *this;
    }
  };
  std::array<Vertex, max_vertices> vert;
  int nv = 0;
  for (int i = 0; i < s.n; ++i)
    vert[static_cast<std::size_t>(nv++)] = s.v[static_cast<std::size_t>(i)];
  const auto W = [&](int i) -> const Vec3& { return vert[static_cast<std::size_t>(i)].w; };
  // Blow a lower-dimensional simplex up to a tetrahedron.
  const auto try_add = [&](const Vec3& dir, auto&& accept) {
    for (const double sign : {1.0, -1.0}) {
      const SupportPoint p = minkowski_support(A, B, sign * dir);
      if (accept(p.w)) {
        vert[static_cast<std::size_t>(nv++)] = p;
        return true;
      }
    }
    return false;
  };
  constexpr double eps = 1e-12;
  if (nv == 1) {
    const std::array<Vec3, 3> axes{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
    for (const Vec3& e : axes)
      if (try_add(e, [&](const Vec3& w) { return (w - W(0)).norm() > eps; })) break;
    if (nv == 1) return false;
  }
  if (nv == 2) {
    const Vec3 u = (W(1) - W(0)).normalized();
    const Vec3 e1 = any_perpendicular<double>(u), e2 = u.cross(e1);
    bool added = false;
    for (int k = 0; k < 6 && !added; ++k) {
      const double t = pi * k / 6.0;
      const Vec3 dir = std::cos(t) * e1 + std::sin(t) * e2;
      added = try_add(dir, [&](const Vec3& w) { return (w - W(0)).cross(u).norm() > eps; });
    }
    if (!added) return false;
  }
  if (nv == 3) {
    const Vec3 n = (W(1) - W(0)).cross(W(2) - W(0));
    if (!try_add(n, [&](const Vec3& w) { return std::abs((w - W(0)).dot(n)) > eps * n.norm(); }))
      return false;
  }
  struct Face {
    std::array<int, 3> i;
    Vec3 n;
    double dist;
  };
  std::array<Face, max_faces> faces;
  int nf = 0;
  const auto make_face = [&](int a, int b, int c) {
    Face f;
    f.i = {a, b, c};
    const Vec3 n = (W(b) - W(a)).cross(W(c) - W(a));
    const double len = n.norm();
    if (!(len > 0.0)) return false;
    f.n = n / len;
    f.dist = f.n.dot(W(a));
    faces[static_cast<std::size_t>(nf++)] = f;
    return true;
  };
  {
    const Vec3 c = 0.25 * (W(0) + W(1) + W(2) + W(3));
    constexpr std::array<std::array<int, 3>, 4> tet{{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
    // Orient the tetrahedron so that its faces point outward.
    const double vol = (W(1) - W(0)).cross(W(2) - W(0)).dot(W(3) - W(0));
    if (std::abs(vol) < 1e-30) return false;
    for (auto f : tet) {
      if ((W(f[1]) - W(f[0])).cross(W(f[2]) - W(f[0])).dot(W(f[0]) - c) < 0.0)
        std::swap(f[1], f[2]);
      if (!make_face(f[0], f[1], f[2])) return false;
      if (faces[static_cast<std::size_t>(nf - 1)].dist < -1e-12) return false;
    }
  }
  // The answer from a face: the origin's projection dist * n in barycentric coordinates gives
  // the witness points. Returns false for a degenerate face.
  const auto answer = [&](const Face& f) {
    // The origin's projection dist * n on the nearest face, in barycentric coordinates, gives
    // the witness points.
    const Vec3 &a = W(f.i[0]), &b = W(f.i[1]), &c = W(f.i[2]);
    const Vec3 p = f.dist * f.n;
    const Vec3 v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1), d20 = v2.dot(v0),
                 d21 = v2.dot(v1);
    const double den = d00 * d11 - d01 * d01;
    if (!(den > 0.0)) return false;
    const double lv = (d11 * d20 - d01 * d21) / den, lw = (d00 * d21 - d01 * d20) / den;
    const double lu = 1.0 - lv - lw;
    const auto& A0 = vert[static_cast<std::size_t>(f.i[0])];
    const auto& A1 = vert[static_cast<std::size_t>(f.i[1])];
    const auto& A2 = vert[static_cast<std::size_t>(f.i[2])];
    const Vec3 xa = lu * A0.a + lv * A1.a + lw * A2.a, xb = lu * A0.b + lv * A1.b + lw * A2.b;
    if (!(std::isfinite(f.dist) && f.n.allFinite() && xa.allFinite() && xb.allFinite()))
      return false;
    pa = xa;
    pb = xb;
    depth = f.dist;
    normal = f.n;
    return true;
  };
  bool have = false;
  for (int iter = 0; iter < 4 * max_vertices; ++iter) {
    int best = 0;
    for (int f = 1; f < nf; ++f)
      if (faces[static_cast<std::size_t>(f)].dist < faces[static_cast<std::size_t>(best)].dist)
        best = f;
    const Face fb = faces[static_cast<std::size_t>(best)];
    // The polytope is inside the Minkowski difference, so its nearest face is an answer that
    // only improves; keep it in case the polytope degenerates below.
    if (answer(fb)) have = true;
    const SupportPoint w = minkowski_support(A, B, fb.n);
    const double gain = fb.n.dot(w.w) - fb.dist;
    if (gain <= 1e-10 + 1e-10 * std::abs(fb.dist) || nv == max_vertices) break;
    // Remove every face that sees w and collect the horizon (edges of exactly one removed face).
    const double eps_visible = 1e-10 * (1.0 + w.w.norm());
    std::array<std::array<int, 2>, max_faces> edges;
    int ne = 0;
    for (int f = 0; f < nf;) {
      const Face& fc = faces[static_cast<std::size_t>(f)];
      if (fc.n.dot(w.w - W(fc.i[0])) > -eps_visible) {
        for (int k = 0; k < 3; ++k) {
          const int a = fc.i[static_cast<std::size_t>(k)];
          const int b = fc.i[static_cast<std::size_t>((k + 1) % 3)];
          bool cancelled = false;
          for (int e = 0; e < ne; ++e) {
            auto& edge = edges[static_cast<std::size_t>(e)];
            if (edge[0] == b && edge[1] == a) {
              edge = edges[static_cast<std::size_t>(--ne)];
              cancelled = true;
              break;
            }
          }
          if (!cancelled) {
            if (ne == max_faces) return have;
            edges[static_cast<std::size_t>(ne++)] = {a, b};
          }
        }
        faces[static_cast<std::size_t>(f)] = faces[static_cast<std::size_t>(--nf)];
      } else {
        ++f;
      }
    }
    if (nf + ne > max_faces || ne < 3) return have;
    const int iw = nv;
    vert[static_cast<std::size_t>(nv++)] = w;
    for (int e = 0; e < ne; ++e) {
      if (!make_face(edges[static_cast<std::size_t>(e)][0], edges[static_cast<std::size_t>(e)][1],
                     iw))
        return have;
      // The new polytope holds the old one, so no face can come nearer the origin than the old
      // nearest face; if one does, rounding has folded the surface: keep the last good answer.
      if (faces[static_cast<std::size_t>(nf - 1)].dist < fb.dist - 1e-12 * (1.0 + fb.dist))
        return have;
    }
  }
  return have;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

}  // namespace topograsp::detail

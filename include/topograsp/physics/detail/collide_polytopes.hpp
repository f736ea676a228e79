// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The narrow phase for two polytopes (internal): box or cylinder prism against box or cylinder
/// prism by separating axes, then edge-edge closest points or the incident face clipped against
/// the reference face, reduced to at most 4 points.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include <topograsp/core/assert.hpp>
#include <topograsp/geometry/detail/closest.hpp>
#include <topograsp/physics/contact_set.hpp>
#include <topograsp/physics/polytope.hpp>

namespace topograsp::detail {

// Box/cylinder against box/cylinder: separating axes (face normals of both, cross products of edge
// directions; for two prisms the cap-edge by cap-edge products are skipped), then either the
// closest points of two edges or the incident face clipped against the reference face.
template <class S>
void collide_polytopes(const ShapeView<S>& A, const ShapeView<S>& B, S margin,
                       ContactSet<S>& out) noexcept {
  TOPOGRASP_ASSERT(A.polytope != nullptr && B.polytope != nullptr,
                   "the polytope collider needs both shapes' polytopes");
  const Polytope<S>& PA = *A.polytope;
  const Polytope<S>& PB = *B.polytope;
  std::array<Vec<3, S>, Polytope<S>::max_vertices> va, vb;
  for (int i = 0; i < PA.n_vertices; ++i) {
    const auto u = static_cast<std::size_t>(i);
    va[u] = A.R * PA.vertices[u] + A.p;
  }
  for (int i = 0; i < PB.n_vertices; ++i) {
    const auto u = static_cast<std::size_t>(i);
    vb[u] = B.R * PB.vertices[u] + B.p;
  }
  const auto min_dot = [](const auto& v, int n, const Vec<3, S>& axis) {
    S m = std::numeric_limits<S>::max();
    for (int i = 0; i < n; ++i) m = std::min(m, axis.dot(v[static_cast<std::size_t>(i)]));
    return m;
  };
  const auto max_dot = [](const auto& v, int n, const Vec<3, S>& axis) {
    S m = std::numeric_limits<S>::lowest();
    for (int i = 0; i < n; ++i) m = std::max(m, axis.dot(v[static_cast<std::size_t>(i)]));
    return m;
  };
  // The face of X (polytope PX) that separates it most from the vertices vy of the other shape:
  // its separation and index; false as soon as a face separates them by more than the margin.
  const auto deepest_face = [&](const ShapeView<S>& X, const Polytope<S>& PX, const auto& vy,
                                int ny, S& sep, int& face) {
    sep = std::numeric_limits<S>::lowest();
    face = 0;
    for (int f = 0; f < PX.n_faces; ++f) {
      const auto u = static_cast<std::size_t>(f);
      const Vec<3, S> n = X.R * PX.normals[u];
      const S s = min_dot(vy, ny, n) - (PX.offsets[u] + n.dot(X.p));
      if (s > margin) return false;
      if (s > sep) {
        sep = s;
        face = f;
      }
    }
    return true;
  };
  S sep_a, sep_b;
  int face_a, face_b;
  if (!deepest_face(A, PA, vb, PB.n_vertices, sep_a, face_a)) return;
  if (!deepest_face(B, PB, va, PA.n_vertices, sep_b, face_b)) return;
  // Edge pairs.
  S sep_e = std::numeric_limits<S>::lowest();
  int dir_a = -1, dir_b = -1;
  Vec<3, S> axis_e = Vec<3, S>::Zero();
  for (int i = 0; i < PA.n_directions; ++i) {
    const Vec<3, S> ea = A.R * PA.directions[static_cast<std::size_t>(i)];
    for (int j = 0; j < PB.n_directions; ++j) {
      if (PA.prism && PB.prism && i > 0 && j > 0) continue;
      const Vec<3, S> eb = B.R * PB.directions[static_cast<std::size_t>(j)];
      Vec<3, S> axis = ea.cross(eb);
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
    const Vec<3, S>& a0 = va[static_cast<std::size_t>(EA[0])];
    const Vec<3, S>& a1 = va[static_cast<std::size_t>(EA[1])];
    const Vec<3, S>& b0 = vb[static_cast<std::size_t>(EB[0])];
    const Vec<3, S>& b1 = vb[static_cast<std::size_t>(EB[1])];
    S s, t;
    closest_segment_params<S>(a0, a1, b0, b1, s, t);
    const Vec<3, S> pa = a0 + s * (a1 - a0), pb = b0 + t * (b1 - b0);
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
  const Vec<3, S> n_ref = RefV.R * Ref.normals[rfu];
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
  std::array<Vec<3, S>, cap> poly, next;
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
    const Vec<3, S>& r0 = vref[static_cast<std::size_t>(
        Ref.face_indices[static_cast<std::size_t>(Ref.face_begin[rfu] + e)])];
    const Vec<3, S>& r1 = vref[static_cast<std::size_t>(
        Ref.face_indices[static_cast<std::size_t>(Ref.face_begin[rfu] + (e + 1) % nr)])];
    const Vec<3, S> m = (r1 - r0).cross(n_ref);  // outward side normal of the loop edge
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
  std::array<Vec<3, S>, cap> pts;
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
  const Vec<3, S> normal = flip ? Vec<3, S>(-n_ref) : n_ref;
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
    const Vec<3, S> e = pts[static_cast<std::size_t>(i1)] - pts[static_cast<std::size_t>(i0)];
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

}  // namespace topograsp::detail

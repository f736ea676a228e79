// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Mesh simplification by quadric edge collapse (after Garland and Heckbert 1997, "Surface
/// simplification using quadric error metrics"): each vertex carries the sum of the squared
/// distances to the planes of its triangles (area-weighted), and the edge whose two endpoints can
/// merge into one point at the least such error collapses first. Only collapses that keep a closed
/// mesh closed, manifold, of the same genus and free of folded or flattened triangles are taken.
/// Also the largest distance from points to a mesh's surface, to measure what was lost.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <queue>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/geometry/mesh.hpp>

namespace topograsp {

/// The options of simplify_mesh().
struct SimplifyOptions {
  /// The number of triangles to reach (at least 4). Each collapse removes two, so an odd target
  /// ends one below it; simplification stops earlier when no collapse may be taken.
  int triangles = 1000;
  /// The largest turn (rad, in (0, pi]) that one collapse may give the normal of any triangle
  /// around the collapsed edge; a collapse that turns one more, or folds it over, is refused.
  double max_normal_turn = deg(60.0);
};

/// \p mesh without the triangles that welding its coincident vertices (read_mesh_file()) may have
/// collapsed, as scanned meshes with a sliver or a zero-width fold show: triangles that name a
/// vertex twice, and pairs of triangles on the same three vertices wound opposite ways (back to
/// back, they enclose nothing). The vertices are kept as they are, the other triangles in order.
[[nodiscard]] inline TriangleMesh drop_collapsed_triangles(const TriangleMesh& mesh) {
  TriangleMesh out;
  out.vertices = mesh.vertices;
  // The triangles on each set of three vertices, by winding (sorted corners, an even or odd turn
  // of them); the first of one winding cancels the first of the other, and so on.
  std::map<std::array<int, 3>, std::array<std::vector<std::size_t>, 2>> on;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<int, 3> c = mesh.triangles[t];
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
    const std::size_t first =
        static_cast<std::size_t>(std::min_element(c.begin(), c.end()) - c.begin());
    std::rotate(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(first), c.end());
    const bool odd = c[1] > c[2];
    if (odd) std::swap(c[1], c[2]);
    on[c][odd ? 1 : 0].push_back(t);
  }
  std::vector<char> keep(mesh.triangles.size(), 0);
  for (const auto& [corners, windings] : on) {
    const std::size_t cancelled = std::min(windings[0].size(), windings[1].size());
    for (const auto& w : windings)
      for (std::size_t k = cancelled; k < w.size(); ++k) keep[w[k]] = 1;
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (keep[t]) out.triangles.push_back(mesh.triangles[t]);
  return out;
}

namespace detail {

inline std::size_t simplify_index(int i) { return static_cast<std::size_t>(i); }

// 4 * sqrt(3) * area over the summed squared edge lengths: 1 for an equilateral triangle, 0 for a
// flat one.
inline double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double edges = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  if (!(edges > 0.0)) return 0.0;
  return 2.0 * std::numbers::sqrt3 * (b - a).cross(c - a).norm() / edges;
}

// The distance from p to the segment (a, b).
inline double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  const double t = dd > 0.0 ? std::clamp((p - a).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// The distance from p to the triangle (a, b, c): to its plane if p projects inside it, otherwise
// to the nearest of its edges (the nearest point then lies on the boundary).
inline double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (nn > 0.0) {
    const Vec3 q = p - n * (n.dot(p - a) / nn);  // p projected onto the plane
    if ((b - a).cross(q - a).dot(n) >= 0.0 && (c - b).cross(q - b).dot(n) >= 0.0 &&
        (a - c).cross(q - c).dot(n) >= 0.0)
      return (p - q).norm();
  }
  return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                   point_segment_distance(p, c, a)});
}

// The quadric edge collapse of simplify_mesh() on a closed mesh. Vertices keep their indices
// (merged ones die); triangles keep their indices and winding (collapsed ones die).
class EdgeCollapser {
 public:
  using Mat4 = Mat<4, 4>;

  EdgeCollapser(const TriangleMesh& mesh, const SimplifyOptions& options)
      : pos_(mesh.vertices),
        tri_(mesh.triangles),
        tri_alive_(mesh.triangles.size(), 1),
        vert_alive_(mesh.vertices.size(), 1),
        version_(mesh.vertices.size(), 0),
        quadric_(mesh.vertices.size(), Mat4::Zero()),
        star_(mesh.vertices.size()),
        alive_triangles_(mesh.triangles.size()),
        cos_turn_(std::cos(options.max_normal_turn)) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Vec3& v : pos_) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    // 100 times mesh_problems()'s degenerate area: no collapse comes near it.
    min_area_ = 1e-10 * (hi - lo).squaredNorm();
    for (std::size_t t = 0; t < tri_.size(); ++t) {
      const Vec3 &a = pos_[simplify_index(tri_[t][0])], &b = pos_[simplify_index(tri_[t][1])],
                 &c = pos_[simplify_index(tri_[t][2])];
      const Vec3 n = (b - a).cross(c - a);  // |n| = twice the area
      const double norm = n.norm();
      Eigen::Vector4d plane;
      plane << n / norm, -n.dot(a) / norm;
      const Mat4 q = (0.5 * norm) * (plane * plane.transpose());
      for (const int v : tri_[t]) {
        quadric_[simplify_index(v)] += q;
        star_[simplify_index(v)].push_back(static_cast<int>(t));
      }
    }
    for (std::size_t v = 0; v < pos_.size(); ++v)
      for (const int w : neighbours(static_cast<int>(v)))
        if (static_cast<int>(v) < w) push(static_cast<int>(v), w);
  }

  // Collapses edges, cheapest first, until at most `target` triangles remain or no edge may go.
  void run(std::size_t target) {
    while (alive_triangles_ > target && !queue_.empty()) {
      const Entry e = queue_.top();
      queue_.pop();
      if (!vert_alive_[simplify_index(e.a)] || !vert_alive_[simplify_index(e.b)] ||
          version_[simplify_index(e.a)] != e.version_a ||
          version_[simplify_index(e.b)] != e.version_b)
        continue;  // stale: an endpoint merged or its neighbourhood changed since the push
      const std::vector<Candidate> candidates = merge_candidates(e.a, e.b);
      for (std::size_t r = e.rank; r < candidates.size(); ++r) {
        if (!collapse_allowed(e.a, e.b, candidates[r].position)) continue;
        if (r == e.rank) {
          collapse(e.a, e.b, candidates[r].position);
        } else {  // the cheapest allowed position costs more: queue the edge again at its cost
          Entry again = e;
          again.cost = candidates[r].cost;
          again.rank = r;
          queue_.push(again);
        }
        break;
      }
      // No allowed position: the edge waits until a collapse near it pushes it again.
    }
  }

  // The surviving vertices and triangles, in their original order, renumbered.
  [[nodiscard]] TriangleMesh result() const {
    TriangleMesh out;
    std::vector<int> to(pos_.size(), -1);
    for (std::size_t t = 0; t < tri_.size(); ++t) {
      if (!tri_alive_[t]) continue;
      for (const int v : tri_[t]) to[simplify_index(v)] = 0;  // used
    }
    for (std::size_t v = 0; v < pos_.size(); ++v)
      if (to[v] == 0) {
        to[v] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(pos_[v]);
      }
    for (std::size_t t = 0; t < tri_.size(); ++t)
      if (tri_alive_[t])
        out.triangles.push_back({to[simplify_index(tri_[t][0])], to[simplify_index(tri_[t][1])],
                                 to[simplify_index(tri_[t][2])]});
    return out;
  }

 private:
  struct Candidate {
    double cost = 0.0;
    Vec3 position = Vec3::Zero();
  };
  // An edge (a < b) in the queue, with the versions of its endpoints when it was pushed and the
  // rank of the merge position to take among merge_candidates(a, b).
  struct Entry {
    double cost = 0.0;
    int a = 0, b = 0;
    unsigned version_a = 0, version_b = 0;
    std::size_t rank = 0;
    // Cheapest first; ties in a fixed order (the result does not depend on the queue's insides).
    bool operator>(const Entry& o) const {
      if (cost != o.cost) return cost > o.cost;
      if (a != o.a) return a > o.a;
      if (b != o.b) return b > o.b;
      return rank > o.rank;
    }
  };

  // The vertices that share a triangle with v, ascending.
  [[nodiscard]] std::vector<int> neighbours(int v) const {
    std::vector<int> out;
    for (const int t : star_[simplify_index(v)])
      for (const int w : tri_[simplify_index(t)])
        if (w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  [[nodiscard]] static double error(const Mat4& q, const Vec3& x) {
    return std::max(
        0.0, x.dot(q.topLeftCorner<3, 3>() * x) + 2.0 * x.dot(q.topRightCorner<3, 1>()) + q(3, 3));
  }

  // Where a and b may merge, cheapest first: the point of least quadric error where the 3x3
  // system is well conditioned and its solution lies within one edge length of the edge's middle,
  // then the two endpoints and the middle.
  [[nodiscard]] std::vector<Candidate> merge_candidates(int a, int b) const {
    const Mat4 q = quadric_[simplify_index(a)] + quadric_[simplify_index(b)];
    const Vec3 &pa = pos_[simplify_index(a)], &pb = pos_[simplify_index(b)];
    const Vec3 middle = 0.5 * (pa + pb);
    std::vector<Candidate> out;
    const Mat3 A = q.topLeftCorner<3, 3>();
    // For a symmetric positive semi-definite A, det / |A|_F^3 bounds the ratio of its smallest to
    // its largest eigenvalue from below.
    const double scale = A.norm(), det = A.determinant();
    if (scale > 0.0 && det > 1e-9 * scale * scale * scale) {
      const Vec3 x = A.ldlt().solve(-q.topRightCorner<3, 1>());
      if (x.allFinite() && (x - middle).norm() <= (pb - pa).norm()) out.push_back({error(q, x), x});
    }
    for (const Vec3& x : {pa, pb, middle}) out.push_back({error(q, x), x});
    std::stable_sort(out.begin(), out.end(),
                     [](const Candidate& l, const Candidate& r) { return l.cost < r.cost; });
    return out;
  }

  void push(int a, int b) {
    const std::vector<Candidate> c = merge_candidates(a, b);
    queue_.push(
        {c.front().cost, a, b, version_[simplify_index(a)], version_[simplify_index(b)], 0});
  }

  // Whether merging a and b into one vertex at x keeps the mesh a closed manifold of the same
  // genus with no triangle folded, turned too far or flattened.
  [[nodiscard]] bool collapse_allowed(int a, int b, const Vec3& x) const {
    if (alive_triangles_ <= 4) return false;
    // The link condition: a and b share exactly the two vertices opposite their edge. A third
    // shared neighbour would pinch the surface into a non-manifold edge or change its genus.
    const std::vector<int> na = neighbours(a), nb = neighbours(b);
    std::vector<int> common;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    if (common.size() != 2) return false;
    // No vertex may be left with fewer than three neighbours (a tetrahedron flattened to a
    // doubled triangle, or a vertex inside a two-triangle pocket).
    if (na.size() + nb.size() < 7) return false;
    for (const int c : common)
      if (neighbours(c).size() <= 3) return false;
    // Every triangle that stays (around a or b, not on the edge) keeps area, shape and
    // orientation within bounds.
    for (const int v : {a, b})
      for (const int t : star_[simplify_index(v)]) {
        const auto& tri = tri_[simplify_index(t)];
        const bool has_a = std::find(tri.begin(), tri.end(), a) != tri.end(),
                   has_b = std::find(tri.begin(), tri.end(), b) != tri.end();
        if (has_a && has_b) continue;  // removed by the collapse
        std::array<Vec3, 3> before, after;
        for (std::size_t k = 0; k < 3; ++k) {
          before[k] = pos_[simplify_index(tri[k])];
          after[k] = tri[k] == v ? x : before[k];
        }
        const Vec3 n0 = (before[1] - before[0]).cross(before[2] - before[0]),
                   n1 = (after[1] - after[0]).cross(after[2] - after[0]);
        if (!(0.5 * n1.norm() > min_area_)) return false;
        if (n1.dot(n0) < cos_turn_ * n1.norm() * n0.norm()) return false;
        const double q1 = triangle_quality(after[0], after[1], after[2]);
        if (q1 < 1e-3 && q1 < triangle_quality(before[0], before[1], before[2])) return false;
      }
    return true;
  }

  // Merges b into a at x: b's triangles that hold a die, the others take a in b's place.
  void collapse(int a, int b, const Vec3& x) {
    auto& star_a = star_[simplify_index(a)];
    for (const int t : star_[simplify_index(b)]) {
      auto& tri = tri_[simplify_index(t)];
      if (std::find(tri.begin(), tri.end(), a) != tri.end()) {
        tri_alive_[simplify_index(t)] = 0;
        --alive_triangles_;
        for (const int w : tri)
          if (w != b) {
            auto& s = star_[simplify_index(w)];
            s.erase(std::find(s.begin(), s.end(), t));
          }
      } else {
        std::replace(tri.begin(), tri.end(), b, a);
        star_a.push_back(t);
      }
    }
    std::sort(star_a.begin(), star_a.end());
    star_[simplify_index(b)].clear();
    vert_alive_[simplify_index(b)] = 0;
    pos_[simplify_index(a)] = x;
    quadric_[simplify_index(a)] += quadric_[simplify_index(b)];
    // Every edge at a or at one of its neighbours may now cost or be allowed differently: their
    // queue entries go stale and they are pushed again.
    std::vector<int> ring = neighbours(a);
    ring.push_back(a);
    for (const int v : ring) ++version_[simplify_index(v)];
    std::vector<std::pair<int, int>> edges;
    for (const int v : ring)
      for (const int w : neighbours(v)) edges.emplace_back(std::min(v, w), std::max(v, w));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& [v, w] : edges) push(v, w);
  }

  std::vector<Vec3> pos_;
  std::vector<std::array<int, 3>> tri_;
  std::vector<char> tri_alive_, vert_alive_;
  std::vector<unsigned> version_;
  std::vector<Mat4> quadric_;
  std::vector<std::vector<int>> star_;  // the living triangles at each vertex
  std::size_t alive_triangles_ = 0;
  double cos_turn_ = 0.5, min_area_ = 0.0;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
};

}  // namespace detail

/// \p mesh simplified to at most `options.triangles` triangles by quadric edge collapse (Garland
/// and Heckbert 1997). Each vertex carries the area-weighted sum of the squared distances to the
/// planes of its triangles (a 4x4 quadric); an edge's two endpoints merge where their summed
/// quadric is least (solving its 3x3 system, or where that is ill-conditioned or lands more than
/// one edge length from the edge's middle, at the best of the endpoints and the middle), cheapest
/// edge first. A collapse is taken only if it keeps the mesh closed, manifold and of the same
/// genus (the endpoints share exactly the two neighbours opposite their edge, and every vertex
/// keeps three neighbours or more), and if it turns no surrounding triangle's normal by more than
/// `options.max_normal_turn` and leaves none with almost no area (1e-10 of the squared diagonal
/// of the bounding box) or a sliver (shape quality, 4 sqrt(3) area over the summed squared edges,
/// below 0.001 and worse than before). Simplification stops at the target or when no collapse may
/// be taken. Triangles that repeat a vertex index, and pairs on the same three vertices wound
/// opposite ways, are dropped first (drop_collapsed_triangles()). The result keeps the winding,
/// has no unused vertices and is the same for the same input.
/// \throws topograsp::invalid_argument naming "options.triangles" (below 4),
///         "options.max_normal_turn" (not in (0, pi]) or "mesh" (with what require_closed_mesh()
///         finds once drop_collapsed_triangles() has dropped what it drops).
[[nodiscard]] inline TriangleMesh simplify_mesh(const TriangleMesh& mesh,
                                                const SimplifyOptions& options = {}) {
  if (options.triangles < 4)
    detail::throw_invalid_argument("options.triangles", "expected at least 4 triangles, got " +
                                                            std::to_string(options.triangles));
  if (!(options.max_normal_turn > 0.0 && options.max_normal_turn <= pi))
    detail::throw_invalid_argument(
        "options.max_normal_turn",
        "expected an angle in (0, pi] rad, got " + std::to_string(options.max_normal_turn));
  const TriangleMesh cleaned = drop_collapsed_triangles(mesh);
  require_closed_mesh(cleaned, "mesh");
  detail::EdgeCollapser collapser(cleaned, options);
  collapser.run(static_cast<std::size_t>(options.triangles));
  return collapser.result();
}

/// The largest distance (m) from any of \p points to the surface of \p mesh (the nearest point of
/// any of its triangles): how far a simplified mesh strays from the original's vertices. Brute
/// force, points times triangles; 0 for no points.
/// \throws topograsp::invalid_argument naming "mesh" if it has no triangles or a vertex index out
///         of range.
[[nodiscard]] inline double max_distance_to_mesh(std::span<const Vec3> points,
                                                 const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) detail::throw_invalid_argument("mesh", "the mesh has no triangles");
  const auto n = static_cast<int>(mesh.vertices.size());
  for (const auto& t : mesh.triangles)
    if (std::any_of(t.begin(), t.end(), [&](int i) { return i < 0 || i >= n; }))
      detail::throw_invalid_argument(
          "mesh", "a triangle has a vertex index outside 0.." + std::to_string(n - 1));
  double largest = 0.0;
  for (const Vec3& p : points) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles)
      d = std::min(d,
                   detail::point_triangle_distance(p, mesh.vertices[detail::simplify_index(t[0])],
                                                   mesh.vertices[detail::simplify_index(t[1])],
                                                   mesh.vertices[detail::simplify_index(t[2])]));
    largest = std::max(largest, d);
  }
  return largest;
}

}  // namespace topograsp

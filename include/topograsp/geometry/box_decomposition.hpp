// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The box decomposition of a point set (BADGr: Huebner, Ruthotto and Kragic 2008): the point
/// set's minimum-volume bounding box, split in two along the plane across one of its axes whose
/// halves' minimum-volume boxes have the least summed volume, recursively, while a split is worth
/// it (the halves' boxes fill at most `gain` of their parent's volume) and each half keeps enough
/// points. Candidate planes are scored on a sample of each half's points (the boxes of a dense
/// surface sample are fixed by few of them); the chosen split is checked on all of them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Eigenvalues>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/parameters.hpp>
#include <topograsp/geometry/mesh.hpp>

namespace topograsp {

/// An oriented box: centre and axes (columns of R), half extents along them (m).
struct OrientedBox {
  Mat3 R = Mat3::Identity();
  Vec3 centre = Vec3::Zero();
  Vec3 half = Vec3::Zero();
  [[nodiscard]] double volume() const noexcept { return 8.0 * half.prod(); }
};

/// The options of box_decomposition().
struct BoxDecompositionOptions {
  /// A box is split when its two halves' boxes fill at most this fraction of its volume
  /// (Huebner et al.'s volume gain; 0.9: a split must save a tenth of the volume).
  double gain = 0.9;
  /// Fewest points a half may keep (a split leaving fewer is not taken).
  int min_points = 20;
  /// Slabs each box axis is cut into: the planes - 1 planes between them are the splits tried.
  int planes = 24;
  /// Deepest split (a box is split at most this many times on its way from the root).
  int max_depth = 6;
  /// The points' spacing (m): each point stands for a cube of this side, so every box is grown
  /// by half of it on each side. Without it a split of sampled points always gains the gap of one
  /// spacing between the halves, and a box of a fine grid is split again and again.
  double resolution = 0.005;
  /// About how many of a box's points (every k-th, in order) a candidate plane's two boxes are
  /// found on, each half on its share of them; the chosen split's boxes use every point.
  int sample = 400;
};

/// Throws topograsp::invalid_argument naming \p argument unless \p options has a gain in (0, 1],
/// min_points >= 1, planes >= 1, max_depth >= 0 and a finite resolution >= 0.
inline void require_valid(const BoxDecompositionOptions& options, std::string_view argument) {
  if (!(options.gain > 0.0 && options.gain <= 1.0) || options.min_points < 1 ||
      options.planes < 1 || options.max_depth < 0 || options.sample < 1 ||
      !(options.resolution >= 0.0 && std::isfinite(options.resolution)))
    detail::throw_invalid_argument(argument,
                                   "expected gain in (0, 1], min_points >= 1, planes >= 1, "
                                   "max_depth >= 0, sample >= 1 and a finite resolution >= 0");
}

namespace detail {

// The box of `points` with axes R (columns): the smallest such box.
inline OrientedBox box_with_axes(std::span<const Vec3> points, const Mat3& R) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& p : points) {
    const Vec3 l = R.transpose() * p;
    lo = lo.cwiseMin(l);
    hi = hi.cwiseMax(l);
  }
  OrientedBox b;
  b.R = R;
  b.centre = R * (0.5 * (lo + hi));
  b.half = 0.5 * (hi - lo);
  return b;
}

}  // namespace detail

/// An approximately minimum-volume box around \p points (at least one, all finite): the box along
/// the principal axes of the points, then improved by turning it about each of its axes in turn
/// (a search over 90 degrees in 1-degree steps, refined to 0.05 degrees) while that shrinks it.
/// \throws topograsp::invalid_argument naming "points" if empty or not finite.
[[nodiscard]] inline OrientedBox minimum_volume_box(std::span<const Vec3> points) {
  if (points.empty()) detail::throw_invalid_argument("points", "expected at least one point");
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) {
    if (!p.allFinite()) detail::throw_invalid_argument("points", "a point is not finite");
    mean += p;
  }
  mean /= static_cast<double>(points.size());
  Mat3 cov = Mat3::Zero();
  for (const Vec3& p : points) cov += (p - mean) * (p - mean).transpose();
  Mat3 R = Eigen::SelfAdjointEigenSolver<Mat3>(cov).eigenvectors();
  if (R.determinant() < 0.0) R.col(2) = -R.col(2);
  OrientedBox best = detail::box_with_axes(points, R);
  for (int round = 0; round < 3; ++round) {
    bool improved = false;
    for (int axis = 0; axis < 3; ++axis) {
      const Mat3 base = best.R;
      double chosen = 0.0, span = deg(45.0), step = deg(1.0);
      for (int refine = 0; refine < 2; ++refine) {
        const double centre = chosen;
        for (double a = centre - span; a <= centre + span + 1e-12; a += step) {
          const OrientedBox b = detail::box_with_axes(
              points, base * Eigen::AngleAxisd(a, Vec3::Unit(axis)).toRotationMatrix());
          if (b.volume() < best.volume() * (1.0 - 1e-9)) {
            best = b;
            chosen = a;
            improved = true;
          }
        }
        span = step;
        step = deg(0.05);
      }
    }
    if (!improved) break;
  }
  return best;
}

/// The box decomposition of \p points (object frame), BADGr's: the minimum-volume box of all
/// points, split recursively as BoxDecompositionOptions says. Deterministic.
/// \throws topograsp::invalid_argument naming "points" (empty or not finite) or "options" (gain
///         outside (0, 1], min_points < 1, planes < 1, max_depth < 0, resolution negative or not
///         finite).
[[nodiscard]] inline std::vector<OrientedBox> box_decomposition(
    std::span<const Vec3> points, const BoxDecompositionOptions& options = {}) {
  require_valid(options, "options");
  std::vector<OrientedBox> out;
  struct Work {
    std::vector<Vec3> points;
    int depth;
  };
  std::vector<Work> todo{{std::vector<Vec3>(points.begin(), points.end()), 0}};
  while (!todo.empty()) {
    Work w = std::move(todo.back());
    todo.pop_back();
    const auto grown = [&](OrientedBox b) {
      b.half.array() += 0.5 * options.resolution;
      return b;
    };
    const OrientedBox box = grown(minimum_volume_box(w.points));
    // The plane: of the planes across each axis of the box, the one whose halves' minimum-volume
    // boxes have the least summed volume, the boxes found on at most `sample` of each half's
    // points (every k-th, in order): a box's volume is decided by its outermost points, which a
    // dense surface sample repeats many times over. The chosen halves' boxes are then taken on
    // all their points to decide whether the split is worth it.
    const std::size_t n = w.points.size();
    const std::size_t stride = (n + options.sample - 1) / options.sample;
    double best = std::numeric_limits<double>::infinity();
    int best_axis = -1;
    double best_cut = 0.0;
    std::vector<Vec3> below, above;
    if (w.depth < options.max_depth && n >= 2 * static_cast<std::size_t>(options.min_points))
      for (int axis = 0; axis < 3; ++axis)
        for (int k = 1; k < options.planes; ++k) {
          const double cut = -box.half[axis] + 2.0 * box.half[axis] * k / options.planes;
          std::size_t n_below = 0;
          below.clear();
          above.clear();
          for (std::size_t i = 0; i < n; ++i) {
            const bool is_below = box.R.col(axis).dot(w.points[i] - box.centre) < cut;
            const std::size_t rank = is_below ? n_below++ : i - n_below;
            if (rank % stride == 0) (is_below ? below : above).push_back(w.points[i]);
          }
          if (n_below < static_cast<std::size_t>(options.min_points) ||
              n - n_below < static_cast<std::size_t>(options.min_points))
            continue;
          const double v =
              grown(minimum_volume_box(below)).volume() + grown(minimum_volume_box(above)).volume();
          if (v < best) {
            best = v;
            best_axis = axis;
            best_cut = cut;
          }
        }
    std::vector<Vec3> lower, upper;
    if (best_axis >= 0) {
      for (const Vec3& p : w.points)
        (box.R.col(best_axis).dot(p - box.centre) < best_cut ? lower : upper).push_back(p);
      const double split =
          grown(minimum_volume_box(lower)).volume() + grown(minimum_volume_box(upper)).volume();
      if (!(split <= options.gain * box.volume())) lower.clear();
    }
    if (lower.empty()) {
      out.push_back(box);
      continue;
    }
    todo.push_back({std::move(upper), w.depth + 1});
    todo.push_back({std::move(lower), w.depth + 1});
  }
  return out;
}

/// The most points surface_points() makes: 4e6, about 100 MB of points and some 400 MB and 20 s
/// for box_decomposition() to split them. At 4 mm (MeshObjectOptions::spacing) that is a 2 m
/// cube (3e6 points); the largest shipped YCB mesh, the cracker box, needs 33901, over 100 times
/// fewer. A mesh in millimetres (1000 times larger, 1e6 times the points) is far beyond it.
inline constexpr double max_surface_points = 4e6;

namespace detail {

// The grid steps along the longest edge of triangle t of mesh at spacing: surface_points()'s n.
inline double surface_steps(const TriangleMesh& mesh, const std::array<int, 3>& t, double spacing) {
  const Vec3 &a = mesh.vertices[static_cast<std::size_t>(t[0])],
             &b = mesh.vertices[static_cast<std::size_t>(t[1])],
             &c = mesh.vertices[static_cast<std::size_t>(t[2])];
  return std::ceil(std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()}) / spacing);
}

}  // namespace detail

/// How many points surface_points(\p mesh, \p spacing) returns, counted without making them (a
/// double: it may be beyond every integer type); about twice the surface area over spacing^2.
[[nodiscard]] inline double surface_point_count(const TriangleMesh& mesh, double spacing) {
  double count = static_cast<double>(mesh.vertices.size());
  for (const auto& t : mesh.triangles) {
    const double n = detail::surface_steps(mesh, t, spacing);
    count += std::max(0.0, (n + 1.0) * (n + 2.0) / 2.0 - 3.0);  // the grid without the corners
  }
  return count;
}

namespace detail {

// Throws topograsp::invalid_argument unless surface_points(mesh, spacing) stays within
// max_surface_points, saying how many it needs: naming mesh_name with a hint at millimetres when
// the mesh is larger than 2 m (no object a hand grasps is), else spacing_name.
inline void require_surface_point_count(const TriangleMesh& mesh, double spacing,
                                        std::string_view spacing_name, std::string_view mesh_name) {
  const double count = surface_point_count(mesh, spacing);
  if (count <= max_surface_points) return;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 * (mesh.vertices[static_cast<std::size_t>(t[1])] -
                   mesh.vertices[static_cast<std::size_t>(t[0])])
                      .cross(mesh.vertices[static_cast<std::size_t>(t[2])] -
                             mesh.vertices[static_cast<std::size_t>(t[0])])
                      .norm();
  const Vec3 size = hi - lo;
  const bool huge = size.maxCoeff() > 2.0;
  throw_invalid_argument(
      huge ? mesh_name : spacing_name,
      std::string(huge ? "sampling its surface (" : "sampling the mesh's surface (") +
          number_text(area) + " m^2, bounding box " + number_text(size.x()) + " x " +
          number_text(size.y()) + " x " + number_text(size.z()) + " m) every " +
          number_text(spacing) + " m needs " + number_text(count) +
          " points, more than the limit of " + number_text(max_surface_points) +
          " (max_surface_points); " +
          (huge ? "is the mesh in millimetres? scale it by 0.001"
                : "a larger spacing samples fewer"));
}

}  // namespace detail

/// Points on the surface of \p mesh about \p spacing (m) apart: each triangle's vertices and a
/// grid of points over it, as many as its area asks. Deterministic.
/// \throws topograsp::invalid_argument naming "spacing" (not positive and finite, or more points
///         than max_surface_points) or "mesh" (more than max_surface_points and larger than 2 m:
///         the message asks whether it is in millimetres).
[[nodiscard]] inline std::vector<Vec3> surface_points(const TriangleMesh& mesh, double spacing) {
  require_positive(spacing, "spacing");
  detail::require_surface_point_count(mesh, spacing, "spacing", "mesh");
  std::vector<Vec3> out(mesh.vertices);
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[static_cast<std::size_t>(t[0])],
               &b = mesh.vertices[static_cast<std::size_t>(t[1])],
               &c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const int n = static_cast<int>(detail::surface_steps(mesh, t, spacing));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        if ((i == 0 && j == 0) || (i == n && j == 0) || (i == 0 && j == n)) continue;
        const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
        out.push_back(a + u * (b - a) + v * (c - a));
      }
  }
  return out;
}

/// The signed distance (m) from \p p to the surface of \p box: negative inside.
[[nodiscard]] inline double signed_distance(const OrientedBox& box, const Vec3& p) {
  const Vec3 d = (box.R.transpose() * (p - box.centre)).cwiseAbs() - box.half;
  return d.cwiseMax(0.0).norm() + std::min(d.maxCoeff(), 0.0);
}

/// How well boxes stand for the solid that a mesh bounds (box_decomposition's error).
struct DecompositionError {
  double volume_ratio = 0.0;  ///< the boxes' summed volume over the mesh's (overlaps counted twice)
  double mean_distance = 0.0;  ///< mean over the mesh's surface points of the nearest box face (m)
  double max_distance = 0.0;   ///< the largest such distance (m)
};

/// The error of \p boxes against the closed \p mesh: the volume ratio, and the distance from each
/// point of the mesh's surface (surface_points at \p spacing) to the nearest face of any box,
/// min over the boxes of |signed_distance|: 0 where a box face lies on the surface, the gap where
/// the surface is outside every box or the overhang where a box reaches beyond it.
/// \throws topograsp::invalid_argument naming "mesh" (require_closed_mesh), "boxes" (none) or
///         "spacing".
[[nodiscard]] inline DecompositionError decomposition_error(const TriangleMesh& mesh,
                                                            std::span<const OrientedBox> boxes,
                                                            double spacing) {
  if (boxes.empty()) detail::throw_invalid_argument("boxes", "expected at least one box");
  DecompositionError e;
  double box_volume = 0.0;
  for (const OrientedBox& b : boxes) box_volume += b.volume();
  e.volume_ratio = box_volume / mesh_mass_properties(mesh, 1.0).mass;
  const std::vector<Vec3> points = surface_points(mesh, spacing);
  for (const Vec3& p : points) {
    double d = std::numeric_limits<double>::infinity();
    for (const OrientedBox& b : boxes) d = std::min(d, std::abs(signed_distance(b, p)));
    e.mean_distance += d;
    e.max_distance = std::max(e.max_distance, d);
  }
  e.mean_distance /= static_cast<double>(points.size());
  return e;
}

}  // namespace topograsp

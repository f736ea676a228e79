// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Polytope: the convex polyhedron of a box or of a cylinder (an N-gon prism), used by the
/// box-box, box-cylinder and cylinder-cylinder contacts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/model/spec.hpp>
#include <topograsp/physics/detail/math.hpp>

namespace topograsp {

/// Sides of the prism that stands in for a cylinder in contacts with boxes and other cylinders.
/// Its vertices lie on the cylinder, so the prism is inside the cylinder by at most
/// r (1 - cos(pi / 16)) = 1.9 % of the radius between vertices. Contacts of a cylinder with
/// spheres and capsules use the exact cylinder.
inline constexpr int cylinder_prism_sides = 16;

/// A convex polyhedron in the frame of its shape: vertices, faces (outward unit normal, offset
/// and a counter-clockwise vertex loop seen from outside), edges and their distinct directions.
/// Fixed capacity, no heap memory.
template <class S = double>
struct Polytope {
  static constexpr int max_vertices = 2 * cylinder_prism_sides;
  static constexpr int max_faces = cylinder_prism_sides + 2;
  static constexpr int max_face_indices = 6 * cylinder_prism_sides;
  static constexpr int max_edges = 3 * cylinder_prism_sides;
  static constexpr int max_directions = cylinder_prism_sides / 2 + 1;

  int n_vertices = 0, n_faces = 0, n_edges = 0, n_directions = 0;
  bool prism = false;  ///< a cylinder's prism: direction 0 is the axis, the others cap edges
  std::array<Vec<3, S>, max_vertices> vertices{};
  std::array<Vec<3, S>, max_faces> normals{};
  std::array<S, max_faces> offsets{};  ///< normal . x = offset on the face plane
  std::array<int, max_faces> face_begin{}, face_size{};
  std::array<int, max_face_indices> face_indices{};
  std::array<std::array<int, 2>, max_edges> edges{};
  std::array<int, max_edges> edge_direction{};  ///< index into directions
  std::array<Vec<3, S>, max_directions> directions{};
};

namespace detail {

template <class S>
void add_face(Polytope<S>& P, const Vec<3, S>& n, const int* ids_in, int k) {
  // Adds the face with outward normal n through the k vertices ids_in, sorted into a loop.
  std::array<int, Polytope<S>::max_vertices> ids{};
  Vec<3, S> c = Vec<3, S>::Zero();
  for (int i = 0; i < k; ++i) {
    ids[static_cast<std::size_t>(i)] = ids_in[i];
    c += P.vertices[static_cast<std::size_t>(ids_in[i])];
  }
  c /= static_cast<S>(k);
  Vec<3, S> t1, t2;
  tangent_basis<S>(n, t1, t2);
  const auto angle = [&](int i) {
    const Vec<3, S> d = P.vertices[static_cast<std::size_t>(i)] - c;
    return std::atan2(d.dot(t2), d.dot(t1));
  };
  std::sort(ids.begin(), ids.begin() + k, [&](int a, int b) { return angle(a) < angle(b); });
  const auto f = static_cast<std::size_t>(P.n_faces++);
  P.normals[f] = n;
  P.offsets[f] = n.dot(P.vertices[static_cast<std::size_t>(ids[0])]);
  P.face_begin[f] = f == 0 ? 0 : P.face_begin[f - 1] + P.face_size[f - 1];
  P.face_size[f] = k;
  for (int i = 0; i < k; ++i)
    P.face_indices[static_cast<std::size_t>(P.face_begin[f] + i)] =
        ids[static_cast<std::size_t>(i)];
}

[[noreturn]] inline void throw_too_thin(std::string_view argument) {
  throw_invalid_argument(argument,
                         "the shape is too thin for its scalar type: the vertices of its faces "
                         "cannot be ordered");
}

// Collects the edges of the faces (each once) and their distinct directions (up to sign). Throws
// topograsp::invalid_argument naming \p argument if an edge has no direction in S (the shape's
// size is zero, or too small for S: its vertices coincide), or if a face so thin that add_face()
// could not order its vertices in S gives more edges or directions than the polytope holds or
// breaks Euler's formula.
template <class S>
void finish_edges(Polytope<S>& P, std::string_view argument) {
  for (int f = 0; f < P.n_faces; ++f) {
    const auto fu = static_cast<std::size_t>(f);
    for (int i = 0; i < P.face_size[fu]; ++i) {
      int a = P.face_indices[static_cast<std::size_t>(P.face_begin[fu] + i)];
      int b =
          P.face_indices[static_cast<std::size_t>(P.face_begin[fu] + (i + 1) % P.face_size[fu])];
      if (a > b) std::swap(a, b);
      bool seen = false;
      for (int e = 0; e < P.n_edges && !seen; ++e)
        seen = P.edges[static_cast<std::size_t>(e)] == std::array<int, 2>{a, b};
      if (seen) continue;
      if (P.n_edges == Polytope<S>::max_edges) throw_too_thin(argument);
      const auto e = static_cast<std::size_t>(P.n_edges++);
      P.edges[e] = {a, b};
      const Vec<3, S> edge =
          P.vertices[static_cast<std::size_t>(b)] - P.vertices[static_cast<std::size_t>(a)];
      const S largest = edge.cwiseAbs().maxCoeff(), squared = edge.squaredNorm();
      if (!(largest > S(0)) || !std::isfinite(largest))
        detail::throw_invalid_argument(argument,
                                       "the shape is too small (or too large) for its scalar type: "
                                       "two of its polytope's vertices coincide");
      // An edge whose squared length underflows or overflows is scaled by its largest entry first.
      const Vec<3, S> d = squared >= std::numeric_limits<S>::min() && std::isfinite(squared)
                              ? Vec<3, S>(edge.normalized())
                              : Vec<3, S>((edge / largest).normalized());
      int dir = -1;
      for (int k = 0; k < P.n_directions && dir < 0; ++k)
        if (std::abs(P.directions[static_cast<std::size_t>(k)].dot(d)) > S(1) - S(1e-5)) dir = k;
      if (dir < 0) {
        if (P.n_directions == Polytope<S>::max_directions) throw_too_thin(argument);
        dir = P.n_directions++;
        P.directions[static_cast<std::size_t>(dir)] = d;
      }
      P.edge_direction[e] = dir;
    }
  }
  // A closed convex polyhedron has V - E + F = 2; a face whose loop came out of order (a diagonal
  // taken for an edge) breaks it.
  if (P.n_vertices - P.n_edges + P.n_faces != 2) throw_too_thin(argument);
}

}  // namespace detail

/// The polytope of a box with half extents \p h, centred at the origin.
/// \throws topograsp::invalid_argument naming "h" if an entry is not finite and positive, or so
///         small next to the others that S cannot resolve the box's faces.
template <class S = double>
[[nodiscard]] Polytope<S> box_polytope(const Vec<3, S>& h) {
  for (int k = 0; k < 3; ++k) require_positive(static_cast<double>(h[k]), "h");
  Polytope<S> P;
  for (int i = 0; i < 8; ++i)
    P.vertices[static_cast<std::size_t>(i)] =
        Vec<3, S>((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  P.n_vertices = 8;
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 2; ++s) {
      Vec<3, S> n = Vec<3, S>::Zero();
      n[k] = s ? S(1) : S(-1);
      std::array<int, 4> ids{};
      int c = 0;
      for (int i = 0; i < 8; ++i)
        if (((i >> k) & 1) == s) ids[static_cast<std::size_t>(c++)] = i;
      detail::add_face<S>(P, n, ids.data(), 4);
    }
  // Directions first along x, y, z so that direction k is the axis k.
  P.n_directions = 3;
  P.directions[0] = Vec<3, S>::UnitX();
  P.directions[1] = Vec<3, S>::UnitY();
  P.directions[2] = Vec<3, S>::UnitZ();
  detail::finish_edges<S>(P, "h");
  return P;
}

/// The polytope of a cylinder of \p radius and \p half_height along z: a prism with
/// cylinder_prism_sides sides whose vertices lie on the cylinder.
/// \throws topograsp::invalid_argument naming "radius" or "half_height" if it is not finite and
///         positive, or so small next to the other that S cannot resolve the prism's faces.
template <class S = double>
[[nodiscard]] Polytope<S> cylinder_polytope(S radius, S half_height) {
  require_positive(static_cast<double>(radius), "radius");
  require_positive(static_cast<double>(half_height), "half_height");
  constexpr int n = cylinder_prism_sides;
  Polytope<S> P;
  P.prism = true;
  for (int i = 0; i < n; ++i) {
    const double a = two_pi * static_cast<double>(i) / n;
    const S c = static_cast<S>(std::cos(a)), s = static_cast<S>(std::sin(a));
    P.vertices[static_cast<std::size_t>(i)] = Vec<3, S>(radius * c, radius * s, -half_height);
    P.vertices[static_cast<std::size_t>(i + n)] = Vec<3, S>(radius * c, radius * s, half_height);
  }
  P.n_vertices = 2 * n;
  std::array<int, n> bottom{}, top{};
  for (int i = 0; i < n; ++i) {
    bottom[static_cast<std::size_t>(i)] = i;
    top[static_cast<std::size_t>(i)] = i + n;
  }
  detail::add_face<S>(P, Vec<3, S>(S(0), S(0), S(-1)), bottom.data(), n);
  detail::add_face<S>(P, Vec<3, S>(S(0), S(0), S(1)), top.data(), n);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const double a = two_pi * (static_cast<double>(i) + 0.5) / n;
    const Vec<3, S> normal(static_cast<S>(std::cos(a)), static_cast<S>(std::sin(a)), S(0));
    const int ids[4] = {i, j, i + n, j + n};
    detail::add_face<S>(P, normal, ids, 4);
  }
  P.n_directions = 1;
  P.directions[0] = Vec<3, S>::UnitZ();
  detail::finish_edges<S>(P, half_height < radius ? "half_height" : "radius");
  return P;
}

}  // namespace topograsp

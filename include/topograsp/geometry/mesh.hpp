// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TriangleMesh: a closed triangle mesh of an object (vertices and triangles), the checks a mesh
/// must pass before it can stand for a solid (finite, no degenerate triangle, closed, manifold,
/// wound consistently), and its mass properties at a stated density (the divergence theorem over
/// the signed tetrahedra from the origin to each triangle).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/geometry/mass_properties.hpp>

namespace topograsp {

/// A triangle mesh: vertices (m) and triangles, three vertex indices each, wound
/// counter-clockwise seen from outside (outward normals).
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

namespace detail {

// The volume of the solid a closed mesh bounds and its first and second moments (integrals of x
// and x x^T over it), by the signed tetrahedra from the origin to each triangle.
struct MeshMoments {
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
};
inline MeshMoments mesh_moments(const TriangleMesh& mesh) {
  MeshMoments m;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[static_cast<std::size_t>(t[0])],
               &b = mesh.vertices[static_cast<std::size_t>(t[1])],
               &c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const double v = a.dot(b.cross(c)) / 6.0;  // the signed tetrahedron (0, a, b, c)
    const Vec3 s = a + b + c;
    m.volume += v;
    m.first += v * s / 4.0;
    m.second +=
        v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  return m;
}

// The inertia about the centre of mass of the solid of moments m at density rho.
inline Mat3 mesh_inertia(const MeshMoments& m, double rho) {
  const Vec3 com = m.first / m.volume;
  const Mat3 origin = rho * (m.second.trace() * Mat3::Identity() - m.second);
  return origin - rho * m.volume * (com.squaredNorm() * Mat3::Identity() - com * com.transpose());
}

// The mass properties of the solid of moments m at density rho: mesh_mass_properties() without
// its checks, for a caller that made them.
inline MassProperties<> mesh_mass(const MeshMoments& m, double rho) {
  MassProperties<> p;
  p.mass = rho * m.volume;
  p.com = m.first / m.volume;
  p.inertia = mesh_inertia(m, rho);
  return p;
}

}  // namespace detail

/// What is wrong with a mesh that should bound a solid: empty if nothing. Each problem says what
/// and where (vertex or triangle indices, from 0), the first few of each kind:
/// - a vertex that is not finite, or a triangle whose index is out of range;
/// - a degenerate triangle (area below 1e-12 of the squared bounding-box diagonal, or a repeated
///   vertex);
/// - an open edge (in one triangle only: the mesh has a hole) or a non-manifold edge (in more
///   than two);
/// - two triangles that run along a shared edge the same way (inconsistent winding);
/// - a negative enclosed volume (every triangle wound inward), or a volume or moments that
///   overflow (coordinates too large).
[[nodiscard]] inline std::vector<std::string> mesh_problems(const TriangleMesh& mesh) {
  constexpr std::size_t shown = 3;  // problems of each kind that are spelled out
  std::vector<std::string> out;
  std::map<std::string, std::size_t> count;
  const auto report = [&](const std::string& kind, const std::string& what) {
    if (++count[kind] <= shown) out.push_back(what);
  };
  const auto n = static_cast<int>(mesh.vertices.size());
  if (mesh.triangles.empty()) return {"the mesh has no triangles"};
  for (int i = 0; i < n; ++i)
    if (!mesh.vertices[static_cast<std::size_t>(i)].allFinite())
      report("vertex", "vertex " + std::to_string(i) + " is not finite");
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& v : mesh.vertices)
    if (v.allFinite()) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  const double min_area = 1e-12 * (hi - lo).squaredNorm();
  // Directed edges a -> b and the triangles they come from.
  std::map<std::pair<int, int>, std::vector<int>> directed;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::string name = "triangle " + std::to_string(t);
    if (std::any_of(tri.begin(), tri.end(), [&](int i) { return i < 0 || i >= n; })) {
      report("index", name + " has a vertex index outside 0.." + std::to_string(n - 1));
      continue;
    }
    const Vec3 &a = mesh.vertices[static_cast<std::size_t>(tri[0])],
               &b = mesh.vertices[static_cast<std::size_t>(tri[1])],
               &c = mesh.vertices[static_cast<std::size_t>(tri[2])];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
        !(0.5 * (b - a).cross(c - a).norm() > min_area))
      report("degenerate", name + " (vertices " + std::to_string(tri[0]) + ", " +
                               std::to_string(tri[1]) + ", " + std::to_string(tri[2]) +
                               ") has no area");
    for (int k = 0; k < 3; ++k)
      directed[{tri[static_cast<std::size_t>(k)], tri[static_cast<std::size_t>((k + 1) % 3)]}]
          .push_back(static_cast<int>(t));
  }
  const auto edge = [](int a, int b) {
    return "edge (" + std::to_string(std::min(a, b)) + ", " + std::to_string(std::max(a, b)) + ")";
  };
  for (const auto& [e, ts] : directed) {
    const auto [a, b] = e;
    const auto back = directed.find({b, a});
    const std::size_t uses = ts.size() + (back == directed.end() ? 0 : back->second.size());
    if (a > b && back != directed.end()) continue;  // the pair is reported once, from a < b
    if (uses == 1)
      report("open",
             edge(a, b) + " is in triangle " + std::to_string(ts[0]) + " only: the mesh is open");
    else if (uses > 2)
      report("manifold", edge(a, b) + " is in " + std::to_string(uses) +
                             " triangles: the mesh is not manifold");
    else if (ts.size() == 2)
      report("winding", edge(a, b) + " runs the same way in triangles " + std::to_string(ts[0]) +
                            " and " + std::to_string(ts[1]) + ": they are wound inconsistently");
  }
  for (const auto& [kind, k] : count)
    if (k > shown)
      out.push_back("... and " + std::to_string(k - shown) + " more of the kind above (" + kind +
                    ")");
  if (out.empty()) {
    const detail::MeshMoments m = detail::mesh_moments(mesh);
    if (!std::isfinite(m.volume) || !m.first.allFinite() || !m.second.allFinite() ||
        !detail::mesh_inertia(m, 1.0).allFinite())
      out.push_back(
          "the enclosed volume or its moments overflow: coordinates too large to integrate");
    else if (!(m.volume > 0.0))
      out.push_back("the enclosed volume is not positive: the triangles are wound inward");
  }
  return out;
}

/// Throws topograsp::invalid_argument naming \p argument with every problem of mesh_problems()
/// unless \p mesh bounds a solid.
inline void require_closed_mesh(const TriangleMesh& mesh, std::string_view argument) {
  const std::vector<std::string> problems = mesh_problems(mesh);
  if (problems.empty()) return;
  std::string why;
  for (const std::string& p : problems) why += (why.empty() ? "" : "; ") + p;
  detail::throw_invalid_argument(argument, why);
}

/// The mass properties of the solid that \p mesh bounds, of uniform \p density (kg/m^3): mass,
/// centre of mass and inertia about it, in the mesh's frame. Exact for the polyhedron: the sum
/// over the triangles of the signed tetrahedra they span with the origin.
/// \throws topograsp::invalid_argument naming "mesh" (require_closed_mesh) or "density" (not
///         positive and finite).
[[nodiscard]] inline MassProperties<> mesh_mass_properties(const TriangleMesh& mesh,
                                                           double density) {
  require_closed_mesh(mesh, "mesh");
  require_positive(density, "density");
  return detail::mesh_mass(detail::mesh_moments(mesh), density);
}

}  // namespace topograsp

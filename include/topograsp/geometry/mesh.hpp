// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TriangleMesh: a closed triangle mesh of an object (vertices and triangles), the checks a mesh
/// must pass before it can stand for a solid (finite and not too large, no degenerate triangle,
/// closed, manifold, wound consistently, every shell outward), and its mass properties at a stated
/// density (the divergence theorem over the signed tetrahedra from the origin to each triangle).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/parameters.hpp>
#include <topograsp/geometry/mass_properties.hpp>

namespace topograsp {

/// A triangle mesh: vertices (m) and triangles, three vertex indices each, wound
/// counter-clockwise seen from outside (outward normals).
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

/// The largest magnitude (m) of a vertex coordinate that mesh_problems() accepts. The mesh's
/// formulas multiply coordinates: areas are of degree 2, the volume of degree 3, the inertia of
/// degree 5; at 1e6 m that is at most about 1e30 per triangle, leaving some 270 orders of
/// magnitude for the density and the triangle count, while 1e200 overflows an area. 1e6 m
/// (1000 km) is far beyond any object a hand grasps, so no mesh in metres is refused by it.
inline constexpr double max_mesh_coordinate = 1e6;

namespace detail {

// The signed volume of the tetrahedron from the origin to triangle t of mesh.
inline double tetrahedron_volume(const TriangleMesh& mesh, const std::array<int, 3>& t) {
  const Vec3 &a = mesh.vertices[static_cast<std::size_t>(t[0])],
             &b = mesh.vertices[static_cast<std::size_t>(t[1])],
             &c = mesh.vertices[static_cast<std::size_t>(t[2])];
  return a.dot(b.cross(c)) / 6.0;
}

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
    const double v = tetrahedron_volume(mesh, t);  // the signed tetrahedron (0, a, b, c)
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

// A shell of a mesh: triangles connected through shared vertices (an edge shares two).
struct MeshShell {
  std::size_t first = 0;      // its first triangle
  std::size_t triangles = 0;  // how many it has
  double volume = 0.0;        // the signed volume it encloses (positive: wound outward)
};

// The shells of a mesh whose vertex indices are in range, in the order of their first triangles.
inline std::vector<MeshShell> mesh_shells(const TriangleMesh& mesh) {
  const auto index = [](int i) { return static_cast<std::size_t>(i); };
  std::vector<std::size_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : mesh.triangles)
    for (std::size_t k = 1; k < 3; ++k) parent[root(index(t[k]))] = root(index(t[0]));
  std::vector<MeshShell> shells;
  std::vector<std::size_t> shell_of(mesh.vertices.size(), shells.max_size());  // by root vertex
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::size_t& s = shell_of[root(index(mesh.triangles[t][0]))];
    if (s == shells.max_size()) {
      s = shells.size();
      shells.push_back({t, 0, 0.0});
    }
    ++shells[s].triangles;
    shells[s].volume += tetrahedron_volume(mesh, mesh.triangles[t]);
  }
  return shells;
}

}  // namespace detail

/// What is wrong with a mesh that should bound a solid: empty if nothing. Each problem says what
/// and where (vertex or triangle indices, from 0), the first few of each kind:
/// - a vertex that is not finite, or a triangle whose index is out of range;
/// - a vertex coordinate larger in magnitude than max_mesh_coordinate (then nothing else is
///   checked: the areas and volumes would overflow);
/// - a degenerate triangle (area below 1e-12 of the squared bounding-box diagonal, or a repeated
///   vertex);
/// - an open edge (in one triangle only: the mesh has a hole) or a non-manifold edge (in more
///   than two);
/// - two triangles that run along a shared edge the same way (inconsistent winding);
/// - a shell (triangles connected through shared vertices) whose enclosed volume is not positive
///   (its triangles wound inward), named by its first triangle: every shell must be wound
///   outward, so a cavity given as an inner shell wound inward is refused; or a volume or moments
///   that overflow.
[[nodiscard]] inline std::vector<std::string> mesh_problems(const TriangleMesh& mesh) {
  constexpr std::size_t shown = 3;  // problems of each kind that are spelled out
  std::vector<std::string> out;
  std::map<std::string, std::size_t> count;
  const auto report = [&](const std::string& kind, const std::string& what) {
    if (++count[kind] <= shown) out.push_back(what);
  };
  const auto summed = [&] {  // out with a line for each kind of which some were not spelled out
    for (const auto& [kind, k] : count)
      if (k > shown)
        out.push_back("... and " + std::to_string(k - shown) + " more of the kind above (" + kind +
                      ")");
    return out;
  };
  const auto n = static_cast<int>(mesh.vertices.size());
  if (mesh.triangles.empty()) return {"the mesh has no triangles"};
  for (int i = 0; i < n; ++i) {
    const Vec3& v = mesh.vertices[static_cast<std::size_t>(i)];
    if (!v.allFinite())
      report("vertex", "vertex " + std::to_string(i) + " is not finite");
    else if (v.cwiseAbs().maxCoeff() > max_mesh_coordinate)
      report("large", "vertex " + std::to_string(i) + " has a coordinate of magnitude " +
                          detail::number_text(v.cwiseAbs().maxCoeff()) + " m, more than " +
                          detail::number_text(max_mesh_coordinate) +
                          " m: coordinates too large for the mesh's areas, volume and inertia "
                          "(is the mesh in metres?)");
  }
  if (count.contains("large")) return summed();
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
  if (!out.empty()) return summed();
  const detail::MeshMoments m = detail::mesh_moments(mesh);
  if (!std::isfinite(m.volume) || !m.first.allFinite() || !m.second.allFinite() ||
      !detail::mesh_inertia(m, 1.0).allFinite())
    return {"the enclosed volume or its moments overflow: coordinates too large to integrate"};
  for (const detail::MeshShell& s : detail::mesh_shells(mesh))
    if (!(s.volume > 0.0))
      report("inward", "the shell of triangle " + std::to_string(s.first) + " (" +
                           std::to_string(s.triangles) +
                           " triangles) encloses a volume that is not positive (" +
                           detail::number_text(s.volume) + " m^3): it is wound inward");
  return summed();
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

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Internals of the scene renderer: primitives tessellated into flat polygons with outward
/// normals (world frame).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <topograsp/core/constants.hpp>
#include <topograsp/geometry/primitive.hpp>

namespace topograsp::detail {

/// One flat polygon of a tessellated shape: vertices [first, first + count) of the mesh.
struct MeshFace {
  int first = 0;                 ///< index of its first vertex in Mesh::vertices
  int count = 0;                 ///< number of vertices (3 or 4, or more for box faces)
  int item = 0;                  ///< the scene item it belongs to
  Vec3 normal = Vec3::UnitZ();   ///< outward unit normal (world)
  Vec3 centroid = Vec3::Zero();  ///< mean of the vertices (world, m)
};

/// Polygons of one or more shapes (world frame).
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<MeshFace> faces;
};

/// Appends the polygon \p pts (\p n vertices in order around it) of item \p item, its normal
/// turned away from \p inside (a point inside the convex shape). Degenerate polygons are dropped.
inline void add_mesh_face(Mesh& m, const Vec3* pts, int n, const Vec3& inside, int item) {
  Vec3 normal = Vec3::Zero(), c = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    const Vec3& a = pts[i];
    const Vec3& b = pts[(i + 1) % n];
    normal.x() += (a.y() - b.y()) * (a.z() + b.z());  // Newell's method
    normal.y() += (a.z() - b.z()) * (a.x() + b.x());
    normal.z() += (a.x() - b.x()) * (a.y() + b.y());
    c += a;
  }
  c /= static_cast<double>(n);
  const double len = normal.norm();
  if (!(len > 1e-300)) return;
  normal /= len;
  if (normal.dot(c - inside) < 0.0) normal = -normal;
  MeshFace f;
  f.first = static_cast<int>(m.vertices.size());
  f.count = n;
  f.item = item;
  f.normal = normal;
  f.centroid = c;
  for (int i = 0; i < n; ++i) m.vertices.push_back(pts[i]);
  m.faces.push_back(f);
}

/// Appends the surface of revolution of \p profile ((z, rho) points from one end to the other,
/// rho = 0 at a pole) about the z axis of \p s, with \p n segments around.
inline void revolve(Mesh& m, const Primitive& s,
                    const std::vector<std::pair<double, double>>& profile, int n, int item) {
  const auto at = [&](const std::pair<double, double>& zr, int j) -> Vec3 {
    const double phi = 2.0 * pi * static_cast<double>(j % n) / static_cast<double>(n);
    return s.p + s.R * Vec3(zr.second * std::cos(phi), zr.second * std::sin(phi), zr.first);
  };
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const auto& a = profile[k];
    const auto& b = profile[k + 1];
    for (int j = 0; j < n; ++j) {
      if (a.second <= 0.0 && b.second <= 0.0) break;
      if (a.second <= 0.0) {
        const Vec3 t[3] = {at(a, 0), at(b, j + 1), at(b, j)};
        add_mesh_face(m, t, 3, s.p, item);
      } else if (b.second <= 0.0) {
        const Vec3 t[3] = {at(a, j), at(a, j + 1), at(b, 0)};
        add_mesh_face(m, t, 3, s.p, item);
      } else {
        const Vec3 q[4] = {at(a, j), at(a, j + 1), at(b, j + 1), at(b, j)};
        add_mesh_face(m, q, 4, s.p, item);
      }
    }
  }
}

/// The number of pieces that splits a length \p len into pieces of at most \p max_edge (1..64).
inline int mesh_pieces(double len, double max_edge) {
  if (!(max_edge > 0.0)) return 1;
  return std::clamp(static_cast<int>(std::ceil(len / max_edge - 1e-9)), 1, 64);
}

/// Appends the polygons of \p s: \p segments around round shapes, flat parts split so that no
/// edge is much longer than \p max_edge (m; 0: no splitting), so that depth sorting by centroid
/// works between neighbouring shapes.
inline void tessellate(Mesh& m, const Primitive& s, int segments, double max_edge, int item) {
  const int n = segments;
  std::vector<std::pair<double, double>> profile;
  const double r = s.size[0];
  switch (s.type) {
    case ShapeType::sphere: {
      const int bands = std::max(2, n / 2);
      for (int k = 0; k <= bands; ++k) {
        const double t = pi * static_cast<double>(k) / static_cast<double>(bands);
        profile.emplace_back(r * std::cos(t), k == 0 || k == bands ? 0.0 : r * std::sin(t));
      }
      revolve(m, s, profile, n, item);
      return;
    }
    case ShapeType::capsule: {
      const double h = s.size[1];
      const int bands = std::max(2, n / 4);
      for (int k = 0; k <= bands; ++k) {
        const double t = 0.5 * pi * static_cast<double>(k) / static_cast<double>(bands);
        profile.emplace_back(h + r * std::cos(t), k == 0 ? 0.0 : r * std::sin(t));
      }
      const int body = h > 0.0 ? mesh_pieces(2.0 * h, max_edge) : 0;
      for (int k = 1; k <= body; ++k)
        profile.emplace_back(h - 2.0 * h * static_cast<double>(k) / static_cast<double>(body), r);
      for (int k = 1; k <= bands; ++k) {
        const double t = 0.5 * pi * static_cast<double>(k) / static_cast<double>(bands);
        profile.emplace_back(-h - r * std::sin(t), k == bands ? 0.0 : r * std::cos(t));
      }
      revolve(m, s, profile, n, item);
      return;
    }
    case ShapeType::cylinder: {
      const double h = s.size[1];
      const int rings = mesh_pieces(r, max_edge), body = mesh_pieces(2.0 * h, max_edge);
      for (int k = 0; k <= rings; ++k)
        profile.emplace_back(h, r * static_cast<double>(k) / static_cast<double>(rings));
      for (int k = 1; k <= body; ++k)
        profile.emplace_back(h - 2.0 * h * static_cast<double>(k) / static_cast<double>(body), r);
      for (int k = rings - 1; k >= 0; --k)
        profile.emplace_back(-h, r * static_cast<double>(k) / static_cast<double>(rings));
      revolve(m, s, profile, n, item);
      return;
    }
    case ShapeType::box: {
      for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int nu = mesh_pieces(2.0 * s.size[u], max_edge);
        const int nv = mesh_pieces(2.0 * s.size[v], max_edge);
        for (const double side : {1.0, -1.0})
          for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
              Vec3 q[4];
              const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
              for (int c = 0; c < 4; ++c) {
                Vec3 local;
                local[axis] = side * s.size[axis];
                local[u] = s.size[u] * (-1.0 + 2.0 * static_cast<double>(i + du[c]) / nu);
                local[v] = s.size[v] * (-1.0 + 2.0 * static_cast<double>(j + dv[c]) / nv);
                q[c] = s.p + s.R * local;
              }
              add_mesh_face(m, q, 4, s.p, item);
            }
      }
      return;
    }
  }
}

}  // namespace topograsp::detail

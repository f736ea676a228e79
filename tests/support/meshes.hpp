// SPDX-License-Identifier: BSD-3-Clause
// Closed triangle meshes of known solids for the tests and benchmarks: a box and a cylinder whose
// volume, centre of mass and inertia have closed forms.
#pragma once

#include <cmath>

#include <topograsp/core/constants.hpp>
#include <topograsp/geometry/mesh.hpp>

namespace topograsp::test {

// The axis-aligned box [0, x] x [0, y] x [0, z], 8 vertices, 12 triangles wound outward.
inline TriangleMesh box_mesh(double x, double y, double z) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? x : 0.0, i & 2 ? y : 0.0, i & 4 ? z : 0.0);
  // Each face as a quad (counter-clockwise from outside), split into two triangles.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// A cylinder of radius r standing on z = 0 up to z = h about the z axis, its circles as n-gons
// (2n + 2 vertices: the rings and the caps' centres), wound outward.
inline TriangleMesh cylinder_mesh(double r, double h, int n) {
  TriangleMesh m;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * pi * k / n;
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), h);
  }
  const int bottom = 2 * n, top = 2 * n + 1;
  m.vertices.emplace_back(0.0, 0.0, 0.0);
  m.vertices.emplace_back(0.0, 0.0, h);
  for (int k = 0; k < n; ++k) {
    const int b0 = 2 * k, t0 = 2 * k + 1, b1 = 2 * ((k + 1) % n), t1 = b1 + 1;
    m.triangles.push_back({b0, b1, t1});
    m.triangles.push_back({b0, t1, t0});
    m.triangles.push_back({bottom, b1, b0});
    m.triangles.push_back({top, t0, t1});
  }
  return m;
}

}  // namespace topograsp::test

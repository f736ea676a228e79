// SPDX-License-Identifier: BSD-3-Clause
// TriangleMesh (geometry/mesh.hpp): what mesh_problems() finds in broken meshes, and the mass
// properties of closed meshes against closed forms.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include <topograsp/geometry/mesh.hpp>

#include "support/meshes.hpp"

using namespace topograsp;
using topograsp::test::box_mesh;

namespace {

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const std::string& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("a closed box mesh has no problems and the mass properties of the box",
          "[geometry][mesh]") {
  const TriangleMesh m = box_mesh(0.1, 0.2, 0.3);
  CHECK(mesh_problems(m).empty());
  const MassProperties<> p = mesh_mass_properties(m, 1000.0);
  const double mass = 1000.0 * 0.1 * 0.2 * 0.3;
  CHECK(p.mass == Approx(mass));
  CHECK((p.com - Vec3(0.05, 0.1, 0.15)).norm() < 1e-12);
  const Vec3 diagonal(mass * (0.04 + 0.09) / 12.0, mass * (0.01 + 0.09) / 12.0,
                      mass * (0.01 + 0.04) / 12.0);
  CHECK((p.inertia.diagonal() - diagonal).norm() < 1e-12);
  CHECK(std::abs(p.inertia(0, 1)) < 1e-12);
  // Moving the mesh moves the centre of mass, not the inertia about it.
  TriangleMesh moved = m;
  for (Vec3& v : moved.vertices) v += Vec3(1.0, -2.0, 0.5);
  const MassProperties<> q = mesh_mass_properties(moved, 1000.0);
  CHECK((q.com - p.com - Vec3(1.0, -2.0, 0.5)).norm() < 1e-9);
  CHECK((q.inertia - p.inertia).norm() < 1e-9);
}

TEST_CASE("mesh_problems says what is wrong and where", "[geometry][mesh][bad-input]") {
  const TriangleMesh box = box_mesh(1, 1, 1);
  TriangleMesh open = box;
  open.triangles.pop_back();
  CHECK(mentions(mesh_problems(open), "the mesh is open"));
  TriangleMesh flipped = box;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  CHECK(mentions(mesh_problems(flipped), "wound inconsistently"));
  CHECK(mentions(mesh_problems(flipped), "triangles 3"));
  TriangleMesh doubled = box;
  doubled.triangles.push_back(box.triangles[0]);
  doubled.triangles.push_back({box.triangles[0][0], box.triangles[0][2], box.triangles[0][1]});
  CHECK(mentions(mesh_problems(doubled), "not manifold"));
  TriangleMesh degenerate = box;
  degenerate.triangles[5] = {1, 1, 2};
  CHECK(mentions(mesh_problems(degenerate), "triangle 5 (vertices 1, 1, 2) has no area"));
  TriangleMesh bad_index = box;
  bad_index.triangles[2][0] = 8;
  CHECK(mentions(mesh_problems(bad_index), "triangle 2 has a vertex index outside 0..7"));
  TriangleMesh nan = box;
  nan.vertices[4].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK(mentions(mesh_problems(nan), "vertex 4 is not finite"));
  TriangleMesh inward = box;
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  CHECK(mentions(mesh_problems(inward), "wound inward"));
  CHECK(mesh_problems(TriangleMesh{}) == std::vector<std::string>{"the mesh has no triangles"});
  CHECK_THROWS_WITH(mesh_mass_properties(open, 1000.0),
                    Catch::StartsWith("mesh: ") && Catch::Contains("open"));
  CHECK_THROWS_WITH(mesh_mass_properties(box, -1.0), Catch::Contains("density"));
}

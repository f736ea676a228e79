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

TEST_CASE("every closed shell of a mesh must be wound outward", "[geometry][mesh][bad-input]") {
  // Two disjoint boxes, 1 m^3 and 0.125 m^3. Wound outward they are one solid of 1.125 m^3.
  TriangleMesh two = box_mesh(1, 1, 1);
  const TriangleMesh small = box_mesh(0.5, 0.5, 0.5);
  for (const Vec3& v : small.vertices) two.vertices.push_back(v + Vec3(2, 0, 0));
  for (auto t : small.triangles) {
    for (int& i : t) i += 8;
    two.triangles.push_back(t);
  }
  CHECK(mesh_problems(two).empty());
  CHECK(mesh_mass_properties(two, 1.0).mass == Approx(1.125).epsilon(1e-12));
  // The small one wound inward: only the total volume's sign was checked, so it passed and
  // weighed 0.875 for 1.125. Its shell is named by its first triangle, 12.
  TriangleMesh inward = two;
  for (std::size_t t = 12; t < inward.triangles.size(); ++t)
    std::swap(inward.triangles[t][1], inward.triangles[t][2]);
  CHECK(mesh_problems(inward) ==
        std::vector<std::string>{"the shell of triangle 12 (12 triangles) encloses a volume that "
                                 "is not positive (-0.125 m^3): it is wound inward"});
  CHECK_THROWS_WITH(mesh_mass_properties(inward, 1.0),
                    Catch::StartsWith("mesh: the shell of triangle 12 "));
}

TEST_CASE("coordinates too large to integrate are named as such, not as degenerate triangles",
          "[geometry][mesh][bad-input]") {
  // A 1e200 m cube: its areas overflow, which read as "triangle 0 ... has no area".
  const std::vector<std::string> problems = mesh_problems(box_mesh(1e200, 1e200, 1e200));
  CHECK(mentions(problems,
                 "vertex 1 has a coordinate of magnitude 1e+200 m, more than 1e+06 m: "
                 "coordinates too large"));
  CHECK_FALSE(mentions(problems, "no area"));
  CHECK(mentions(problems, "... and 4 more"));  // 7 of the 8 vertices
  TriangleMesh far = box_mesh(1, 1, 1);
  far.vertices[6].z() = -2e6;
  CHECK(mesh_problems(far) ==
        std::vector<std::string>{"vertex 6 has a coordinate of magnitude 2e+06 m, more than "
                                 "1e+06 m: coordinates too large for the mesh's areas, volume "
                                 "and inertia (is the mesh in metres?)"});
  // At the bound the mass properties are finite, even at a dense material's density.
  const MassProperties<> p = mesh_mass_properties(box_mesh(1e6, 1e6, 1e6), 2e4);
  CHECK(p.mass == Approx(2e22));
  CHECK(p.inertia.allFinite());
}

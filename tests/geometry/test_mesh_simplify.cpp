// SPDX-License-Identifier: BSD-3-Clause
// simplify_mesh (geometry/mesh_simplify.hpp): fine meshes of a sphere, a cylinder and a torus
// simplified stay closed, keep their genus, volume and shape; and the OBJ writer
// (io/mesh_write.hpp) reads back what it wrote.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <catch2/catch.hpp>

#include <topograsp/geometry/mesh.hpp>
#include <topograsp/geometry/mesh_simplify.hpp>
#include <topograsp/io/mesh_file.hpp>
#include <topograsp/io/mesh_write.hpp>

#include "support/meshes.hpp"

using namespace topograsp;

namespace {

// The unit icosahedron subdivided `levels` times, every new vertex pushed onto the sphere of
// `radius`: 20 * 4^levels triangles, wound outward.
TriangleMesh simplify_test_icosphere(double radius, int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh m;
  for (const auto& v : {Vec3(-1, g, 0), Vec3(1, g, 0), Vec3(-1, -g, 0), Vec3(1, -g, 0),
                        Vec3(0, -1, g), Vec3(0, 1, g), Vec3(0, -1, -g), Vec3(0, 1, -g),
                        Vec3(g, 0, -1), Vec3(g, 0, 1), Vec3(-g, 0, -1), Vec3(-g, 0, 1)})
    m.vertices.push_back(radius * v.normalized());
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = middle.try_emplace(key, static_cast<int>(m.vertices.size()));
      if (added)
        m.vertices.push_back(radius * (m.vertices[static_cast<std::size_t>(a)] +
                                       m.vertices[static_cast<std::size_t>(b)])
                                          .normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& t : m.triangles) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = std::move(finer);
  }
  return m;
}

// The torus about the z axis of tube centre radius R and tube radius r, a u x v grid of quads
// (u around the axis, v around the tube) split into triangles, wound outward.
TriangleMesh simplify_test_torus(double R, double r, int u, int v) {
  TriangleMesh m;
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < v; ++j) {
      const double a = two_pi * i / u, b = two_pi * j / v;
      m.vertices.emplace_back((R + r * std::cos(b)) * std::cos(a),
                              (R + r * std::cos(b)) * std::sin(a), r * std::sin(b));
    }
  const auto at = [&](int i, int j) { return (i % u) * v + j % v; };
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < v; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

double simplify_test_volume(const TriangleMesh& m) { return mesh_mass_properties(m, 1.0).mass; }

// V - E + F.
long simplify_test_euler(const TriangleMesh& m) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : m.triangles)
    for (std::size_t k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  return static_cast<long>(m.vertices.size()) - static_cast<long>(edges.size()) +
         static_cast<long>(m.triangles.size());
}

// Whether every vertex of m is used by a triangle.
bool simplify_test_compact(const TriangleMesh& m) {
  std::vector<bool> used(m.vertices.size(), false);
  for (const auto& t : m.triangles)
    for (const int i : t) used[static_cast<std::size_t>(i)] = true;
  return std::all_of(used.begin(), used.end(), [](bool b) { return b; });
}

}  // namespace

TEST_CASE("a fine sphere simplified tenfold stays closed and close to the sphere",
          "[geometry][mesh][simplify]") {
  const TriangleMesh sphere = simplify_test_icosphere(1.0, 4);
  REQUIRE(sphere.triangles.size() == 5120);
  REQUIRE(mesh_problems(sphere).empty());
  const TriangleMesh s = simplify_mesh(sphere, {.triangles = 500});
  CHECK(mesh_problems(s).empty());
  CHECK(s.triangles.size() <= 500);
  CHECK(s.triangles.size() >= 490);
  CHECK(simplify_test_compact(s));
  CHECK(simplify_test_euler(s) == 2);
  CHECK(simplify_test_volume(s) == Approx(simplify_test_volume(sphere)).epsilon(0.02));
  // Every vertex of the fine sphere lies near the simplified surface (its triangles' edges are
  // about 0.25 long: their sagitta is about 0.008).
  CHECK(max_distance_to_mesh(sphere.vertices, s) < 0.02);
  // The result is a function of the input.
  const TriangleMesh again = simplify_mesh(sphere, {.triangles = 500});
  CHECK(again.triangles == s.triangles);
  CHECK(again.vertices == s.vertices);
}

TEST_CASE("a 128-gon cylinder simplified keeps its caps flat and its volume",
          "[geometry][mesh][simplify]") {
  const double r = 0.05, h = 0.1;
  const TriangleMesh cylinder = topograsp::test::cylinder_mesh(r, h, 128);
  REQUIRE(mesh_problems(cylinder).empty());
  const TriangleMesh s = simplify_mesh(cylinder, {.triangles = 100});
  CHECK(mesh_problems(s).empty());
  CHECK(s.triangles.size() <= 100);
  CHECK(simplify_test_euler(s) == 2);
  // Every vertex stays in the plane of one of the caps.
  double off_cap = 0.0;
  for (const Vec3& v : s.vertices)
    off_cap = std::max(off_cap, std::min(std::abs(v.z()), std::abs(v.z() - h)));
  CHECK(off_cap < 1e-12);
  CHECK(simplify_test_volume(s) == Approx(simplify_test_volume(cylinder)).epsilon(0.03));
  CHECK(max_distance_to_mesh(cylinder.vertices, s) < 0.05 * r);
}

TEST_CASE("a box asked for fewer triangles than it can lose stays a closed box",
          "[geometry][mesh][simplify]") {
  const TriangleMesh box = topograsp::test::box_mesh(0.1, 0.2, 0.3);
  const TriangleMesh s = simplify_mesh(box, {.triangles = 8});
  CHECK(mesh_problems(s).empty());
  CHECK(s.triangles.size() >= 4);
  CHECK(s.triangles.size() <= 12);
  // A mesh already at or below the target comes back as it was.
  const TriangleMesh same = simplify_mesh(box, {.triangles = 12});
  CHECK(same.triangles == box.triangles);
  CHECK(same.vertices == box.vertices);
}

TEST_CASE("a torus simplified keeps its genus", "[geometry][mesh][simplify]") {
  const TriangleMesh torus = simplify_test_torus(0.1, 0.04, 64, 32);
  REQUIRE(mesh_problems(torus).empty());
  REQUIRE(simplify_test_euler(torus) == 0);
  const TriangleMesh s = simplify_mesh(torus, {.triangles = 200});
  CHECK(mesh_problems(s).empty());
  CHECK(s.triangles.size() <= 200);
  CHECK(simplify_test_compact(s));
  CHECK(simplify_test_euler(s) == 0);
  CHECK(simplify_test_volume(s) == Approx(simplify_test_volume(torus)).epsilon(0.05));
}

TEST_CASE("triangles that welding collapsed are dropped before simplifying",
          "[geometry][mesh][simplify]") {
  TriangleMesh box = topograsp::test::box_mesh(1, 1, 1);
  // What welding two coincident vertices of a zero-width fold leaves: triangles that repeat a
  // vertex, and two triangles on the same three vertices wound opposite ways.
  box.triangles.push_back({0, 0, 3});
  box.triangles.push_back({5, 6, 5});
  box.triangles.push_back({1, 6, 4});
  box.triangles.push_back({6, 1, 4});
  CHECK_FALSE(mesh_problems(box).empty());
  const TriangleMesh cleaned = drop_collapsed_triangles(box);
  CHECK(cleaned.triangles.size() == 12);
  CHECK(mesh_problems(cleaned).empty());
  const TriangleMesh s = simplify_mesh(box, {.triangles = 12});
  CHECK(mesh_problems(s).empty());
  CHECK(s.triangles.size() == 12);
  // Triangles on the same vertices wound the same way are not welding's: they stay (and are a
  // problem).
  TriangleMesh twice = topograsp::test::box_mesh(1, 1, 1);
  twice.triangles.push_back({1, 6, 4});
  twice.triangles.push_back({6, 4, 1});
  CHECK(drop_collapsed_triangles(twice).triangles.size() == 14);
  CHECK_THROWS_WITH(simplify_mesh(twice), Catch::StartsWith("mesh: "));
}

TEST_CASE("simplify_mesh refuses bad input naming the argument",
          "[geometry][mesh][simplify][bad-input]") {
  const TriangleMesh box = topograsp::test::box_mesh(1, 1, 1);
  TriangleMesh open = box;
  open.triangles.pop_back();
  CHECK_THROWS_AS(simplify_mesh(open), topograsp::invalid_argument);
  CHECK_THROWS_WITH(simplify_mesh(open), Catch::StartsWith("mesh: ") && Catch::Contains("open"));
  CHECK_THROWS_WITH(simplify_mesh(box, {.triangles = 3}), Catch::StartsWith("options.triangles: "));
  CHECK_THROWS_WITH(simplify_mesh(box, {.triangles = 100, .max_normal_turn = 0.0}),
                    Catch::StartsWith("options.max_normal_turn: "));
  CHECK_THROWS_WITH(max_distance_to_mesh(box.vertices, TriangleMesh{}),
                    Catch::StartsWith("mesh: "));
}

TEST_CASE("write_obj writes comments, vertices to 1e-9 and 1-based faces that read back",
          "[io][mesh][obj]") {
  TriangleMesh m = simplify_test_icosphere(0.0987654321, 1);
  for (Vec3& v : m.vertices) v += Vec3(0.123456789123, -0.5, 0.000123456789);
  std::ostringstream out;
  write_obj(out, m, "YCB object test\nsecond line");
  const std::string text = out.str();
  CHECK(text.starts_with("# YCB object test\n# second line\nv "));
  CHECK(text.find("\nf 1 ") != std::string::npos);  // 1-based
  const TriangleMesh back = parse_mesh(text, MeshFormat::obj);
  REQUIRE(back.vertices.size() == m.vertices.size());
  CHECK(back.triangles == m.triangles);
  double worst = 0.0;
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    worst = std::max(worst, (back.vertices[i] - m.vertices[i]).cwiseAbs().maxCoeff());
  CHECK(worst < 1e-9);
  std::ostringstream bare;
  write_obj(bare, topograsp::test::box_mesh(1, 2, 3), "");
  CHECK(bare.str().starts_with("v 0 0 0\n"));
}

TEST_CASE("write_obj_file writes a file atomically that read_mesh_file reads back",
          "[io][mesh][obj]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "topograsp_test_mesh_write";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "sphere.obj").string();
  const TriangleMesh sphere = simplify_mesh(simplify_test_icosphere(0.05, 3), {.triangles = 200});
  write_obj_file(path, sphere, "a simplified sphere");
  write_obj_file(path, sphere, "a simplified sphere, written over");  // replaces the file
  const TriangleMesh back = read_mesh_file(path);
  CHECK(mesh_problems(back).empty());
  CHECK(back.triangles == sphere.triangles);
  REQUIRE(back.vertices.size() == sphere.vertices.size());
  for (std::size_t i = 0; i < back.vertices.size(); ++i)
    CHECK((back.vertices[i] - sphere.vertices[i]).norm() < 1e-9);
  // Nothing but the file is left in the folder: no temporary file.
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  const std::string missing = (dir / "no_such_folder" / "x.obj").string();
  CHECK_THROWS_AS(write_obj_file(missing, sphere, ""), std::runtime_error);
  CHECK_THROWS_WITH(write_obj_file(missing, sphere, ""), Catch::Contains(missing));
  fs::remove_all(dir);
}

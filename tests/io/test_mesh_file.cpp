// SPDX-License-Identifier: BSD-3-Clause
// read_mesh_file / parse_mesh (io/mesh_file.hpp): OBJ and STL (binary, ASCII) of the same box read
// to the same closed mesh, and each malformed input refused with the file, the line and the
// problem.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include <topograsp/io/mesh_file.hpp>

using namespace topograsp;

namespace {

// The unit cube's 8 corners and 6 faces (counter-clockwise from outside), 1-based as in OBJ.
const int corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const int quads[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                         {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};

std::string cube_obj() {
  std::string s = "# a cube\no cube\n";
  for (const auto& c : corners)
    s += "v " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) +
         "\n";
  s += "vn 0 0 1\n";
  for (const auto& q : quads)
    s += "f " + std::to_string(q[0]) + "//1 " + std::to_string(q[1]) + "//1 " +
         std::to_string(q[2]) + "//1 " + std::to_string(q[3]) + "//1\n";
  return s;
}

// The cube's 12 triangles, each as three corners.
std::vector<std::array<int, 3>> cube_triangles() {
  std::vector<std::array<int, 3>> t;
  for (const auto& q : quads) {
    t.push_back({q[0] - 1, q[1] - 1, q[2] - 1});
    t.push_back({q[0] - 1, q[2] - 1, q[3] - 1});
  }
  return t;
}

std::string cube_ascii_stl() {
  std::string s = "solid cube\n";
  for (const auto& t : cube_triangles()) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (const int i : t)
      s += "      vertex " + std::to_string(corners[i][0]) + " " + std::to_string(corners[i][1]) +
           " " + std::to_string(corners[i][2]) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid cube\n";
}

std::string cube_binary_stl() {
  const auto ts = cube_triangles();
  std::string s(80, ' ');
  const auto n = static_cast<std::uint32_t>(ts.size());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : ts) {
    float f[12] = {};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) f[3 + 3 * k + a] = static_cast<float>(corners[t[k]][a]);
    s.append(reinterpret_cast<const char*>(f), sizeof f);
    s.append(2, '\0');
  }
  return s;
}

void check_cube(const TriangleMesh& m) {
  CHECK(m.vertices.size() == 8);
  CHECK(m.triangles.size() == 12);
  CHECK(mesh_problems(m).empty());
  CHECK(mesh_mass_properties(m, 1.0).mass == Approx(1.0));
}

std::string written(const std::string& name, const std::string& data) {
  const auto path = std::filesystem::temp_directory_path() / ("topograsp_mesh_" + name);
  std::ofstream(path, std::ios::binary) << data;
  return path.string();
}

}  // namespace

TEST_CASE("the same cube from OBJ, ASCII STL and binary STL", "[io][mesh]") {
  check_cube(parse_mesh(cube_obj(), MeshFormat::obj));
  check_cube(parse_mesh(cube_ascii_stl(), MeshFormat::stl));
  check_cube(parse_mesh(cube_binary_stl(), MeshFormat::stl));
  const std::string path = written("cube.STL", cube_binary_stl());
  check_cube(read_mesh_file(path));
  std::filesystem::remove(path);
  // Negative (relative) OBJ indices.
  check_cube(parse_mesh(
      [] {
        std::string s;
        for (const auto& c : corners)
          s += "v " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " +
               std::to_string(c[2]) + "\n";
        for (const auto& q : quads)
          s += "f " + std::to_string(q[0] - 9) + " " + std::to_string(q[1] - 9) + " " +
               std::to_string(q[2] - 9) + " " + std::to_string(q[3] - 9) + "\n";
        return s;
      }(),
      MeshFormat::obj));
}

TEST_CASE("malformed mesh files are refused with the file, the line and the problem",
          "[io][mesh][bad-input]") {
  CHECK_THROWS_WITH(parse_mesh("v 0 0\nf 1 2 3\n", MeshFormat::obj, "a.obj"),
                    "a.obj:1: a vertex needs three numbers (v x y z)");
  CHECK_THROWS_WITH(parse_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", MeshFormat::obj, "a.obj"),
                    "a.obj:4: vertex 4 of the face is not defined above (3 vertices so far)");
  CHECK_THROWS_WITH(parse_mesh("v 0 0 0\nv 1 0 0\nf 1 2\n", MeshFormat::obj, "a.obj"),
                    "a.obj:3: a face needs three vertices or more");
  CHECK_THROWS_WITH(parse_mesh("v 0 0 0\nf 0 1 1\n", MeshFormat::obj, "a.obj"),
                    Catch::StartsWith("a.obj:2: a face's vertex must be a non-zero integer index"));
  // A fraction or trailing letters are not an index (read as 1 before).
  for (const char* face : {"f 1.5 2 3", "f 1 2x 3", "f 1 2 3,"}) {
    INFO(face);
    CHECK_THROWS_WITH(parse_mesh(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + face + "\n",
                                 MeshFormat::obj, "a.obj"),
                      Catch::StartsWith("a.obj:4: a face's vertex must be a non-zero integer"));
  }
  // Texture and normal indices after the vertex's are allowed.
  CHECK(parse_mesh(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1/1/1 3//2 2/3 \nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
            MeshFormat::obj, "a.obj")
            .triangles.size() == 4);
  CHECK_THROWS_WITH(parse_mesh("# nothing\n", MeshFormat::obj, "a.obj"),
                    "a.obj: no faces (f) in the OBJ file");
  CHECK_THROWS_WITH(parse_mesh("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 "
                               "0\nendloop\nendfacet\nendsolid\n",
                               MeshFormat::stl, "b.stl"),
                    "b.stl:2: a facet with 2 vertices, not three");
  CHECK_THROWS_WITH(
      parse_mesh("solid x\nfacet normal 0 0 1\nvertex 0 0 q\n", MeshFormat::stl, "b.stl"),
      "b.stl:3: a vertex needs three numbers (vertex x y z)");
  CHECK_THROWS_WITH(
      parse_mesh("solid x\nfacet normal 0 0 1\nouter loop\n", MeshFormat::stl, "b.stl"),
      "b.stl:2: a facet without endfacet");
  CHECK_THROWS_WITH(parse_mesh("solid x\nendsolid\n", MeshFormat::stl, "b.stl"),
                    "b.stl: no facets in the ASCII STL file");
  std::string cut = cube_binary_stl();
  cut.pop_back();
  CHECK_THROWS_WITH(parse_mesh(cut, MeshFormat::stl, "c.stl"),
                    Catch::StartsWith("c.stl: neither binary STL"));
  CHECK_THROWS_WITH(read_mesh_file("/nonexistent/x.obj"),
                    "/nonexistent/x.obj: no such file (a regular file is expected)");
  const std::string ply = written("cube.ply", "ply\n");
  CHECK_THROWS_WITH(read_mesh_file(ply), Catch::Contains("unknown mesh format \".ply\""));
  std::filesystem::remove(ply);
  CHECK_THROWS_AS(parse_mesh("v 0 0\n", MeshFormat::obj), invalid_argument);
  // An open mesh reads (the reader reads what is written) and mesh_problems says what is wrong.
  const TriangleMesh open = parse_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::obj);
  CHECK_FALSE(mesh_problems(open).empty());
  // A vertex that is not finite is never welded to another (NaN compares equal to everything in
  // the weld's ordering): it stays, and mesh_problems names it (found by fuzz_mesh_file).
  const TriangleMesh nan = parse_mesh(
      "v 1 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 2 4 3\nf 1 3 5\nf 1 5 4\nf 3 4 5\n",
      MeshFormat::obj);
  CHECK(nan.vertices.size() == 5);
  CHECK(mesh_problems(nan).front().find("vertex 1 is not finite") != std::string::npos);
  // Coordinates whose volume or moments would overflow are a problem, not an infinite solid:
  // beyond max_mesh_coordinate (1e6 m), named before they overflow.
  const TriangleMesh huge = parse_mesh(
      "v 0 0 0\nv 1e62 0 0\nv 0 1e62 0\nv 0 0 1e62\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
      MeshFormat::obj);
  const std::vector<std::string> problems = mesh_problems(huge);
  REQUIRE(problems.size() == 3);  // vertices 1, 2 and 3
  CHECK(problems.front() ==
        "vertex 1 has a coordinate of magnitude 1e+62 m, more than 1e+06 m: coordinates too large "
        "for the mesh's areas, volume and inertia (is the mesh in metres?)");
}

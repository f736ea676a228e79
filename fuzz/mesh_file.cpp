// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: parse_mesh (io/mesh_file.hpp) on any bytes: the first byte chooses the format
// (even: OBJ, odd: STL; an empty input is an empty OBJ file), the rest is the file.
//
// - Only topograsp::mesh_error may escape parse_mesh() (its documented error); anything else
//   (std::out_of_range, std::length_error, ...) is a failure. Its what() starts with the file name
//   given and ':' ("FILE:LINE: problem" or "FILE: problem").
// - A parsed mesh has triangles, and every triangle's indices are in [0, vertices).
// - A binary STL file (84 bytes and 50 per triangle of its header's count) gives its triangles in
//   order, each corner the file's floats (welding merges identical vertices only: a NaN stays NaN
//   and no finite vertex becomes another; 0 and -0 may merge).
// - mesh_problems() (geometry/mesh.hpp) does not throw; when it finds no problem,
//   mesh_mass_properties(mesh, 1) does not throw either and gives a finite positive mass (the
//   volume), a finite centre of mass and a finite symmetric inertia.
// - Written with write_obj() (io/mesh_write.hpp, 9 significant digits) and parsed back, a mesh
//   whose coordinates are all finite and below 1e30 in magnitude has the same number of triangles
//   and, triangle by triangle, the same corners within 1e-8 relative per coordinate (the parser
//   welds vertices that the rounding made equal, so indices are not compared).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include <topograsp/geometry/mesh.hpp>
#include <topograsp/io/mesh_file.hpp>
#include <topograsp/io/mesh_write.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::MeshFormat;
using topograsp::TriangleMesh;
using topograsp::Vec3;
using topograsp::fuzz::c_literal;
using topograsp::fuzz::fuzz_fail;
using topograsp::fuzz::num;
using topograsp::fuzz::vec_str;

// Every coordinate finite and below \p bound in magnitude.
bool bounded(const TriangleMesh& m, double bound) {
  for (const Vec3& v : m.vertices)
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(v[k]) < bound)) return false;
  return true;
}

// \p b within 1e-8 of \p a, relative, coordinate by coordinate.
bool close(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(b[k] - a[k]) <= 1e-8 * std::abs(a[k]))) return false;
  return true;
}

Vec3 corner(const TriangleMesh& m, std::size_t t, std::size_t k) {
  return m.vertices[static_cast<std::size_t>(m.triangles[t][k])];
}

// What in \p m differs from the binary STL file \p text ("" if nothing, or if \p text is not
// binary STL by the reader's rule: 84 bytes and 50 per triangle of the header's count).
std::string binary_stl_difference(std::string_view text, const TriangleMesh& m) {
  if (text.size() < 84) return {};
  std::uint32_t n = 0;
  std::memcpy(&n, text.data() + 80, 4);
  if (84 + 50 * static_cast<std::uint64_t>(n) != text.size()) return {};
  if (m.triangles.size() != n)
    return std::to_string(m.triangles.size()) + " triangles from a binary STL file of " +
           std::to_string(n);
  for (std::size_t t = 0; t < n; ++t)
    for (std::size_t k = 0; k < 3; ++k) {
      float f[3];
      std::memcpy(f, text.data() + 84 + 50 * t + 12 + 12 * k, 12);
      const Vec3 file(static_cast<double>(f[0]), static_cast<double>(f[1]),
                      static_cast<double>(f[2]));
      const Vec3 c = corner(m, t, k);
      for (int j = 0; j < 3; ++j)
        if (!(file[j] == c[j] || (std::isnan(file[j]) && std::isnan(c[j]))))
          return "corner " + std::to_string(k) + " of triangle " + std::to_string(t) + " is " +
                 vec_str(c) + " but the file has " + vec_str(file);
    }
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    const MeshFormat format = size > 0 && (data[0] & 1U) != 0 ? MeshFormat::stl : MeshFormat::obj;
    const std::string file = format == MeshFormat::obj ? "fuzz.obj" : "fuzz.stl";
    const std::string_view text =
        size > 0 ? std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1)
                 : std::string_view();
    const std::string input = "format = " + file + "\ntext = " + c_literal(text);
    TriangleMesh mesh;
    try {
      mesh = topograsp::parse_mesh(text, format, file);
    } catch (const topograsp::mesh_error& e) {
      // The documented error: it must name the file first.
      if (std::string_view(e.what()).substr(0, file.size() + 1) != file + ":")
        fuzz_fail("mesh_file", "the mesh_error does not name the file: " + c_literal(e.what()),
                  input);
      return;
    } catch (const std::exception& e) {
      fuzz_fail("mesh_file",
                std::string("parse_mesh threw ") + typeid(e).name() +
                    " (not topograsp::mesh_error): " + e.what(),
                input);
    }
    if (mesh.triangles.empty()) fuzz_fail("mesh_file", "parsed a mesh with no triangles", input);
    const auto n = static_cast<long long>(mesh.vertices.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (const int i : mesh.triangles[t])
        if (i < 0 || i >= n)
          fuzz_fail("mesh_file",
                    "triangle " + std::to_string(t) + " has index " + std::to_string(i) +
                        " outside [0, " + std::to_string(n) + ")",
                    input);

    if (format == MeshFormat::stl)
      if (const std::string d = binary_stl_difference(text, mesh); !d.empty())
        fuzz_fail("mesh_file", "the mesh is not the binary STL file's: " + d, input);

    std::vector<std::string> problems;
    try {
      problems = topograsp::mesh_problems(mesh);
    } catch (const std::exception& e) {
      fuzz_fail("mesh_file",
                std::string("mesh_problems threw ") + typeid(e).name() + ": " + e.what(), input);
    }
    if (problems.empty()) {
      topograsp::MassProperties<> p;
      try {
        p = topograsp::mesh_mass_properties(mesh, 1.0);
      } catch (const std::exception& e) {
        fuzz_fail("mesh_file",
                  std::string("mesh_mass_properties threw ") + typeid(e).name() +
                      " for a mesh without problems: " + e.what(),
                  input);
      }
      const auto& I = p.inertia;
      const double scale = I.cwiseAbs().maxCoeff();
      if (!(std::isfinite(p.mass) && p.mass > 0.0) || !p.com.allFinite() || !I.allFinite() ||
          !((I - I.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale))
        fuzz_fail("mesh_file",
                  "a mesh without problems has mass properties that are not finite, positive and "
                  "symmetric: volume " +
                      num(p.mass) + ", centre " + vec_str(p.com) + ", inertia " +
                      topograsp::fuzz::mat_str(I),
                  input);
    }

    if (!bounded(mesh, 1e30)) return;
    std::ostringstream out;
    topograsp::write_obj(out, mesh, "fuzz round trip\nsecond comment line");
    const std::string written = out.str();
    TriangleMesh again;
    try {
      again = topograsp::parse_mesh(written, MeshFormat::obj, "fuzz.obj");
    } catch (const std::exception& e) {
      fuzz_fail("mesh_file", std::string("the written OBJ does not parse: ") + e.what(),
                input + "\nwritten = " + c_literal(written));
    }
    if (again.triangles.size() != mesh.triangles.size())
      fuzz_fail("mesh_file",
                "writing and parsing changed the triangle count from " +
                    std::to_string(mesh.triangles.size()) + " to " +
                    std::to_string(again.triangles.size()),
                input + "\nwritten = " + c_literal(written));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (std::size_t k = 0; k < 3; ++k)
        if (const Vec3 a = corner(mesh, t, k), b = corner(again, t, k); !close(a, b))
          fuzz_fail("mesh_file",
                    "writing and parsing moved corner " + std::to_string(k) + " of triangle " +
                        std::to_string(t) + " from " + vec_str(a) + " to " + vec_str(b),
                    input + "\nwritten = " + c_literal(written));
  });
}

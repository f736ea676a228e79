// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Triangle meshes from files: read_mesh_file() reads Wavefront OBJ and STL (binary and ASCII)
/// into a TriangleMesh with its identical vertices welded, and says what is wrong and where when a
/// file cannot be read (topograsp::mesh_error, "FILE:LINE: problem"). Whether the mesh bounds a
/// solid is mesh_problems()'s question (geometry/mesh.hpp), not the reader's.
///
/// OBJ: `v x y z` vertices, `f` faces of three or more vertices (`i`, `i/t`, `i/t/n`, `i//n`;
/// negative indices count back from the last vertex), fan-triangulated; every other statement
/// (vt, vn, o, g, s, usemtl, mtllib, comments) is skipped. STL: binary when the file's size is 84
/// bytes plus 50 per triangle of its header's count, ASCII (`solid` ... `facet` ... `outer loop`,
/// three `vertex x y z`, `endloop`, `endfacet` ... `endsolid`) otherwise.
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/mesh.hpp>

namespace topograsp {

/// The error of read_mesh_file() and parse_mesh(): what() is "FILE:LINE: problem", or "FILE:
/// problem" where no line applies (a binary file, a file that cannot be opened).
class mesh_error : public invalid_argument {
 public:
  mesh_error(const std::string& file, int line, const std::string& problem)
      : invalid_argument(detail::file_line_message(file, line, problem)) {}
};

/// The formats parse_mesh() reads.
enum class MeshFormat : std::uint8_t { obj, stl };

namespace detail {

// The numbers of `rest`, separated by blanks; false at the first that is not a number.
inline bool mesh_numbers(std::string_view rest, double* out, int n) {
  std::size_t k = 0;
  for (int i = 0; i < n; ++i) {
    while (k < rest.size() && (rest[k] == ' ' || rest[k] == '\t')) ++k;
    const auto [p, ec] = std::from_chars(rest.data() + k, rest.data() + rest.size(), out[i]);
    if (ec != std::errc()) return false;
    k = static_cast<std::size_t>(p - rest.data());
  }
  return true;
}

// `line` without leading and trailing blanks (and a carriage return).
inline std::string_view mesh_trim(std::string_view line) {
  const std::size_t s = line.find_first_not_of(" \t\r");
  if (s == std::string_view::npos) return {};
  const std::size_t e = line.find_last_not_of(" \t\r");
  return line.substr(s, e - s + 1);
}

// Calls take(line number, trimmed line) for every line of text.
template <class F>
void mesh_lines(std::string_view text, F&& take) {
  int number = 0;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    take(++number, mesh_trim(text.substr(at, end - at)));
    at = end + 1;
  }
}

// The mesh with its identical finite vertices (equal coordinates) made one, triangles renumbered.
inline TriangleMesh weld_vertices(const TriangleMesh& in) {
  TriangleMesh out;
  std::map<std::tuple<double, double, double>, int> index;
  std::vector<int> to(in.vertices.size());
  for (std::size_t i = 0; i < in.vertices.size(); ++i) {
    const Vec3& v = in.vertices[i];
    if (!v.allFinite()) {  // never welded (NaN is unordered): mesh_problems() names it
      to[i] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(v);
      continue;
    }
    const auto [it, added] =
        index.try_emplace({v.x(), v.y(), v.z()}, static_cast<int>(out.vertices.size()));
    if (added) out.vertices.push_back(v);
    to[i] = it->second;
  }
  for (const auto& t : in.triangles)
    out.triangles.push_back({to[static_cast<std::size_t>(t[0])], to[static_cast<std::size_t>(t[1])],
                             to[static_cast<std::size_t>(t[2])]});
  return out;
}

inline TriangleMesh parse_obj(std::string_view text, const std::string& file) {
  TriangleMesh m;
  mesh_lines(text, [&](int line, std::string_view s) {
    if (s.starts_with("v ") || s.starts_with("v\t")) {
      double v[3];
      if (!mesh_numbers(s.substr(2), v, 3))
        throw mesh_error(file, line, "a vertex needs three numbers (v x y z)");
      m.vertices.emplace_back(v[0], v[1], v[2]);
    } else if (s.starts_with("f ") || s.starts_with("f\t")) {
      std::vector<int> face;
      std::string_view rest = s.substr(2);
      while (!(rest = mesh_trim(rest)).empty()) {
        long long i = 0;
        const auto [p, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), i);
        // The index ends the entry or is followed by its texture and normal (1/2/3): "1.5" or
        // "1x" is not an index.
        const bool ends = p == rest.data() + rest.size() || *p == '/' || *p == ' ' || *p == '\t';
        if (ec != std::errc() || i == 0 || !ends)
          throw mesh_error(file, line,
                           "a face's vertex must be a non-zero integer index (f 1 2 3 or f "
                           "1/1/1 2/2/2 3/3/3)");
        const auto n = static_cast<long long>(m.vertices.size());
        const long long index = i < 0 ? n + i : i - 1;
        if (index < 0 || index >= n)
          throw mesh_error(file, line,
                           "vertex " + std::to_string(i) + " of the face is not defined above (" +
                               std::to_string(n) + " vertices so far)");
        face.push_back(static_cast<int>(index));
        const std::size_t next =
            rest.find_first_of(" \t", static_cast<std::size_t>(p - rest.data()));
        rest = next == std::string_view::npos ? std::string_view() : rest.substr(next);
      }
      if (face.size() < 3) throw mesh_error(file, line, "a face needs three vertices or more");
      for (std::size_t t = 2; t < face.size(); ++t)
        m.triangles.push_back({face[0], face[t - 1], face[t]});
    }
  });
  if (m.triangles.empty()) throw mesh_error(file, 0, "no faces (f) in the OBJ file");
  return weld_vertices(m);  // exporters repeat a vertex where its normal or texture changes
}

inline TriangleMesh parse_stl(std::string_view data, const std::string& file) {
  TriangleMesh m;
  if (data.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    if (84 + 50 * static_cast<std::uint64_t>(n) == data.size()) {
      for (std::uint32_t t = 0; t < n; ++t) {
        for (int k = 0; k < 3; ++k) {
          float f[3];
          std::memcpy(f, data.data() + 84 + 50 * static_cast<std::size_t>(t) + 12 + 12 * k, 12);
          m.vertices.emplace_back(f[0], f[1], f[2]);
        }
        const int first = 3 * static_cast<int>(t);
        m.triangles.push_back({first, first + 1, first + 2});
      }
      if (m.triangles.empty()) throw mesh_error(file, 0, "a binary STL file with no triangles");
      return weld_vertices(m);
    }
  }
  if (!mesh_trim(data.substr(0, std::min<std::size_t>(data.size(), 80))).starts_with("solid"))
    throw mesh_error(file, 0,
                     "neither binary STL (84 bytes and 50 per triangle) nor ASCII STL (starts "
                     "with \"solid\")");
  int in_facet = 0, facet_line = 0;  // vertices of the open facet, and where it opened
  mesh_lines(data, [&](int line, std::string_view s) {
    if (s.starts_with("facet")) {
      if (facet_line > 0) throw mesh_error(file, line, "a facet inside a facet (endfacet missing)");
      facet_line = line;
      in_facet = 0;
    } else if (s.starts_with("vertex")) {
      double v[3];
      if (facet_line == 0) throw mesh_error(file, line, "a vertex outside a facet");
      if (!mesh_numbers(s.substr(6), v, 3))
        throw mesh_error(file, line, "a vertex needs three numbers (vertex x y z)");
      if (++in_facet > 3) throw mesh_error(file, line, "a facet with more than three vertices");
      m.vertices.emplace_back(v[0], v[1], v[2]);
    } else if (s.starts_with("endfacet")) {
      if (in_facet != 3)
        throw mesh_error(file, facet_line,
                         "a facet with " + std::to_string(in_facet) + " vertices, not three");
      const int first = static_cast<int>(m.vertices.size()) - 3;
      m.triangles.push_back({first, first + 1, first + 2});
      facet_line = 0;
    }
  });
  if (facet_line > 0) throw mesh_error(file, facet_line, "a facet without endfacet");
  if (m.triangles.empty()) throw mesh_error(file, 0, "no facets in the ASCII STL file");
  return weld_vertices(m);
}

}  // namespace detail

/// The triangle mesh in \p data, a file's whole contents in \p format; \p file names it in errors.
/// \throws topograsp::mesh_error ("FILE:LINE: problem") for a malformed file.
[[nodiscard]] inline TriangleMesh parse_mesh(std::string_view data, MeshFormat format,
                                             const std::string& file = "<mesh>") {
  return format == MeshFormat::obj ? detail::parse_obj(data, file) : detail::parse_stl(data, file);
}

/// The triangle mesh of the OBJ or STL file at \p path (by its extension, in any case), its
/// identical vertices welded, in the file's units.
/// \throws topograsp::mesh_error naming the file (and the line) for a file that cannot be read,
///         an unknown extension or a malformed file.
[[nodiscard]] inline TriangleMesh read_mesh_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw mesh_error(path, 0, "no such file (a regular file is expected)");
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".obj" && ext != ".stl")
    throw mesh_error(path, 0, "unknown mesh format \"" + ext + "\" (expected .obj or .stl)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw mesh_error(path, 0, "cannot be opened");
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_mesh(data, ext == ".obj" ? MeshFormat::obj : MeshFormat::stl, path);
}

}  // namespace topograsp

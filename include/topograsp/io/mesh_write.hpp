// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Triangle meshes to Wavefront OBJ: write_obj() to a stream, write_obj_file() to a file written
/// atomically. Comment lines first (where the mesh comes from, its licence), then `v x y z` with 9
/// significant digits (a metre-sized mesh to 1e-9 m) and `f i j k` with 1-based indices. What
/// read_mesh_file() (io/mesh_file.hpp) reads back.
#pragma once

#include <charconv>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/mesh.hpp>
#include <topograsp/io/text_file.hpp>

namespace topograsp {

namespace detail {

// v with 9 significant digits, shortest form ("%.9g"), independent of the locale.
inline std::string obj_number(double v) {
  char b[32];
  const auto [end, ec] = std::to_chars(b, b + sizeof b, v, std::chars_format::general, 9);
  if (ec != std::errc()) return "nan";  // cannot happen: 32 characters hold any double at 9 digits
  return std::string(b, end);
}

}  // namespace detail

/// Writes \p mesh to \p out as OBJ: each line of \p comment as a comment ("# " and the line; none
/// for an empty comment), then the vertices (`v x y z`, 9 significant digits) and the triangles
/// (`f i j k`, indices from 1, in the mesh's winding). The mesh is written as it is, unchecked.
inline void write_obj(std::ostream& out, const TriangleMesh& mesh, std::string_view comment) {
  std::size_t at = 0;
  while (at < comment.size()) {
    std::size_t end = comment.find('\n', at);
    if (end == std::string_view::npos) end = comment.size();
    std::string_view line = comment.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    out << "# " << line << '\n';
    at = end + 1;
  }
  for (const Vec3& v : mesh.vertices)
    out << "v " << detail::obj_number(v.x()) << ' ' << detail::obj_number(v.y()) << ' '
        << detail::obj_number(v.z()) << '\n';
  for (const auto& t : mesh.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

/// Writes \p mesh as OBJ (write_obj()) to the file \p path atomically: into a temporary file in
/// the same folder, renamed onto \p path once complete (detail::write_text_file()), so readers see
/// the previous file or the new one, never a part.
/// \throws std::runtime_error naming \p path, with the system's reason, if the file cannot be
///         written; a previous file at \p path is then left as it was.
inline void write_obj_file(const std::string& path, const TriangleMesh& mesh,
                           std::string_view comment) {
  std::ostringstream text;
  write_obj(text, mesh, comment);
  try {
    detail::write_text_file(path, text.str());
  } catch (const invalid_argument& e) {  // "path: cannot write "PATH" (reason); ..."
    std::string_view what = e.what();
    if (what.starts_with("path: ")) what.remove_prefix(6);
    throw std::runtime_error("OBJ file: " + std::string(what));
  }
}

}  // namespace topograsp

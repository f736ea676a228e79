// SPDX-License-Identifier: BSD-3-Clause
// topograsp_simplify_mesh: a closed OBJ or STL mesh simplified by quadric edge collapse
// (geometry/mesh_simplify.hpp) to a target triangle count, written as OBJ (io/mesh_write.hpp) with
// comment lines saying where it comes from. Prints what the simplification cost: the triangle
// counts, the change of the enclosed volume and how far the original vertices lie from the result.
#include <charconv>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <topograsp/geometry/mesh.hpp>
#include <topograsp/geometry/mesh_simplify.hpp>
#include <topograsp/io/mesh_file.hpp>
#include <topograsp/io/mesh_write.hpp>

namespace {

constexpr const char* usage =
    "usage: topograsp_simplify_mesh IN OUT --triangles N [--comment TEXT]...\n"
    "Reads the closed mesh IN (.obj or .stl), drops the triangles that welding its coincident\n"
    "vertices collapsed (a vertex named twice; two back to back on the same vertices), simplifies\n"
    "it by quadric edge collapse to at most N triangles (fewer when no more collapses keep it\n"
    "closed, manifold, of the same genus and unfolded) and writes it to OUT as OBJ, atomically.\n"
    "  --triangles N   the triangle count to reach (N >= 4)\n"
    "  --comment TEXT  a comment line at the top of OUT (where IN comes from, its licence)\n"
    "Prints the triangle counts, the enclosed volume before and after and the largest distance\n"
    "from a vertex of IN to the surface of the result, in the file's units.\n"
    "Exit status: 0 written, 1 IN cannot be read or simplified or OUT written, 2 a wrong command\n"
    "line.\n";

int wrong(const std::string& why) {
  std::fprintf(stderr, "topograsp_simplify_mesh: %s (--help for usage)\n", why.c_str());
  return 2;
}

int failed(const std::string& why) {
  std::fprintf(stderr, "topograsp_simplify_mesh: %s\n", why.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string in, out, comment;
  int triangles = 0;
  bool has_triangles = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return 0;
    }
    if (a == "--triangles" || a == "--comment") {
      if (i + 1 >= argc) return wrong(std::string(a) + " needs a value");
      const std::string_view value = argv[++i];
      if (a == "--comment") {
        comment += comment.empty() ? "" : "\n";
        comment += value;
        continue;
      }
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), triangles);
      if (ec != std::errc() || end != value.data() + value.size() || triangles < 4)
        return wrong("--triangles: expected a whole number >= 4, got \"" + std::string(value) +
                     "\"");
      has_triangles = true;
    } else if (!a.empty() && a[0] == '-') {
      return wrong("unknown option " + std::string(a));
    } else if (in.empty()) {
      in = a;
    } else if (out.empty()) {
      out = a;
    } else {
      return wrong("more than two files (" + in + ", " + out + ", " + std::string(a) + ")");
    }
  }
  if (in.empty()) return wrong("no IN mesh");
  if (out.empty()) return wrong("no OUT file");
  if (!has_triangles) return wrong("no --triangles N");

  topograsp::TriangleMesh original, simplified;
  try {
    const topograsp::TriangleMesh read = topograsp::read_mesh_file(in);
    original = topograsp::drop_collapsed_triangles(read);
    if (original.triangles.size() != read.triangles.size())
      std::printf("%s: dropped %zu triangles that welding its vertices collapsed\n", in.c_str(),
                  read.triangles.size() - original.triangles.size());
    topograsp::require_closed_mesh(original, in);
    simplified = topograsp::simplify_mesh(original, {.triangles = triangles});
  } catch (const std::exception& e) {
    return failed(e.what());
  }
  const double before = topograsp::mesh_mass_properties(original, 1.0).mass;
  const double after = topograsp::mesh_mass_properties(simplified, 1.0).mass;
  const double deviation = topograsp::max_distance_to_mesh(original.vertices, simplified);
  std::printf("%s: %zu -> %zu triangles (%zu -> %zu vertices)\n", in.c_str(),
              original.triangles.size(), simplified.triangles.size(), original.vertices.size(),
              simplified.vertices.size());
  std::printf("volume %.6g -> %.6g (%+.3f %%)\n", before, after, 100.0 * (after / before - 1.0));
  std::printf("largest distance from a vertex of IN to the result: %.4g\n", deviation);
  try {
    topograsp::write_obj_file(out, simplified, comment);
  } catch (const std::exception& e) {
    return failed(e.what());
  }
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

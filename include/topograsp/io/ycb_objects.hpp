// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The YCB objects topograsp ships (Calli et al. 2015; scans under CC BY 4.0, simplified: NOTICE
/// and docs/objects.md): their meshes in the data directory, their published masses, what their
/// surfaces are made of; and one lookup for every object a run can name, built-in or YCB.
#pragma once

#include <array>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/grasp/mesh_object.hpp>
#include <topograsp/grasp/object.hpp>
#include <topograsp/io/mesh_file.hpp>

namespace topograsp {

/// The folder of topograsp's data (it holds objects/ycb/): the environment variable
/// TOPOGRASP_DATA_DIR when set and not empty, else the folder compiled in by CMake (the source
/// tree's data/ in a build, share/topograsp in an install), else "data".
[[nodiscard]] inline std::string data_directory() {
  if (const char* env = std::getenv("TOPOGRASP_DATA_DIR"); env != nullptr && *env != '\0')
    return env;
#ifdef TOPOGRASP_DATA_DIR
  return TOPOGRASP_DATA_DIR;
#else
  return "data";
#endif
}

/// A YCB object that topograsp ships: its name here, its YCB id (its mesh is
/// objects/ycb/<id>.obj in the data directory, metres, in the scan's frame: z up, the base near
/// z = 0), its mass as the YCB object list gives it, and the material of its surface (friction)
/// with why.
struct YcbObject {
  std::string_view name;  ///< e.g. "ycb_mustard_bottle"
  std::string_view id;    ///< e.g. "006_mustard_bottle"
  double mass = 0.0;      ///< kg (Calli et al. 2015's object list)
  Material material;      ///< its surface, for friction (the mass is given, not its density)
  std::string_view why;   ///< why that material
};

/// The shipped YCB objects: the paper's categories (a bottle, a hammer) and more. Masses: the YCB
/// object list (ycbbenchmarks.com object-list-Sheet1.pdf; Calli et al., IEEE RAM 22(3) 2015,
/// p. 43), as docs/objects.md cites them.
inline constexpr std::array<YcbObject, 9> ycb_objects{{
    {"ycb_cracker_box", "003_cracker_box", 0.411, materials::cardboard, "a carton"},
    {"ycb_sugar_box", "004_sugar_box", 0.514, materials::cardboard, "a carton"},
    {"ycb_tomato_soup_can", "005_tomato_soup_can", 0.349, materials::steel,
     "a tinplate (steel) food can"},
    {"ycb_mustard_bottle", "006_mustard_bottle", 0.603, materials::pet,
     "a plastic squeeze bottle (the table's plastic)"},
    {"ycb_banana", "011_banana", 0.066, materials::pet, "a plastic toy banana"},
    {"ycb_bleach_cleanser", "021_bleach_cleanser", 1.131, materials::pet,
     "a plastic bottle (the table's plastic)"},
    {"ycb_mug", "025_mug", 0.118, materials::pet,
     "a plastic mug (118 g: a stoneware mug of its size weighs about 300 g)"},
    {"ycb_power_drill", "035_power_drill", 0.895, materials::pet,
     "a plastic housing (the table's plastic)"},
    {"ycb_hammer", "048_hammer", 0.665, materials::steel, "a steel hammer, held by its shaft"},
}};

/// The shipped YCB object called \p name (YcbObject::name), or nothing for another name: read
/// from objects/ycb/<id>.obj under \p directory and made a mesh_object() with the object's mass
/// and material (BADGr's boxes at MeshObjectOptions' defaults).
/// \throws topograsp::mesh_error naming the file when it is missing or malformed (the message
///         says to set TOPOGRASP_DATA_DIR when missing), topograsp::invalid_argument naming
///         "mesh" when it does not bound a solid (mesh_object()).
[[nodiscard]] inline std::optional<GraspObject> ycb_object(
    std::string_view name, const std::string& directory = data_directory()) {
  for (const YcbObject& y : ycb_objects) {
    if (y.name != name) continue;
    const std::string path = directory + "/objects/ycb/" + std::string(y.id) + ".obj";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw mesh_error(path, 0,
                       "no such file: the YCB meshes are in topograsp's data/objects/ycb; set "
                       "TOPOGRASP_DATA_DIR to the folder that holds objects/ycb");
    return mesh_object(std::string(y.name), read_mesh_file(path), y.material, y.mass);
  }
  return std::nullopt;
}

namespace objects {

/// Every object a run can name: the built-in ones (names()), then the shipped YCB objects.
[[nodiscard]] inline std::vector<std::string> all_names() {
  std::vector<std::string> out = names();
  for (const YcbObject& y : ycb_objects) out.emplace_back(y.name);
  return out;
}

/// The built-in or shipped YCB object called \p name (from data_directory()), or nothing.
/// \throws as ycb_object() for a YCB object whose mesh cannot be read.
[[nodiscard]] inline std::optional<GraspObject> find_any(std::string_view name) {
  if (std::optional<GraspObject> o = find(name)) return o;
  return ycb_object(name);
}

}  // namespace objects

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// What an import of a URDF or MJCF file gives (ImportedHand, with its options and errors) and the
/// element readers both formats share: names, numbers and the boxes of collision meshes.
#pragma once

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/mesh.hpp>
#include <topograsp/io/mesh_file.hpp>
#include <topograsp/io/xml.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {

/// The robot description formats import_hand_file() reads.
enum class HandFileFormat : std::uint8_t {
  urdf,  ///< a <robot> document
  mjcf,  ///< a <mujoco> document
};

/// The format's name ("urdf", "mjcf").
[[nodiscard]] constexpr std::string_view to_string(HandFileFormat f) noexcept {
  return f == HandFileFormat::urdf ? "urdf" : "mjcf";
}

/// How a file is imported.
struct ImportOptions {
  /// The link (URDF) or body (MJCF) the model starts at, its root: the part of the file below it
  /// is imported and its own pose and joints are dropped (a hand cut off an arm). Empty: the
  /// file's one root link, or the one top-level body of the worldbody.
  std::string root;
  /// The folder mesh files are looked up in. Empty: the folder of the file (MJCF: with the
  /// compiler's meshdir).
  std::string mesh_dir;
  /// Leave out mesh geoms whose file cannot be read (each named in the notes) instead of failing.
  bool skip_missing_meshes = false;
};

/// A robot description read from a file: the links (parents before children), the collision
/// shapes and the frames (MJCF sites) of the model, in the file's names.
struct ImportedHand {
  std::string source;  ///< the file's path
  HandFileFormat format = HandFileFormat::urdf;
  std::vector<LinkSpec> links;
  std::vector<ShapeSpec> shapes;
  std::vector<FrameSpec> frames;
  /// The file's name of the joint of each link ("" for the root and unnamed fixed joints).
  std::vector<std::string> joint_names;
  /// What was approximated or left out, one sentence each.
  std::vector<std::string> notes;
  /// The index of the link whose joint the file calls \p joint, or -1.
  [[nodiscard]] int link_of_joint(std::string_view joint) const noexcept {
    for (std::size_t i = 0; i < joint_names.size(); ++i)
      if (!joint.empty() && joint_names[i] == joint) return static_cast<int>(i);
    return -1;
  }
};

/// Thrown for a file that cannot be imported. The message names the file, the line and the
/// element and says what is wrong: "hand.urdf:12: <joint name="j1">: revolute joint without
/// <limit>".
class import_error : public invalid_argument {
 public:
  using invalid_argument::invalid_argument;
};

namespace detail {

// Reads attributes, names and numbers of a file's elements; its errors name the file, the line
// and the element.
struct Importer {
  std::string file;

  [[noreturn]] void fail(const XmlElement& e, std::string_view what) const {
    std::string where = "<" + e.name;
    if (const std::string* n = e.attribute("name")) where += " name=\"" + *n + "\"";
    where += ">";
    throw import_error(file + ":" + std::to_string(e.line) + ": " + where + ": " +
                       std::string(what));
  }

  // The numbers of attribute `key` of e (whitespace separated, at least one), exactly `count` of
  // them unless count is 0 (any number); `fallback` if the attribute is absent (an error if there
  // is none and count is not 0).
  std::vector<double> numbers(const XmlElement& e, const std::map<std::string, std::string>& attrs,
                              const std::string& key, std::size_t count,
                              std::vector<double> fallback = {}) const {
    const auto it = attrs.find(key);
    if (it == attrs.end()) {
      if (fallback.empty() && count != 0) fail(e, "no " + key + "= (it is required here)");
      return fallback;
    }
    std::vector<double> out;
    const std::string& s = it->second;
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i == s.size()) break;
      std::size_t j = i;
      while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      double v = 0.0;
      const char* first = s.data() + i;
      if (*first == '+') ++first;
      const auto [end, ec] = std::from_chars(first, s.data() + j, v);
      if (ec != std::errc() || end != s.data() + j || !std::isfinite(v))
        fail(e, key + "=\"" + s + "\" is not a list of finite numbers");
      out.push_back(v);
      i = j;
    }
    if (out.empty()) fail(e, key + "=\"" + s + "\" has no numbers");
    if (count != 0 && out.size() != count)
      fail(e, key + "=\"" + s + "\" has " + std::to_string(out.size()) + " numbers, expected " +
                  std::to_string(count));
    return out;
  }
  std::vector<double> numbers(const XmlElement& e, const std::string& key, std::size_t count,
                              std::vector<double> fallback = {}) const {
    return numbers(e, attributes(e), key, count, std::move(fallback));
  }
  static std::map<std::string, std::string> attributes(const XmlElement& e) {
    std::map<std::string, std::string> out;
    for (const XmlAttribute& a : e.attributes) out[a.name] = a.value;
    return out;
  }
  std::string name_of(const XmlElement& e, std::string_view what) const {
    const std::string* n = e.attribute("name");
    if (!n || n->empty()) fail(e, std::string(what) + " without a name");
    check_name(e, *n);
    return *n;
  }
  void check_name(const XmlElement& e, const std::string& n) const {
    if (std::any_of(n.begin(), n.end(), [](char c) {
          return c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        }))
      fail(e, "the name \"" + n + "\" has a quote, a backslash or a control character");
    if (n.size() > max_name_length)
      fail(e, "the name \"" + n + "\" is longer than " + std::to_string(max_name_length) +
                  " characters (a model's limit)");
  }
};

inline Eigen::Isometry3d translation_of(const std::vector<double>& v) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Vec3(v[0], v[1], v[2]);
  return T;
}

// The STL (binary or ASCII) or OBJ mesh file at path (read_mesh_file), named by element e; no
// vertices if it cannot be read, and *why says why. A vertex that is not finite (NaN, infinite)
// fails, naming the mesh file and the vertex (its index in the mesh as read_mesh_file() gives
// it): its box or volume would be wrong.
inline TriangleMesh read_mesh(const Importer& im, const XmlElement& e, const std::string& path,
                              std::string* why = nullptr) {
  TriangleMesh m;
  try {
    m = read_mesh_file(path);
  } catch (const mesh_error& error) {
    if (why) *why = error.what();
    return {};
  }
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    if (!m.vertices[i].allFinite())
      im.fail(e, "the mesh \"" + path + "\" has a vertex that is not finite (vertex " +
                     std::to_string(i) + ", from 0, identical vertices merged)");
  return m;
}

// The volume enclosed by a closed triangle mesh scaled by `scale`, and its centroid (MuJoCo
// takes a mesh wound inward as it takes one wound outward).
inline std::pair<double, Vec3> mesh_volume(TriangleMesh m, const Vec3& scale) {
  for (Vec3& v : m.vertices) v = v.cwiseProduct(scale);
  const MeshMoments moments = mesh_moments(m);
  const double volume = std::abs(moments.volume);
  return {volume, volume > 0.0 ? Vec3(moments.first / moments.volume) : Vec3::Zero()};
}

// A box (half extents, centre) bounding the vertices scaled by `scale`.
inline std::pair<Vec3, Vec3> bounding_box(const std::vector<Vec3>& v, const Vec3& scale) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& p : v) {
    lo = lo.cwiseMin(p.cwiseProduct(scale));
    hi = hi.cwiseMax(p.cwiseProduct(scale));
  }
  return {(0.5 * (hi - lo)).cwiseMax(1e-4), 0.5 * (hi + lo)};
}

// The pose with z along a -> b, centred between them (capsules and cylinders given by fromto).
inline Eigen::Isometry3d segment_isometry(const Vec3& a, const Vec3& b) {
  const Pose p = segment_pose({a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()});
  return p.isometry();
}

inline void add_box_of_mesh(const Importer& im, const XmlElement& e, const std::string& path,
                            const Vec3& scale, const Eigen::Isometry3d& pose, const Name& link,
                            bool skip_missing, ImportedHand& out) {
  std::string why;
  const std::vector<Vec3> v = read_mesh(im, e, path, &why).vertices;
  if (v.empty()) {
    if (!skip_missing)
      im.fail(
          e,
          "cannot read the mesh \"" + path +
              "\" (STL or OBJ; give --mesh-dir, or --skip-missing-meshes to leave it out): " + why);
    out.notes.push_back("the collision mesh \"" + path + "\" of link " + std::string(link.view()) +
                        " could not be read and was left out");
    return;
  }
  const auto [half, centre] = bounding_box(v, scale);
  ShapeSpec s;
  s.link = link;
  s.type = ShapeType::box;
  s.pose = to_pose(pose * Eigen::Translation3d(centre));
  s.size = {half.x(), half.y(), half.z()};
  out.shapes.push_back(s);
  out.notes.push_back("the collision mesh \"" + std::filesystem::path(path).filename().string() +
                      "\" of link " + std::string(link.view()) +
                      " is approximated by its bounding box");
}

// The first child of e called `name`, or nullptr.
inline const XmlElement* child(const XmlElement& e, std::string_view name) {
  for (const XmlElement& c : e.children)
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace detail
}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Recorded human grasps as 21 hand keypoints (the order of MANO-based datasets: DexYCB, HO-3D,
/// OakInk, GRAB; KeypointGrasp, grasp/keypoints.hpp) in a file: the JSON format, its reader with
/// errors that name the file and the field, and its writer.
///
/// The format ("topograsp keypoint grasp 1"):
///
///     {
///       "format": "topograsp keypoint grasp 1",
///       "object": "bottle",
///       "units": "m",                      // or "mm"
///       "frame": "object",                 // or "world": then object_pose is required
///       "object_pose": {"position": [x, y, z], "quaternion": [w, x, y, z]},
///       "keypoints": [[x, y, z], ... 21 of them],
///       "source": "how the recording was made"   // optional, free text
///     }
///
/// Keypoint order: 0 wrist; 1-4 thumb CMC, MCP, IP, tip; 5-8 index MCP, PIP, DIP, tip; 9-12
/// middle; 13-16 ring; 17-20 little.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/grasp/keypoints.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp {

/// The error of parse_keypoint_grasp() and read_keypoint_grasp(): "FILE: FIELD: problem".
class keypoint_error : public invalid_argument {
 public:
  keypoint_error(const std::string& file, const std::string& field, const std::string& problem)
      : invalid_argument(file + ": " + field + ": " + problem) {}
};

namespace detail {

inline Vec3 json_vec3(const Json& j, const std::string& file, const std::string& field) {
  if (!j.is_array() || j.as_array().size() != 3)
    throw keypoint_error(file, field, "expected three numbers");
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    const Json& x = j.as_array()[static_cast<std::size_t>(k)];
    if (!x.is_number() || !std::isfinite(x.as_number()))
      throw keypoint_error(file, field, "expected three finite numbers");
    v[k] = x.as_number();
  }
  return v;
}

inline const Json& json_field(const Json& doc, std::string_view key, const std::string& file) {
  if (!doc.contains(key)) throw keypoint_error(file, std::string(key), "missing");
  return doc.at(key);
}

}  // namespace detail

/// The keypoint grasp in the JSON text \p text (the format above); \p file names it in errors.
/// \throws topograsp::keypoint_error naming the field for a malformed document (not JSON, a wrong
///         format tag, units other than m or mm, a frame other than object or world, a world frame
///         without object_pose, a quaternion of zero length, not 21 keypoints of three finite
///         numbers each, a keypoint that leaves the range of double in the object frame).
[[nodiscard]] inline KeypointGrasp parse_keypoint_grasp(std::string_view text,
                                                        const std::string& file = "<keypoints>") {
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const invalid_argument& e) {
    throw keypoint_error(file, "document", e.what());
  }
  if (!doc.is_object()) throw keypoint_error(file, "document", "expected a JSON object");
  const Json& format = detail::json_field(doc, "format", file);
  if (!format.is_string() || format.as_string() != "topograsp keypoint grasp 1")
    throw keypoint_error(file, "format", "expected \"topograsp keypoint grasp 1\"");
  // A key the format does not name is refused: a misspelt one ("unit") must not pass unseen.
  constexpr std::string_view keys[] = {"format",      "object",    "units", "frame",
                                       "object_pose", "keypoints", "source"};
  for (const auto& [key, value] : doc.as_object())
    if (std::find(std::begin(keys), std::end(keys), key) == std::end(keys))
      throw keypoint_error(file, key,
                           "not a field of the format (format, object, units, frame, "
                           "object_pose, keypoints, source)");
  if (doc.contains("source") && !doc.at("source").is_string())
    throw keypoint_error(file, "source", "expected a string");
  if (doc.contains("object_pose") && !(doc.contains("frame") && doc.at("frame").is_string() &&
                                       doc.at("frame").as_string() == "world"))
    throw keypoint_error(file, "object_pose", "given, but the frame is not \"world\"");
  KeypointGrasp g;
  const Json& object = detail::json_field(doc, "object", file);
  if (!object.is_string() || object.as_string().empty())
    throw keypoint_error(file, "object", "expected the object's name");
  g.object = object.as_string();
  double unit = 1.0;
  if (doc.contains("units")) {
    const Json& u = doc.at("units");
    if (!u.is_string() || (u.as_string() != "m" && u.as_string() != "mm"))
      throw keypoint_error(file, "units", "expected \"m\" or \"mm\"");
    unit = u.as_string() == "mm" ? 1e-3 : 1.0;
  }
  bool world = false;
  if (doc.contains("frame")) {
    const Json& f = doc.at("frame");
    if (!f.is_string() || (f.as_string() != "object" && f.as_string() != "world"))
      throw keypoint_error(file, "frame", "expected \"object\" or \"world\"");
    world = f.as_string() == "world";
  }
  Eigen::Isometry3d T_world_object = Eigen::Isometry3d::Identity();
  if (world) {
    const Json& pose = detail::json_field(doc, "object_pose", file);
    if (!pose.is_object()) throw keypoint_error(file, "object_pose", "expected an object");
    const Vec3 position = unit * detail::json_vec3(detail::json_field(pose, "position", file), file,
                                                   "object_pose.position");
    const Json& q = detail::json_field(pose, "quaternion", file);
    if (!q.is_array() || q.as_array().size() != 4)
      throw keypoint_error(file, "object_pose.quaternion", "expected four numbers [w, x, y, z]");
    double c[4];
    for (int k = 0; k < 4; ++k) {
      const Json& x = q.as_array()[static_cast<std::size_t>(k)];
      if (!x.is_number() || !std::isfinite(x.as_number()))
        throw keypoint_error(file, "object_pose.quaternion", "expected four finite numbers");
      c[k] = x.as_number();
    }
    // Scaled by its largest component first, so that huge components do not overflow the norm.
    const double largest =
        std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2]), std::abs(c[3])});
    if (largest > 0.0)
      for (double& x : c) x /= largest;
    Eigen::Quaterniond quat(c[0], c[1], c[2], c[3]);
    if (!(largest > 0.0) || !(quat.norm() * largest > 1e-9))
      throw keypoint_error(file, "object_pose.quaternion", "has zero length");
    T_world_object.linear() = quat.normalized().toRotationMatrix();
    T_world_object.translation() = position;
  }
  const Json& kps = detail::json_field(doc, "keypoints", file);
  if (!kps.is_array() || kps.as_array().size() != static_cast<std::size_t>(keypoint_count))
    throw keypoint_error(file, "keypoints",
                         "expected " + std::to_string(keypoint_count) + " keypoints");
  const Eigen::Isometry3d T_object_world = T_world_object.inverse();
  for (int i = 0; i < keypoint_count; ++i) {
    const std::string field = "keypoints[" + std::to_string(i) + "]";
    Vec3& k = g.keypoints[static_cast<std::size_t>(i)];
    k = unit * detail::json_vec3(kps.as_array()[static_cast<std::size_t>(i)], file, field);
    if (world) k = T_object_world * k;
    if (!k.allFinite())
      throw keypoint_error(file, field, "not finite in the object frame (out of range)");
  }
  return g;
}

/// The keypoint grasp in the JSON file at \p path (parse_keypoint_grasp).
/// \throws topograsp::keypoint_error naming the file (and the field).
[[nodiscard]] inline KeypointGrasp read_keypoint_grasp(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw keypoint_error(path, "file", "no such file (a regular file is expected)");
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_keypoint_grasp(text, path);
}

/// The JSON text of \p g in the format above (units m, frame object) with \p source as its
/// "source" field when not empty: what parse_keypoint_grasp() reads back (numbers to the last
/// bit).
[[nodiscard]] inline std::string keypoint_grasp_json(const KeypointGrasp& g,
                                                     std::string_view source = {}) {
  Json doc = Json::object();
  doc.set("format", "topograsp keypoint grasp 1");
  doc.set("object", g.object);
  doc.set("units", "m");
  doc.set("frame", "object");
  Json points = Json::array();
  for (const Vec3& k : g.keypoints)
    points.push_back(Json::array().push_back(k.x()).push_back(k.y()).push_back(k.z()));
  doc.set("keypoints", points);
  if (!source.empty()) doc.set("source", std::string(source));
  return doc.dump() + "\n";
}

}  // namespace topograsp

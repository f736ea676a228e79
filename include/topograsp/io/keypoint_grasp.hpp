// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Recorded human grasps as 21 hand keypoints (the order of MANO-based datasets: DexYCB, HO-3D,
/// OakInk, GRAB): the JSON format, its reader with errors that name the file and the field, and
/// the winding descriptor straight from the keypoints (the hand curves run through them).
///
/// The format ("topograsp keypoint grasp 1"):
///
///     {
///       "format": "topograsp keypoint grasp 1",
///       "object": "bottle",
///       "units": "m",                      // or "mm"
///       "frame": "object",                 // or "world": then object_pose is required
///       "object_pose": {"position": [x, y, z], "quaternion": [w, x, y, z]},
///       "keypoints": [[x, y, z], ... 21 of them]
///     }
///
/// Keypoint order: 0 wrist; 1-4 thumb CMC, MCP, IP, tip; 5-8 index MCP, PIP, DIP, tip; 9-12
/// middle; 13-16 ring; 17-20 little.
#pragma once

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
#include <topograsp/io/json.hpp>
#include <topograsp/task/winding.hpp>

namespace topograsp {

/// The number of hand keypoints of a recorded grasp.
inline constexpr int keypoint_count = 21;

/// A recorded human grasp: its object's name and the 21 keypoints in the object frame (m).
struct KeypointGrasp {
  std::string object;
  std::array<Vec3, keypoint_count> keypoints{};
};

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
///         numbers each).
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
    Eigen::Quaterniond quat(c[0], c[1], c[2], c[3]);
    if (!(quat.norm() > 1e-9))
      throw keypoint_error(file, "object_pose.quaternion", "has zero length");
    T_world_object.linear() = quat.normalized().toRotationMatrix();
    T_world_object.translation() = position;
  }
  const Json& kps = detail::json_field(doc, "keypoints", file);
  if (!kps.is_array() || kps.as_array().size() != static_cast<std::size_t>(keypoint_count))
    throw keypoint_error(file, "keypoints",
                         "expected " + std::to_string(keypoint_count) + " keypoints");
  const Eigen::Isometry3d T_object_world = T_world_object.inverse();
  for (int i = 0; i < keypoint_count; ++i)
    g.keypoints[static_cast<std::size_t>(i)] =
        T_object_world * (unit * detail::json_vec3(kps.as_array()[static_cast<std::size_t>(i)],
                                                   file, "keypoints[" + std::to_string(i) + "]"));
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

/// The hand curves through the keypoints of \p g, one per finger (index, middle, ring, little),
/// as the human model's hand curves run: thumb tip, IP, MCP, CMC, the palm centre (the centroid
/// of the wrist and the four finger MCPs), then the finger's MCP, PIP, DIP and tip.
[[nodiscard]] inline std::array<std::array<Vec3, 9>, 4> keypoint_curves(const KeypointGrasp& g) {
  const auto& k = g.keypoints;
  const Vec3 palm = (k[0] + k[5] + k[9] + k[13] + k[17]) / 5.0;
  std::array<std::array<Vec3, 9>, 4> curves;
  for (std::size_t f = 0; f < 4; ++f) {
    const std::size_t base = 5 + 4 * f;
    curves[f] = {k[4], k[3], k[2], k[1], palm, k[base], k[base + 1], k[base + 2], k[base + 3]};
  }
  return curves;
}

/// The windings (turns) of the four keypoint curves of \p g around \p p (object frame).
/// \throws topograsp::invalid_argument as winding() for a point that is not finite.
[[nodiscard]] inline Eigen::Vector4d keypoint_windings(const KeypointGrasp& g, const Vec3& p) {
  Eigen::Vector4d w;
  const auto curves = keypoint_curves(g);
  for (std::size_t f = 0; f < 4; ++f) w[static_cast<Eigen::Index>(f)] = winding(curves[f], p);
  return w;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// A hand description file: what a URDF or MJCF file cannot say of a hand (its fingers and thumb,
/// its palm centre, which way each joint closes, missing motor limits, joints to hold still,
/// extra frames, a density for links without mass), applied to an imported hand so that the tool
/// writes a complete model. docs/models.md, "A hand description file".
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>

#include <topograsp/core/number_text.hpp>
#include <topograsp/core/pose.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/io/hand_import/common.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/io/json_position.hpp>
#include <topograsp/model/name.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {

/// A chain of a hand: its name and its points, link or frame names from the palm out.
struct HandChain {
  std::string name;
  std::vector<std::string> points;
};

/// The hand that a description makes of an imported file (describe_hand()): the model's name,
/// its palm centre frame, its fingers and its thumb.
struct HandDescription {
  std::string source;  ///< the description file's path
  std::string name;
  std::string palm_centre;
  std::vector<HandChain> fingers;
  HandChain thumb;
};

namespace detail {

class Describer {
 public:
  Describer(ImportedHand& hand, std::string source, std::string_view text)
      : h_(hand), source_(std::move(source)), text_(text) {}

  HandDescription apply(const Json& doc) {
    if (!doc.is_object()) fail("", "expected a JSON object: {\"name\": ..., \"palm_centre\": ...}");
    known_keys(doc, "",
               {"name", "palm_centre", "fingers", "thumb", "joints", "frames", "defaults"});
    HandDescription d;
    d.source = source_;
    d.name = string_at(doc, "name", "");
    if (d.name.size() > max_name_length)
      fail("name", "longer than " + std::to_string(max_name_length) + " characters");
    if (doc.contains("frames")) frames(doc.at("frames"));
    if (doc.contains("joints")) joints(doc.at("joints"));
    if (doc.contains("defaults")) defaults(doc.at("defaults"));
    d.palm_centre = string_at(doc, "palm_centre", "");
    if (frame_index(d.palm_centre) < 0 && link_index(d.palm_centre) < 0)
      fail("palm_centre",
           "\"" + d.palm_centre + "\" is no link or frame of " + file() +
               " (add it under \"frames\": {\"name\": \"" + d.palm_centre +
               "\", \"link\": ..., \"position\": [x, y, z]}; frames: " + frame_list() + ")");
    if (!doc.contains("fingers") || !doc.at("fingers").is_array() ||
        doc.at("fingers").as_array().empty())
      fail("fingers",
           "expected a list of at least one finger: [{\"name\": \"index\", "
           "\"points\": [link or frame names from the palm out]}]");
    const auto& fingers = doc.at("fingers").as_array();
    for (std::size_t i = 0; i < fingers.size(); ++i)
      d.fingers.push_back(chain(fingers[i], "fingers[" + std::to_string(i) + "]"));
    if (!doc.contains("thumb"))
      fail("thumb",
           "missing: a hand needs a thumb, the chain that opposes the fingers "
           "(\"thumb\": {\"name\": \"thumb\", \"points\": [...]})");
    d.thumb = chain(doc.at("thumb"), "thumb");
    return d;
  }

 private:
  ImportedHand& h_;
  std::string source_;
  std::string_view text_;  // the description's text, for the line of a field; may be empty

  [[nodiscard]] std::string file() const {
    return std::filesystem::path(h_.source).filename().string();
  }

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    const std::string line =
        text_.empty() ? "" : ":" + std::to_string(json_field_line(text_, field));
    throw import_error(source_ + line + ": " + (field.empty() ? "" : field + ": ") + what);
  }

  void known_keys(const Json& o, const std::string& field,
                  std::initializer_list<std::string_view> keys) const {
    for (const auto& [k, v] : o.as_object()) {
      (void)v;
      if (std::find(keys.begin(), keys.end(), k) != keys.end()) continue;
      std::string list;
      for (std::string_view n : keys) list += (list.empty() ? "" : ", ") + std::string(n);
      fail(field.empty() ? k : field + "." + k, "unknown key (known: " + list + ")");
    }
  }

  [[nodiscard]] std::string string_at(const Json& o, const std::string& key,
                                      const std::string& field) const {
    const std::string f = field.empty() ? key : field + "." + key;
    if (!o.contains(key)) fail(f, "missing");
    if (!o.at(key).is_string() || o.at(key).as_string().empty())
      fail(f, "expected a non-empty string");
    return o.at(key).as_string();
  }

  [[nodiscard]] double number_at(const Json& o, const std::string& key, const std::string& field,
                                 double lo, double hi) const {
    const std::string f = field + "." + key;
    const Json& v = o.at(key);
    if (!v.is_number() || !std::isfinite(v.as_number()) || v.as_number() < lo || v.as_number() > hi)
      fail(f,
           "expected a number from " + detail::number_text(lo) + " to " + detail::number_text(hi));
    return v.as_number();
  }

  [[nodiscard]] int link_index(std::string_view name) const {
    for (std::size_t i = 0; i < h_.links.size(); ++i)
      if (h_.links[i].name.view() == name) return static_cast<int>(i);
    return -1;
  }
  [[nodiscard]] int frame_index(std::string_view name) const {
    for (std::size_t i = 0; i < h_.frames.size(); ++i)
      if (h_.frames[i].name.view() == name) return static_cast<int>(i);
    return -1;
  }
  [[nodiscard]] std::string link_list() const {
    std::string s;
    for (const LinkSpec& l : h_.links) s += (s.empty() ? "" : ", ") + std::string(l.name.view());
    return s;
  }
  [[nodiscard]] std::string frame_list() const {
    std::string s;
    for (const FrameSpec& f : h_.frames) s += (s.empty() ? "" : ", ") + std::string(f.name.view());
    return s.empty() ? "none" : s;
  }

  // The link of the joint called `name` (the file's joint name, or the link's), or a failure.
  [[nodiscard]] int joint_link(const std::string& name, const std::string& field) const {
    int i = h_.link_of_joint(name);
    if (i < 0) i = link_index(name);
    if (i < 0)
      fail(field,
           "no joint or link \"" + name + "\" in " + file() + " (links: " + link_list() + ")");
    return i;
  }

  void frames(const Json& list) {
    if (!list.is_array())
      fail("frames", "expected a list: [{\"name\": ..., \"link\": ..., \"position\": [x, y, z]}]");
    for (std::size_t i = 0; i < list.as_array().size(); ++i) {
      const Json& f = list.as_array()[i];
      const std::string field = "frames[" + std::to_string(i) + "]";
      if (!f.is_object()) fail(field, "expected an object");
      known_keys(f, field, {"name", "link", "position", "rpy", "quaternion", "xyaxes"});
      const std::string name = string_at(f, "name", field);
      const std::string link = string_at(f, "link", field);
      if (name.size() > max_name_length)
        fail(field + ".name", "longer than " + std::to_string(max_name_length) + " characters");
      if (frame_index(name) >= 0 || link_index(name) >= 0)
        fail(field + ".name", "\"" + name + "\" is already a frame or link of " + file());
      if (link_index(link) < 0)
        fail(field + ".link",
             "no link \"" + link + "\" in " + file() + " (links: " + link_list() + ")");
      Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
      if (f.contains("position")) T.translation() = vector_at<3>(f, "position", field);
      if (int(f.contains("rpy")) + int(f.contains("quaternion")) + int(f.contains("xyaxes")) > 1)
        fail(field, "give the rotation one way: \"rpy\", \"quaternion\" or \"xyaxes\"");
      if (f.contains("rpy")) {
        const Vec3 a = vector_at<3>(f, "rpy", field);
        T.linear() =
            (Eigen::AngleAxisd(a[2], Vec3::UnitZ()) * Eigen::AngleAxisd(a[1], Vec3::UnitY()) *
             Eigen::AngleAxisd(a[0], Vec3::UnitX()))
                .toRotationMatrix();
      }
      if (f.contains("quaternion")) {
        const Eigen::Vector4d q = vector_at<4>(f, "quaternion", field);
        if (q.norm() < 1e-9)
          fail(field + ".quaternion", "expected a non-zero quaternion (w, x, y, z)");
        T.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
      }
      if (f.contains("xyaxes")) {  // MJCF's: the frame's x axis, then its y axis (made square)
        const Eigen::Matrix<double, 6, 1> a = vector_at<6>(f, "xyaxes", field);
        const Vec3 x = a.head<3>();
        const Vec3 y = a.tail<3>() - a.tail<3>().dot(x) / x.squaredNorm() * x;
        if (x.norm() < 1e-9 || y.norm() < 1e-9 * a.tail<3>().norm() || a.tail<3>().norm() < 1e-9)
          fail(field + ".xyaxes", "expected two axes that are not zero nor parallel");
        T.linear().col(0) = x.normalized();
        T.linear().col(1) = y.normalized();
        T.linear().col(2) = x.normalized().cross(y.normalized());
      }
      h_.frames.push_back(frame(Name(name), Name(link), to_pose(T)));
    }
  }

  template <int N>
  [[nodiscard]] Eigen::Matrix<double, N, 1> vector_at(const Json& o, const std::string& key,
                                                      const std::string& field) const {
    const Json& v = o.at(key);
    Eigen::Matrix<double, N, 1> out;
    if (!v.is_array() || v.as_array().size() != static_cast<std::size_t>(N))
      fail(field + "." + key, "expected " + std::to_string(N) + " numbers");
    for (int i = 0; i < N; ++i) {
      const Json& x = v.as_array()[static_cast<std::size_t>(i)];
      if (!x.is_number() || !std::isfinite(x.as_number()))
        fail(field + "." + key, "expected " + std::to_string(N) + " finite numbers");
      out[i] = x.as_number();
    }
    return out;
  }

  void joints(const Json& map) {
    if (!map.is_object())
      fail("joints", "expected an object: {\"joint name\": {\"closes\": 1, \"effort\": N m, ...}}");
    for (const auto& [name, j] : map.as_object()) {
      const std::string field = "joints." + name;
      if (!j.is_object()) fail(field, "expected an object");
      known_keys(j, field, {"closes", "effort", "velocity", "hold"});
      const int i = joint_link(name, field);
      LinkSpec& l = h_.links[static_cast<std::size_t>(i)];
      if (l.type == JointType::fixed)
        fail(field, "\"" + name + "\" is a fixed joint in " + file() +
                        ": only a moving joint closes, has a motor or is held");
      if (j.contains("hold")) {
        if (j.contains("closes") || j.contains("effort") || j.contains("velocity"))
          fail(field, "a held joint does not close and has no motor: give \"hold\" alone");
        hold(i, number_at(j, "hold", field, l.lower, l.upper), field);
        continue;
      }
      if (j.contains("closes")) {
        const double c = number_at(j, "closes", field, -1.0, 1.0);
        if (c != -1.0 && c != 0.0 && c != 1.0)
          fail(field + ".closes", "expected 1 (increasing closes), -1 (decreasing closes) or 0");
        l.closing = c;
      }
      if (j.contains("effort")) l.effort = number_at(j, "effort", field, 0.0, 1e6);
      if (j.contains("velocity")) l.velocity = number_at(j, "velocity", field, 0.0, 1e6);
    }
  }

  // Joint i held at value: a fixed joint whose origin is the joint's frame moved by the value, so
  // that the hand's fingers do not drive it (a wrist roll, a palm slide).
  void hold(int i, double value, const std::string& field) {
    LinkSpec& l = h_.links[static_cast<std::size_t>(i)];
    for (const LinkSpec& other : h_.links)
      if (other.mimic == l.name)
        fail(field + ".hold", "the joint \"" + std::string(other.name.view()) +
                                  "\" follows it (a mimic joint): hold that one too, or neither");
    const Vec3 axis(l.axis[0], l.axis[1], l.axis[2]);
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    if (l.type == JointType::revolute)
      motion.linear() = Eigen::AngleAxisd(value, axis.normalized()).toRotationMatrix();
    else
      motion.translation() = value * axis;
    l.origin = to_pose(l.origin.isometry() * motion);
    l.type = JointType::fixed;
    l.axis = {0.0, 0.0, 0.0};
    l.lower = l.upper = 0.0;
    l.mimic = Name();
    l.multiplier = 1.0;
    l.offset = 0.0;
    l.closing = 0.0;
    l.effort = l.velocity = l.armature = 0.0;
    h_.notes.push_back("the joint " + std::string(l.name.view()) + " is held at " +
                       detail::number_text(value) + " by the description (" +
                       std::filesystem::path(source_).filename().string() + ")");
  }

  void defaults(const Json& d) {
    if (!d.is_object())
      fail("defaults",
           "expected an object: {\"velocity\": rad/s, \"effort\": N m, "
           "\"density\": kg/m^3}");
    known_keys(d, "defaults", {"velocity", "effort", "density"});
    const auto moving = [](const LinkSpec& l) {
      return l.type != JointType::fixed && l.mimic.empty();
    };
    if (d.contains("velocity")) {
      const double v = number_at(d, "velocity", "defaults", 0.0, 1e6);
      for (LinkSpec& l : h_.links)
        if (moving(l) && l.velocity == 0.0) l.velocity = v;
    }
    if (d.contains("effort")) {
      const double e = number_at(d, "effort", "defaults", 0.0, 1e6);
      for (LinkSpec& l : h_.links)
        if (moving(l) && l.effort == 0.0) l.effort = e;
    }
    if (d.contains("density")) {
      const double rho = number_at(d, "density", "defaults", 1.0, 1e5);
      for (LinkSpec& l : h_.links) {
        if (l.mass != 0.0) continue;
        double mass = 0.0;
        Vec3 moment = Vec3::Zero();
        for (const ShapeSpec& s : h_.shapes) {
          if (s.link != l.name) continue;
          const MassProperties<> m = shape_mass_properties(s, rho);
          mass += m.mass;
          moment += m.mass * m.com;
        }
        if (mass <= 0.0) continue;
        const Vec3 c = moment / mass;
        l.mass = mass;
        l.com = {c.x(), c.y(), c.z()};
        h_.notes.push_back("the link " + std::string(l.name.view()) + " has no mass in " + file() +
                           ": " + detail::number_text(mass) + " kg from its collision shapes at " +
                           detail::number_text(rho) + " kg/m^3 (defaults.density)");
      }
    }
  }

  HandChain chain(const Json& c, const std::string& field) const {
    if (!c.is_object()) fail(field, "expected {\"name\": ..., \"points\": [...]}");
    known_keys(c, field, {"name", "points"});
    HandChain out;
    out.name = string_at(c, "name", field);
    if (!c.contains("points") || !c.at("points").is_array() ||
        c.at("points").as_array().size() < 2 ||
        c.at("points").as_array().size() > max_finger_points)
      fail(field + ".points", "expected 2 to " + std::to_string(max_finger_points) +
                                  " link or frame names, from the palm out");
    if (out.name.size() > max_name_length)
      fail(field + ".name", "longer than " + std::to_string(max_name_length) + " characters");
    const auto& points = c.at("points").as_array();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::string f = field + ".points[" + std::to_string(i) + "]";
      if (!points[i].is_string()) fail(f, "expected a link or frame name");
      const std::string& p = points[i].as_string();
      if (link_index(p) < 0 && frame_index(p) < 0)
        fail(f, "\"" + p + "\" is no link or frame of " + file() + " (links: " + link_list() +
                    "; frames: " + frame_list() + ")");
      out.points.push_back(p);
    }
    return out;
  }
};

}  // namespace detail

/// Applies the hand description \p doc (read from \p source) to the imported hand \p hand: its
/// "frames" are added, its "joints" given their closing direction, motor limits, or held still
/// (turned into fixed joints at the value, with a note), its "defaults" fill motor limits the file
/// lacks and give links without mass one from their collision shapes at a density (with a note),
/// and the fingers, thumb and palm centre it names are checked against the hand's links and
/// frames. Returns what the tool writes as the model (model_header()).
/// \throws topograsp::import_error naming the description file, with \p text (the file's text)
/// the line ("hand.json:7: ", json_field_line()), the field ("fingers[1].points[2]",
/// "joints.wrist.hold") and what to write instead, for an unknown key, a name that is no link,
/// joint or frame of the hand file (the message lists those it has), a missing thumb, fingers or
/// palm centre, a closing direction or motor on a fixed joint, a held value outside the joint's
/// limits, or a number out of range.
[[nodiscard]] inline HandDescription describe_hand(ImportedHand& hand, const Json& doc,
                                                   const std::string& source,
                                                   std::string_view text = {}) {
  return detail::Describer(hand, source, text).apply(doc);
}

/// Reads the hand description file at \p path (JSON) and applies it to \p hand (describe_hand()).
/// \throws topograsp::import_error naming \p path for a file that cannot be read or is not JSON,
/// and as describe_hand() does, with the line of the field.
[[nodiscard]] inline HandDescription describe_hand_file(ImportedHand& hand,
                                                        const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw import_error(path + ": cannot be opened");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const invalid_argument& e) {
    throw import_error(path + ": not JSON: " + e.what());
  }
  return describe_hand(hand, doc, path, text);
}

}  // namespace topograsp

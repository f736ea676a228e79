// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Hands from URDF and MJCF files: import_hand_file() reads a robot description into the pieces a
/// model is written from (links with their joints, collision shapes, frames; model/spec.hpp) and
/// model_header() writes them as a C++ header of constexpr arrays, which make_model() then checks
/// and resolves while the user's code compiles, like a hand written out by hand. The tool
/// topograsp_import_hand and the CMake function topograsp_import_hand() run this at build time
/// (docs/models.md, "Bring your own hand").
///
/// What a file cannot say (which chains are the thumb and the fingers, where the palm centre and
/// the fingertips are, which way each joint closes) the user adds in a few lines of C++ that name
/// the file's links (docs/models.md).
///
/// Supported: URDF links, revolute / continuous / prismatic / fixed joints with origins, axes,
/// limits (effort is the torque limit, velocity the speed limit), <mimic>, inertial mass and
/// centre, collision box / cylinder / sphere / mesh. MJCF (MuJoCo 2.x): nested bodies with pos and
/// any orientation (quat, axisangle, euler with the compiler's eulerseq, xyaxes, zaxis), hinge and
/// slide joints (several per body, away from the body origin), ranges in the compiler's angle
/// unit, default classes and childclass, geoms box / capsule / cylinder / sphere / ellipsoid /
/// mesh (fromto included; geoms with contype and conaffinity 0 are visual and left out), sites,
/// <equality><joint> couplings of degree 1, actuators on joints and on fixed tendons with their
/// force ranges and gears, inertial mass and centre. Mesh geoms become the box bounding the mesh
/// (STL or OBJ) in the geom's frame; an ellipsoid becomes the capsule around it along its longest
/// axis. Everything approximated or left out is listed in ImportedHand::notes and in the header.
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/geometry/mass_properties.hpp>
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

// The STL (binary or ASCII) or OBJ mesh file at path (read_mesh_file); no vertices if it cannot
// be read, and *why says why.
inline TriangleMesh read_mesh(const std::string& path, std::string* why = nullptr) {
  try {
    return read_mesh_file(path);
  } catch (const mesh_error& e) {
    if (why) *why = e.what();
    return {};
  }
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
  const std::vector<Vec3> v = read_mesh(path, &why).vertices;
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

// ---------------------------------------------------------------------------------------------
// URDF

inline Eigen::Isometry3d urdf_origin(const Importer& im, const XmlElement& parent) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (const XmlElement& c : parent.children)
    if (c.name == "origin") {
      const auto xyz = im.numbers(c, "xyz", 3, {0, 0, 0});
      const auto rpy = im.numbers(c, "rpy", 3, {0, 0, 0});
      T = at(xyz[0], xyz[1], xyz[2]).rpy(rpy[0], rpy[1], rpy[2]).isometry();
    }
  return T;
}

inline const XmlElement* child(const XmlElement& e, std::string_view name) {
  for (const XmlElement& c : e.children)
    if (c.name == name) return &c;
  return nullptr;
}

inline ImportedHand import_urdf(const XmlDocument& doc, const ImportOptions& options) {
  const Importer im{doc.file};
  const XmlElement& robot = doc.root;
  if (robot.name != "robot") im.fail(robot, "a URDF file's root element must be <robot>");
  ImportedHand out;
  out.source = doc.file;
  out.format = HandFileFormat::urdf;
  std::map<std::string, const XmlElement*> links;
  std::vector<const XmlElement*> joints;
  for (const XmlElement& e : robot.children) {
    if (e.name == "link") {
      const std::string n = im.name_of(e, "a link");
      if (!links.emplace(n, &e).second) im.fail(e, "a second link called \"" + n + "\"");
    } else if (e.name == "joint") {
      joints.push_back(&e);
    }
  }
  // The tree: each child link's joint, each parent's joints in file order.
  std::map<std::string, const XmlElement*> joint_of_child;
  std::map<std::string, std::vector<const XmlElement*>> joints_of_parent;
  std::map<std::string, std::string> child_of_joint;
  for (const XmlElement* j : joints) {
    const std::string n = im.name_of(*j, "a joint");
    const XmlElement* p = child(*j, "parent");
    const XmlElement* c = child(*j, "child");
    if (!p || !p->attribute("link") || !c || !c->attribute("link"))
      im.fail(*j, "a joint needs <parent link=...> and <child link=...>");
    const std::string& pl = *p->attribute("link");
    const std::string& cl = *c->attribute("link");
    if (!links.count(pl)) im.fail(*j, "its parent link \"" + pl + "\" is not in the file");
    if (!links.count(cl)) im.fail(*j, "its child link \"" + cl + "\" is not in the file");
    if (!joint_of_child.emplace(cl, j).second)
      im.fail(*j, "the link \"" + cl + "\" is the child of a second joint");
    if (!child_of_joint.emplace(n, cl).second) im.fail(*j, "a second joint called \"" + n + "\"");
    joints_of_parent[pl].push_back(j);
  }
  std::string root = options.root;
  if (root.empty()) {
    std::vector<std::string> roots;
    for (const auto& [n, e] : links)
      if (!joint_of_child.count(n)) roots.push_back(n);
    if (roots.size() != 1) {
      std::string names;
      for (const std::string& r : roots) names += (names.empty() ? "" : ", ") + r;
      im.fail(robot, roots.empty()
                         ? "the joints form a loop: no link is the root"
                         : "more than one root link (" + names + "): choose one with --root");
    }
    root = roots.front();
  } else if (!links.count(root)) {
    im.fail(robot, "no link called \"" + root + "\" (the root asked for)");
  }
  // Depth first, in file order, parents before children.
  std::vector<std::pair<std::string, const XmlElement*>> stack{{root, nullptr}};
  std::vector<std::pair<std::size_t, std::string>> mimics;  // (link index, source joint)
  while (!stack.empty()) {
    const auto [name, joint] = stack.back();
    stack.pop_back();
    const XmlElement& link = *links.at(name);
    if (out.links.size() > links.size()) im.fail(robot, "the joints form a loop");
    LinkSpec l = topograsp::root(std::string_view(name));
    std::string joint_name;
    if (joint) {
      joint_name = *joint->attribute("name");
      l.parent = std::string_view(*child(*joint, "parent")->attribute("link"));
      l.origin = to_pose(urdf_origin(im, *joint));
      const std::string type = joint->attribute("type") ? *joint->attribute("type") : "";
      const XmlElement* limit = child(*joint, "limit");
      if (type == "revolute" || type == "continuous" || type == "prismatic") {
        const XmlElement* axis = child(*joint, "axis");
        const auto a = axis ? im.numbers(*axis, "xyz", 3, {1, 0, 0}) : std::vector<double>{1, 0, 0};
        if (std::abs(a[0]) + std::abs(a[1]) + std::abs(a[2]) < 1e-12)
          im.fail(*joint, "its axis is zero");
        l.type = type == "prismatic" ? JointType::prismatic : JointType::revolute;
        l.axis = {a[0], a[1], a[2]};
        if (type != "continuous" && !limit)
          im.fail(*joint, type + " joint without <limit> (URDF requires one)");
        if (type == "continuous") {
          l.lower = -pi;
          l.upper = pi;
          out.notes.push_back("the continuous joint " + joint_name + " is limited to [-pi, pi]");
        }
        if (limit) {
          if (type != "continuous") {
            l.lower = im.numbers(*limit, "lower", 1, {0})[0];
            l.upper = im.numbers(*limit, "upper", 1, {0})[0];
            if (l.lower > l.upper) im.fail(*limit, "lower limit above upper limit");
          }
          l.effort = im.numbers(*limit, "effort", 1, {0})[0];
          l.velocity = im.numbers(*limit, "velocity", 1, {0})[0];
          if (l.effort < 0.0 || l.velocity < 0.0)
            im.fail(*limit, "effort and velocity must be >= 0");
        }
        if (const XmlElement* m = child(*joint, "mimic")) {
          if (!m->attribute("joint")) im.fail(*m, "<mimic> without joint=");
          l.multiplier = im.numbers(*m, "multiplier", 1, {1})[0];
          l.offset = im.numbers(*m, "offset", 1, {0})[0];
          mimics.emplace_back(out.links.size(), *m->attribute("joint"));
        }
      } else if (type != "fixed") {
        im.fail(*joint, "joint type \"" + type +
                            "\" is not supported (revolute, continuous, prismatic or fixed)");
      }
    }
    if (const XmlElement* inertial = child(link, "inertial")) {
      if (const XmlElement* m = child(*inertial, "mass")) l.mass = im.numbers(*m, "value", 1)[0];
      const Vec3 c = urdf_origin(im, *inertial).translation();
      l.com = {c.x(), c.y(), c.z()};
      if (l.mass < 0.0) im.fail(*inertial, "negative mass");
    }
    const Name link_name = l.name;
    out.links.push_back(l);
    out.joint_names.push_back(joint_name);
    for (const XmlElement& c : link.children) {
      if (c.name != "collision") continue;
      const Eigen::Isometry3d pose = urdf_origin(im, c);
      const XmlElement* g = child(c, "geometry");
      if (!g || g->children.empty()) im.fail(c, "<collision> without <geometry>");
      const XmlElement& s = g->children.front();
      ShapeSpec shape;
      shape.link = link_name;
      shape.pose = to_pose(pose);
      if (s.name == "box") {
        const auto size = im.numbers(s, "size", 3);
        shape.type = ShapeType::box;
        shape.size = {0.5 * size[0], 0.5 * size[1], 0.5 * size[2]};
      } else if (s.name == "sphere") {
        shape.type = ShapeType::sphere;
        shape.size = {im.numbers(s, "radius", 1, {-1})[0], 0.0, 0.0};
      } else if (s.name == "cylinder" || s.name == "capsule") {
        shape.type = s.name == "cylinder" ? ShapeType::cylinder : ShapeType::capsule;
        shape.size = {im.numbers(s, "radius", 1, {-1})[0],
                      0.5 * im.numbers(s, "length", 1, {-1})[0], 0.0};
      } else if (s.name == "mesh") {
        if (!s.attribute("filename")) im.fail(s, "<mesh> without filename=");
        std::string f = *s.attribute("filename");
        namespace fs = std::filesystem;
        fs::path dir = options.mesh_dir.empty() ? fs::path(doc.file).parent_path()
                                                : fs::path(options.mesh_dir);
        if (f.rfind("file://", 0) == 0) f = f.substr(7);
        if (f.rfind("package://", 0) == 0) {
          // package://PKG/REST: REST in the folder of package PKG, found as a folder called PKG
          // at or above the URDF's (the ROS layout PKG/urdf/hand.urdf); else beside the URDF.
          f = f.substr(10);
          const std::string package = f.substr(0, f.find('/'));
          f = f.substr(std::min(f.size(), f.find('/') + 1));
          if (options.mesh_dir.empty()) {
            std::error_code ec;
            for (fs::path up = fs::absolute(dir, ec); !up.empty(); up = up.parent_path()) {
              if (up.filename() == package) {
                dir = up;
                break;
              }
              if (fs::is_directory(up / package, ec)) {
                dir = up / package;
                break;
              }
              if (up == up.parent_path()) break;
            }
          }
        }
        const auto sc = im.numbers(s, "scale", 3, {1, 1, 1});
        add_box_of_mesh(im, s, (dir / f).string(), Vec3(sc[0], sc[1], sc[2]), pose, link_name,
                        options.skip_missing_meshes, out);
        continue;
      } else {
        im.fail(s, "unknown collision geometry (box, cylinder, sphere or mesh)");
      }
      const auto& z = shape.size;
      if (!(z[0] > 0.0) || !(z[1] >= 0.0) ||
          (shape.type == ShapeType::box && !(z[1] > 0.0 && z[2] > 0.0)))
        im.fail(s, "its size must be > 0");
      out.shapes.push_back(shape);
    }
    const auto& next = joints_of_parent[name];
    for (auto it = next.rbegin(); it != next.rend(); ++it)
      stack.emplace_back(*child(**it, "child")->attribute("link"), *it);
  }
  for (const auto& [i, source] : mimics) {
    const int s = out.link_of_joint(source);
    if (s < 0)
      im.fail(robot, "joint " + out.joint_names[i] + " mimics \"" + source +
                         "\", which is not a joint below the root");
    LinkSpec& l = out.links[i];
    l.mimic = out.links[static_cast<std::size_t>(s)].name;
    if (l.effort != 0.0 || l.velocity != 0.0)
      out.notes.push_back("the mimic joint " + out.joint_names[i] +
                          " is driven through its source: its effort and velocity are dropped");
    l.effort = l.velocity = l.armature = 0.0;
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// MJCF

using Attributes = std::map<std::string, std::string>;

struct MjcfContext {
  Importer im;
  ImportOptions options;
  bool degrees = true;  // MJCF's default angle unit
  std::string eulerseq = "xyz";
  std::string inertia_from_geoms = "auto";     // the compiler's inertiafromgeom
  bool autolimits = true;                      // the compiler's autolimits (MuJoCo 3's default)
  std::array<double, 2> inertia_groups{0, 5};  // the compiler's inertiagrouprange
  std::filesystem::path mesh_dir;
  std::map<std::string, std::map<std::string, Attributes>> defaults;  // [class][element]
  std::map<std::string, std::pair<std::string, Vec3>> meshes;         // name -> (path, scale)
  ImportedHand out;

  double angle(double v) const { return degrees ? v * pi / 180.0 : v; }

  // e's attributes over its class's defaults for elements called `kind`.
  Attributes resolved(const XmlElement& e, const std::string& kind,
                      const std::string& inherited_class) const {
    const std::string* c = e.attribute("class");
    const std::string cls = c ? *c : inherited_class;
    Attributes a;
    const auto d = defaults.find(cls);
    if (c && d == defaults.end()) im.fail(e, "no default class called \"" + cls + "\"");
    if (d != defaults.end()) {
      const auto k = d->second.find(kind);
      if (k != d->second.end()) a = k->second;
    }
    for (const XmlAttribute& x : e.attributes) a[x.name] = x.value;
    return a;
  }

  // The frame given by pos and one of quat / axisangle / euler / xyaxes / zaxis.
  Eigen::Isometry3d frame_of(const XmlElement& e, const Attributes& a) const {
    Eigen::Isometry3d T = translation_of(im.numbers(e, a, "pos", 3, {0, 0, 0}));
    int given = 0;
    for (const char* k : {"quat", "axisangle", "euler", "xyaxes", "zaxis"}) given += a.count(k);
    if (given > 1) im.fail(e, "more than one orientation given");
    Mat3 R = Mat3::Identity();
    if (a.count("quat")) {
      const auto q = im.numbers(e, a, "quat", 4);
      Eigen::Quaterniond qq(q[0], q[1], q[2], q[3]);
      if (qq.norm() < 1e-12) im.fail(e, "quat is zero");
      R = qq.normalized().toRotationMatrix();
    } else if (a.count("axisangle")) {
      const auto v = im.numbers(e, a, "axisangle", 4);
      const Vec3 axis(v[0], v[1], v[2]);
      if (axis.norm() < 1e-12) im.fail(e, "axisangle's axis is zero");
      R = Eigen::AngleAxisd(angle(v[3]), axis.normalized()).toRotationMatrix();
    } else if (a.count("euler")) {
      const auto v = im.numbers(e, a, "euler", 3);
      for (std::size_t i = 0; i < 3; ++i) {
        const char c = eulerseq[i];
        const int k = std::tolower(static_cast<unsigned char>(c)) - 'x';
        const Mat3 Ri = Eigen::AngleAxisd(angle(v[i]), Vec3::Unit(k)).toRotationMatrix();
        R = std::islower(static_cast<unsigned char>(c)) ? Mat3(R * Ri) : Mat3(Ri * R);
      }
    } else if (a.count("xyaxes")) {
      const auto v = im.numbers(e, a, "xyaxes", 6);
      Vec3 x(v[0], v[1], v[2]), y(v[3], v[4], v[5]);
      if (x.norm() < 1e-12) im.fail(e, "xyaxes' x axis is zero");
      x.normalize();
      y -= y.dot(x) * x;
      if (y.norm() < 1e-12) im.fail(e, "xyaxes' y axis is along its x axis");
      y.normalize();
      R.col(0) = x;
      R.col(1) = y;
      R.col(2) = x.cross(y);
    } else if (a.count("zaxis")) {
      const auto v = im.numbers(e, a, "zaxis", 3);
      const Vec3 z(v[0], v[1], v[2]);
      if (z.norm() < 1e-12) im.fail(e, "zaxis is zero");
      R = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), z.normalized()).toRotationMatrix();
    }
    T.linear() = R;
    return T;
  }

  void read_defaults(const XmlElement& d, const std::string& parent) {
    const std::string* c = d.attribute("class");
    const std::string cls = c ? *c : (parent.empty() ? "main" : "");
    if (cls.empty()) im.fail(d, "a nested <default> needs class=");
    // A second top-level <default> adds to "main", as in MuJoCo; a nested one starts from its
    // parent.
    auto inherited = parent.empty() ? defaults[cls] : defaults[parent];
    for (const XmlElement& k : d.children) {
      if (k.name == "default") continue;
      // The actuator shortcuts share one default.
      const bool actuator =
          k.name == "motor" || k.name == "position" || k.name == "velocity" || k.name == "general";
      Attributes& a = inherited[actuator ? "actuator" : k.name];
      for (const XmlAttribute& x : k.attributes) a[x.name] = x.value;
    }
    defaults[cls] = inherited;
    for (const XmlElement& k : d.children)
      if (k.name == "default") read_defaults(k, cls);
  }

  // Adds the links of body b (whose frame is T_link_body in the frame of link `parent`).
  void read_body(const XmlElement& b, const std::string& parent,
                 const Eigen::Isometry3d& body_in_parent, const std::string& child_class,
                 bool is_root) {
    const std::string body = im.name_of(b, "a body");
    const std::string* cc = b.attribute("childclass");
    const std::string cls = cc ? *cc : child_class;
    if (cc && !defaults.count(cls)) im.fail(b, "no default class called \"" + cls + "\"");
    // Its joints, in order: one link each, the last one named after the body.
    std::vector<const XmlElement*> joints;
    for (const XmlElement& c : b.children) {
      if (c.name == "freejoint" || (c.name == "joint" && resolved(c, "joint", cls).count("type") &&
                                    resolved(c, "joint", cls).at("type") == "free")) {
        if (!is_root) im.fail(c, "a free joint below the root");
        out.notes.push_back("the free joint of the root body " + body + " is left out");
        continue;
      }
      if (c.name == "joint") {
        if (is_root) {  // the model starts at the root: what moves it is not part of it
          out.notes.push_back("the joint " + im.name_of(c, "a joint") + " of the root body " +
                              body + " is left out");
          continue;
        }
        joints.push_back(&c);
      }
    }
    Eigen::Isometry3d to_link = body_in_parent;  // the body frame in the frame of `prev`
    std::string prev = parent;
    Eigen::Isometry3d content = Eigen::Isometry3d::Identity();  // body frame in the last link
    if (joints.empty()) {
      const Name bn(std::string_view{body}), pn(std::string_view{prev});
      LinkSpec l = is_root ? topograsp::root(bn) : fixed(bn, pn, to_pose(to_link));
      out.links.push_back(l);
      out.joint_names.emplace_back();
    }
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const XmlElement& j = *joints[k];
      const Attributes a = resolved(j, "joint", cls);
      const std::string type = a.count("type") ? a.at("type") : "hinge";
      if (type != "hinge" && type != "slide")
        im.fail(j, "joint type \"" + type + "\" is not supported (hinge or slide)");
      const std::string jn = im.name_of(j, "a joint");
      const std::string link = k + 1 == joints.size() ? body : jn;
      im.check_name(j, link);
      const auto pos = im.numbers(j, a, "pos", 3, {0, 0, 0});
      const auto axis = im.numbers(j, a, "axis", 3, {0, 0, 1});
      if (std::abs(axis[0]) + std::abs(axis[1]) + std::abs(axis[2]) < 1e-12)
        im.fail(j, "its axis is zero");
      if (a.count("ref") && im.numbers(j, a, "ref", 1)[0] != 0.0)
        im.fail(j, "a joint with ref != 0 is not supported");
      const Eigen::Isometry3d at_joint = to_link * translation_of(pos);
      const Name ln(std::string_view{link}), pn(std::string_view{prev});
      LinkSpec l =
          type == "hinge"
              ? revolute(ln, pn, to_pose(at_joint), {axis[0], axis[1], axis[2]}, -pi, pi)
              : prismatic(ln, pn, to_pose(at_joint), {axis[0], axis[1], axis[2]}, 0.0, 0.0);
      // MuJoCo 3's rule (the compiler's autolimits, default true): a range limits the joint unless
      // limited="false"; with autolimits="false" only limited="true" does.
      const std::string lim = a.count("limited") ? a.at("limited") : "auto";
      const bool limited = a.count("range") && (lim == "true" || (lim != "false" && autolimits));
      if (limited) {
        const auto r = im.numbers(j, a, "range", 2);
        l.lower = type == "hinge" ? angle(r[0]) : r[0];
        l.upper = type == "hinge" ? angle(r[1]) : r[1];
        if (l.lower > l.upper) im.fail(j, "its range's lower end is above its upper end");
      } else if (type == "hinge") {
        out.notes.push_back("the unlimited hinge " + jn + " is limited to [-pi, pi]");
      } else {
        im.fail(j, "a slide joint without a range");
      }
      l.armature = im.numbers(j, a, "armature", 1, {0})[0];
      if (l.armature < 0.0) im.fail(j, "negative armature");
      out.links.push_back(l);
      out.joint_names.push_back(jn);
      // The next joint (or the body's content) is placed from this joint's frame.
      to_link = translation_of({-pos[0], -pos[1], -pos[2]});
      prev = link;
    }
    if (!joints.empty()) content = to_link;
    const std::size_t own = out.links.size() - 1;  // this body's link (children come after)
    const Name link_name = out.links[own].name;
    double geom_mass = 0.0;
    Vec3 geom_moment = Vec3::Zero();
    const bool has_inertial = std::any_of(b.children.begin(), b.children.end(),
                                          [](const XmlElement& c) { return c.name == "inertial"; });
    // Inertial, geoms, sites, children.
    for (const XmlElement& c : b.children) {
      if (c.name == "inertial") {
        const Attributes a = resolved(c, "inertial", cls);
        LinkSpec& l = out.links[own];
        l.mass = im.numbers(c, a, "mass", 1, {0})[0];
        if (l.mass < 0.0) im.fail(c, "negative mass");
        const Vec3 com = content * Vec3(im.numbers(c, a, "pos", 3, {0, 0, 0}).data());
        l.com = {com.x(), com.y(), com.z()};
      } else if (c.name == "geom") {
        const auto [m, centre] = read_geom(c, resolved(c, "geom", cls), content, link_name);
        geom_mass += m;
        geom_moment += m * centre;
      } else if (c.name == "site") {
        const Attributes a = resolved(c, "site", cls);
        if (!c.attribute("name")) continue;
        const std::string n = im.name_of(c, "a site");
        out.frames.push_back(
            frame(std::string_view(n), link_name, to_pose(content * frame_of(c, a))));
      } else if (c.name == "frame" || c.name == "replicate" || c.name == "attach") {
        im.fail(c, "<" + c.name + "> (MuJoCo 3) is not supported: write its bodies out");
      } else if (c.name == "body") {
        read_body(c, std::string(link_name.view()), content * frame_of(c, resolved(c, "body", cls)),
                  cls, false);
      }
    }
    // Without <inertial> (or with inertiafromgeom="true"), the mass from the geoms, as MuJoCo.
    if ((!has_inertial && inertia_from_geoms != "false") || inertia_from_geoms == "true") {
      LinkSpec& l = out.links[own];
      l.mass = geom_mass;
      const Vec3 com = geom_mass > 0.0 ? Vec3(geom_moment / geom_mass) : Vec3::Zero();
      l.com = {com.x(), com.y(), com.z()};
    }
  }

  // Adds g (attributes a, its body's frame `content` in the frame of `link`) to the shapes if it
  // collides (contype or conaffinity not 0); returns its mass and centre of mass (link frame), as
  // MuJoCo infers a body's inertia from all its geoms: its mass= or density (default 1000 kg/m^3)
  // times its volume.
  std::pair<double, Vec3> read_geom(const XmlElement& g, const Attributes& a,
                                    const Eigen::Isometry3d& content, const Name& link) {
    const auto number = [&](const char* k, double fallback) {
      return a.count(k) ? im.numbers(g, a, k, 1)[0] : fallback;
    };
    const bool collides = number("contype", 1.0) != 0.0 || number("conaffinity", 1.0) != 0.0;
    const std::string type = a.count("type") ? a.at("type") : "sphere";
    const auto size = im.numbers(g, a, "size", 0, {});
    Eigen::Isometry3d pose = content * frame_of(g, a);
    double half_from = -1.0;
    if (a.count("fromto")) {
      const auto f = im.numbers(g, a, "fromto", 6);
      const Vec3 p0(f[0], f[1], f[2]), p1(f[3], f[4], f[5]);
      pose = content * segment_isometry(p0, p1);
      half_from = 0.5 * (p1 - p0).norm();
    }
    const auto need = [&](std::size_t n) {
      if (size.size() < n)
        im.fail(g, "a " + type + " geom needs " + std::to_string(n) + " size numbers");
      for (std::size_t i = 0; i < n; ++i)
        if (!(size[i] > 0.0)) im.fail(g, "its size must be > 0");
    };
    const double density = number("density", 1000.0);
    const double group = number("group", 0.0);
    const bool weighs = group >= inertia_groups[0] && group <= inertia_groups[1];
    const auto mass_of = [&](double volume, const Vec3& centre) {
      return std::pair<double, Vec3>{!weighs           ? 0.0
                                     : a.count("mass") ? number("mass", 0.0)
                                                       : density * volume,
                                     centre};
    };
    ShapeSpec s;
    s.link = link;
    s.pose = to_pose(pose);
    if (type == "sphere") {
      need(1);
      s.type = ShapeType::sphere;
      s.size = {size[0], 0.0, 0.0};
    } else if (type == "capsule" || type == "cylinder") {
      need(half_from >= 0.0 ? 1 : 2);
      s.type = type == "capsule" ? ShapeType::capsule : ShapeType::cylinder;
      s.size = {size[0], half_from >= 0.0 ? half_from : size[1], 0.0};
    } else if (type == "box") {
      need(3);
      s.type = ShapeType::box;
      s.size = {size[0], size[1], size[2]};
    } else if (type == "ellipsoid") {
      need(3);
      std::array<int, 3> order{0, 1, 2};
      std::sort(order.begin(), order.end(), [&](int x, int y) {
        return size[static_cast<std::size_t>(x)] > size[static_cast<std::size_t>(y)];
      });
      const double r = size[static_cast<std::size_t>(order[1])];
      const double half = size[static_cast<std::size_t>(order[0])] - r;
      // The capsule's z along the longest semi-axis.
      Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
      turn.linear() = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), Vec3::Unit(order[0]))
                          .toRotationMatrix();
      s.type = half > 0.0 ? ShapeType::capsule : ShapeType::sphere;
      s.pose = to_pose(pose * turn);
      s.size = {r, std::max(half, 0.0), 0.0};
      if (collides) {
        out.shapes.push_back(s);
        out.notes.push_back("an ellipsoid of link " + std::string(link.view()) +
                            " is approximated by the capsule around it");
      }
      // The ellipsoid's own volume, not its capsule's.
      return mass_of(4.0 / 3.0 * pi * size[0] * size[1] * size[2], pose.translation());
    } else if (type == "mesh") {
      const std::string* m = a.count("mesh") ? &a.at("mesh") : nullptr;
      if (!m) im.fail(g, "a mesh geom without mesh=");
      const auto it = meshes.find(*m);
      if (it == meshes.end()) im.fail(g, "no mesh asset called \"" + *m + "\"");
      const auto& [path, scale] = it->second;
      const TriangleMesh mesh = read_mesh(path);
      std::pair<double, Vec3> mass{0.0, pose.translation()};
      if (!mesh.vertices.empty()) {
        const auto [volume, centroid] = mesh_volume(mesh, scale);
        mass = mass_of(volume, pose * centroid);
      } else if (!collides) {
        out.notes.push_back("the mesh \"" + path + "\" of link " + std::string(link.view()) +
                            " could not be read: its mass is not counted");
      }
      if (collides)
        add_box_of_mesh(im, g, path, scale, pose, link, options.skip_missing_meshes, out);
      return mass;
    } else {
      if (collides)
        out.notes.push_back("a " + type + " geom of link " + std::string(link.view()) +
                            " is left out (box, capsule, cylinder, sphere, ellipsoid or mesh)");
      return {0.0, Vec3::Zero()};
    }
    if (collides) out.shapes.push_back(s);
    // A primitive's volume: its mass properties at unit density (physics/mass_properties.hpp).
    return mass_of(shape_mass_properties(s, 1.0).mass, pose.translation());
  }
};

inline ImportedHand import_mjcf(const XmlDocument& doc, const ImportOptions& options) {
  MjcfContext cx{Importer{doc.file}, options, true, "xyz", "auto", true, {0, 5}, {}, {}, {}, {}};
  const XmlElement& mj = doc.root;
  if (mj.name != "mujoco") cx.im.fail(mj, "an MJCF file's root element must be <mujoco>");
  cx.out.source = doc.file;
  cx.out.format = HandFileFormat::mjcf;
  const std::filesystem::path dir = std::filesystem::path(doc.file).parent_path();
  std::string meshdir;
  {  // <include> anywhere: not supported (MuJoCo splices the file in; merge it by hand)
    std::vector<const XmlElement*> stack{&mj};
    while (!stack.empty()) {
      const XmlElement* e = stack.back();
      stack.pop_back();
      if (e->name == "include")
        cx.im.fail(*e, "<include> is not supported: merge the included file into this one");
      for (const XmlElement& c : e->children) stack.push_back(&c);
    }
  }
  for (const XmlElement& e : mj.children) {
    if (e.name != "compiler") continue;
    if (const std::string* a = e.attribute("angle")) {
      if (*a != "degree" && *a != "radian")
        cx.im.fail(e, "angle=\"" + *a + "\" (expected degree or radian)");
      cx.degrees = *a == "degree";
    }
    if (const std::string* s = e.attribute("eulerseq")) {
      if (s->size() != 3 || std::any_of(s->begin(), s->end(), [](char c) {
            return std::string_view("xyzXYZ").find(c) == std::string_view::npos;
          }))
        cx.im.fail(e, "eulerseq=\"" + *s + "\" (expected three of x, y, z, X, Y, Z)");
      cx.eulerseq = *s;
    }
    if (const std::string* m = e.attribute("meshdir")) meshdir = *m;
    if (const std::string* g = e.attribute("inertiafromgeom")) cx.inertia_from_geoms = *g;
    if (const std::string* l = e.attribute("autolimits")) cx.autolimits = *l != "false";
    if (e.has("inertiagrouprange")) {
      const auto r = cx.im.numbers(e, "inertiagrouprange", 2);
      cx.inertia_groups = {r[0], r[1]};
    }
  }
  cx.mesh_dir = options.mesh_dir.empty() ? dir / meshdir : std::filesystem::path(options.mesh_dir);
  cx.defaults["main"];
  for (const XmlElement& e : mj.children)
    if (e.name == "default") cx.read_defaults(e, "");
  for (const XmlElement& e : mj.children)
    if (e.name == "asset")
      for (const XmlElement& m : e.children) {
        if (m.name != "mesh") continue;
        const Attributes a = cx.resolved(m, "mesh", "main");
        if (!a.count("file")) continue;  // a mesh given by its vertices: not used by hands
        const std::string name =
            a.count("name") ? a.at("name") : std::filesystem::path(a.at("file")).stem().string();
        const auto sc = cx.im.numbers(m, a, "scale", 3, {1, 1, 1});
        cx.meshes[name] = {(cx.mesh_dir / a.at("file")).string(), Vec3(sc[0], sc[1], sc[2])};
      }
  // The root body.
  const XmlElement* world = child(mj, "worldbody");
  if (!world) cx.im.fail(mj, "no <worldbody>");
  const XmlElement* root = nullptr;
  std::string root_class = "main";
  if (options.root.empty()) {
    std::string names;
    int count = 0;
    for (const XmlElement& b : world->children)
      if (b.name == "body") {
        root = &b;
        ++count;
        names += (names.empty() ? "" : ", ") +
                 (b.attribute("name") ? *b.attribute("name") : std::string("(unnamed)"));
      }
    if (count == 0) cx.im.fail(*world, "no body in <worldbody>");
    if (count > 1)
      cx.im.fail(*world, "more than one top-level body (" + names + "): choose one with --root");
  } else {
    // Each body with the class its ancestors' childclass gives it.
    std::vector<std::pair<const XmlElement*, std::string>> stack{{world, "main"}};
    while (!stack.empty() && !root) {
      const auto [e, cls] = stack.back();
      stack.pop_back();
      for (const XmlElement& c : e->children)
        if (c.name == "body") {
          if (c.attribute("name") && *c.attribute("name") == options.root) {
            root = &c;
            root_class = cls;
          }
          stack.emplace_back(&c, c.attribute("childclass") ? *c.attribute("childclass") : cls);
        }
    }
    if (!root) cx.im.fail(*world, "no body called \"" + options.root + "\" (the root asked for)");
  }
  cx.read_body(*root, "", Eigen::Isometry3d::Identity(), root_class, true);
  ImportedHand& out = cx.out;
  // Fixed tendons: joint -> (tendon, coefficient).
  std::map<std::string, std::vector<std::pair<std::string, double>>> tendons;
  for (const XmlElement& e : mj.children)
    if (e.name == "tendon")
      for (const XmlElement& t : e.children) {
        if (t.name != "fixed" || !t.attribute("name")) continue;
        for (const XmlElement& j : t.children)
          if (j.name == "joint" && j.attribute("joint"))
            tendons[*t.attribute("name")].emplace_back(*j.attribute("joint"),
                                                       cx.im.numbers(j, "coef", 1, {1})[0]);
      }
  // Equality couplings: joint1 = c0 + c1 joint2.
  for (const XmlElement& e : mj.children)
    if (e.name == "equality")
      for (const XmlElement& q : e.children) {
        if (q.name != "joint") continue;
        const Attributes a = cx.resolved(q, "equality", "main");
        if (a.count("active") && a.at("active") == "false") continue;
        const int i = a.count("joint1") ? out.link_of_joint(a.at("joint1")) : -1;
        const int s = a.count("joint2") ? out.link_of_joint(a.at("joint2")) : -1;
        if (i < 0 || s < 0)
          cx.im.fail(q, "a joint coupling needs joint1= and joint2=, both joints below the root");
        const auto c = cx.im.numbers(q, a, "polycoef", 5, {0, 1, 0, 0, 0});
        if (c[2] != 0.0 || c[3] != 0.0 || c[4] != 0.0)
          cx.im.fail(q, "only linear couplings (polycoef c0 c1 0 0 0) are supported");
        LinkSpec& l = out.links[static_cast<std::size_t>(i)];
        l.mimic = out.links[static_cast<std::size_t>(s)].name;
        l.multiplier = c[1];
        l.offset = c[0];
      }
  // Actuators: the largest torque each joint gets.
  for (const XmlElement& e : mj.children)
    if (e.name == "actuator")
      for (const XmlElement& act : e.children) {
        const Attributes a = cx.resolved(act, "actuator", "main");
        const std::string label = act.attribute("name") ? *act.attribute("name") : act.name;
        const std::string lim = a.count("forcelimited") ? a.at("forcelimited") : "auto";
        if (!a.count("forcerange") || !(lim == "true" || (lim != "false" && cx.autolimits))) {
          out.notes.push_back("the actuator " + label +
                              " has no force range: its joint's effort is left 0");
          continue;
        }
        const auto fr = cx.im.numbers(act, a, "forcerange", 2);
        const double gear = std::abs(cx.im.numbers(act, a, "gear", 0, {1}).front());
        const double force = gear * std::max(std::abs(fr[0]), std::abs(fr[1]));
        std::vector<std::pair<std::string, double>> targets;
        if (a.count("joint")) {
          targets.emplace_back(a.at("joint"), 1.0);
        } else if (a.count("tendon") && tendons.count(a.at("tendon"))) {
          targets = tendons.at(a.at("tendon"));
        } else {
          out.notes.push_back("the actuator " + label +
                              " drives neither a joint nor a fixed tendon: left out");
          continue;
        }
        for (const auto& [joint, coef] : targets) {
          const int i = out.link_of_joint(joint);
          if (i < 0) continue;  // a joint outside the imported part
          LinkSpec& l = out.links[static_cast<std::size_t>(i)];
          l.effort += std::abs(coef) * force;  // actuators on one joint add up
        }
      }
  for (std::size_t i = 0; i < out.links.size(); ++i) {
    LinkSpec& l = out.links[i];
    if (l.mimic.empty() || (l.effort == 0.0 && l.armature == 0.0)) continue;
    out.notes.push_back("the coupled joint " + out.joint_names[i] +
                        " is driven through its source: its own actuator and armature are dropped");
    l.effort = l.velocity = l.armature = 0.0;
  }
  return out;
}

// \p v in the shortest form that reads back exactly; \p clean: below 1e-15 written as 0 (the
// rounding noise of rotations, not a size).
inline void append_number(std::string& s, double v, bool clean = false) {
  if (clean && std::abs(v) < 1e-15) v = 0.0;
  char b[32];
  const auto [end, ec] = std::to_chars(b, b + sizeof b, v);
  std::string t(b, ec == std::errc() ? end : b);
  if (t.find_first_of(".en") == std::string::npos) t += ".0";
  s += t;
}

inline std::string pose_code(const Pose& p) {
  std::string s = "at(";
  for (std::size_t i = 0; i < 3; ++i) {
    append_number(s, p.p[i], true);
    s += i < 2 ? ", " : ")";
  }
  const Eigen::Isometry3d T = p.isometry();
  if (!T.linear().isIdentity(1e-15)) {
    Eigen::Quaterniond q(T.linear());
    if (q.w() < 0.0) q.coeffs() *= -1.0;
    s += ".quat(";
    const double c[4] = {q.w(), q.x(), q.y(), q.z()};
    for (int i = 0; i < 4; ++i) {
      append_number(s, c[i], true);
      s += i < 3 ? ", " : ")";
    }
  }
  return s;
}

inline std::string triple_code(const std::array<double, 3>& v) {
  std::string s = "{";
  for (std::size_t i = 0; i < 3; ++i) {
    append_number(s, v[i]);
    s += i < 2 ? ", " : "}";
  }
  return s;
}

// Refuses, naming the file and the link, shape or frame, what make_model() would refuse, so that
// a header written from an import always compiles: empty, long or repeated names, a parent that
// is not an earlier link, a joint axis of zero, limits that are not finite or in the wrong order,
// a coupling to a joint that is fixed or itself coupled, numbers that are not finite or beyond
// the model's ranges (from huge values in the file), shapes of non-positive size.
inline void check_importable(const ImportedHand& h) {
  const auto fail = [&](std::string_view what, const Name& name, std::string_view problem) {
    throw import_error(h.source + ": " + std::string(what) + " \"" + std::string(name.view()) +
                       "\": " + std::string(problem));
  };
  std::vector<std::string_view> names;
  const auto add_name = [&](std::string_view what, const Name& n) {
    if (n.empty()) fail(what, n, "an empty name");
    const std::string_view v = n.view();
    if (std::any_of(v.begin(), v.end(), [](char c) {
          return c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        }))
      fail(what, n, "a quote, a backslash or a control character in the name");
    if (std::find(names.begin(), names.end(), n.view()) != names.end())
      fail(what, n, "a second link or frame of that name");
    names.push_back(n.view());
  };
  const auto finite = [](std::initializer_list<double> v, double bound) {
    return std::all_of(v.begin(), v.end(),
                       [bound](double x) { return std::isfinite(x) && std::abs(x) < bound; });
  };
  for (std::size_t i = 0; i < h.links.size(); ++i) {
    const LinkSpec& l = h.links[i];
    add_name("link", l.name);
    if ((i == 0) != l.parent.empty()) fail("link", l.name, "only the first link is the root");
    if (i > 0 && std::find(names.begin(), names.end() - 1, l.parent.view()) == names.end() - 1)
      fail("link", l.name, "its parent is not an earlier link");
    const Pose& o = l.origin;
    if (!finite({o.p[0], o.p[1], o.p[2], l.com[0], l.com[1], l.com[2]}, 1e6) ||
        !finite({l.mass}, 1e6) || l.mass < 0.0)
      fail("link", l.name, "its origin, mass or centre of mass is not finite or beyond 1e6");
    if (l.type == JointType::fixed) continue;
    if (!finite({l.axis[0], l.axis[1], l.axis[2]}, 1e300) ||
        std::abs(l.axis[0]) + std::abs(l.axis[1]) + std::abs(l.axis[2]) < 1e-12)
      fail("joint of link", l.name, "its axis is zero or not finite");
    if (!finite({l.lower, l.upper, l.multiplier, l.offset}, 1e300) || l.lower > l.upper)
      fail("joint of link", l.name, "its limits are not finite or lower is above upper");
    if (!(l.effort >= 0.0 && l.effort < 1e9 && l.velocity >= 0.0 && l.velocity < 1e9 &&
          l.armature >= 0.0 && l.armature < 1e9))
      fail("joint of link", l.name, "its effort, velocity or armature is not in [0, 1e9)");
    if (l.mimic.empty()) continue;
    const auto source = std::find_if(h.links.begin(), h.links.end(),
                                     [&](const LinkSpec& s) { return s.name == l.mimic; });
    if (source == h.links.end() || source->type == JointType::fixed || !source->mimic.empty())
      fail("joint of link", l.name, "it is coupled to a joint that is fixed or itself coupled");
  }
  for (const ShapeSpec& sh : h.shapes) {
    const auto& z = sh.size;
    const bool ok = finite({z[0], z[1], z[2], sh.pose.p[0], sh.pose.p[1], sh.pose.p[2]}, 1e6) &&
                    (sh.type == ShapeType::box      ? (z[0] > 0.0 && z[1] > 0.0 && z[2] > 0.0)
                     : sh.type == ShapeType::sphere ? z[0] > 0.0
                                                    : (z[0] > 0.0 && z[1] >= 0.0));
    if (!ok) fail("a shape of link", sh.link, "its size is not positive or it is not finite");
  }
  for (const FrameSpec& f : h.frames) {
    add_name("frame", f.name);
    if (!finite({f.offset.p[0], f.offset.p[1], f.offset.p[2]}, 1e6))
      fail("frame", f.name, "its position is not finite or beyond 1e6");
  }
}

}  // namespace detail

/// Imports a URDF (<robot>) or MJCF (<mujoco>) document \p doc, read from the file doc.file.
/// What it returns, make_model() accepts (with a hand description that names existing links).
/// \throws topograsp::import_error naming the file, the line, the element and the problem, for
/// anything the model cannot hold (the list in this file's comment); or naming the file and the
/// link, shape or frame for what make_model() would refuse (a name used twice, a coupling to a
/// coupled joint, numbers beyond the model's ranges).
[[nodiscard]] inline ImportedHand import_hand(const XmlDocument& doc,
                                              const ImportOptions& options = {}) {
  if (doc.root.name == "robot" || doc.root.name == "mujoco") {
    ImportedHand hand = doc.root.name == "robot" ? detail::import_urdf(doc, options)
                                                 : detail::import_mjcf(doc, options);
    detail::check_importable(hand);
    return hand;
  }
  throw import_error(doc.file + ":" + std::to_string(doc.root.line) + ": <" + doc.root.name +
                     ">: neither a URDF file (<robot>) nor an MJCF file (<mujoco>)");
}

/// Reads and imports the URDF or MJCF file at \p path (the format from its root element).
/// \throws topograsp::xml_error for a file that cannot be read or is not well-formed XML,
/// topograsp::import_error for one that cannot be imported.
[[nodiscard]] inline ImportedHand import_hand_file(const std::string& path,
                                                   const ImportOptions& options = {}) {
  return import_hand(read_xml_file(path), options);
}

/// The C++ header that declares \p hand's links, shapes and frames as constexpr arrays in
/// namespace \p ns (`links`, `shapes`, `frames`, for make_model()), with \p comments (one line
/// each: where the file comes from, its licence), the joint names and the import's notes as
/// comments.
/// \throws topograsp::invalid_argument naming "ns" if \p ns is not a C++ namespace name
/// (identifiers joined by ::).
[[nodiscard]] inline std::string model_header(const ImportedHand& hand, std::string_view ns,
                                              const std::vector<std::string>& comments = {}) {
  bool ok = !ns.empty();
  for (std::size_t i = 0, start = 0; ok && i <= ns.size(); ++i) {
    if (i < ns.size() && ns[i] != ':') continue;
    const std::string_view id = ns.substr(start, i - start);
    ok = !id.empty() && !std::isdigit(static_cast<unsigned char>(id[0])) &&
         std::all_of(id.begin(), id.end(), [](char c) {
           return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
         });
    if (i < ns.size()) {
      ok = ok && i + 1 < ns.size() && ns[i + 1] == ':';
      start = i + 2;
      ++i;
    }
  }
  static constexpr std::array<std::string_view, 97> keywords{"alignas",
                                                             "alignof",
                                                             "and",
                                                             "and_eq",
                                                             "asm",
                                                             "auto",
                                                             "bitand",
                                                             "bitor",
                                                             "bool",
                                                             "break",
                                                             "case",
                                                             "catch",
                                                             "char",
                                                             "char8_t",
                                                             "char16_t",
                                                             "char32_t",
                                                             "class",
                                                             "compl",
                                                             "concept",
                                                             "const",
                                                             "consteval",
                                                             "constexpr",
                                                             "constinit",
                                                             "const_cast",
                                                             "continue",
                                                             "co_await",
                                                             "co_return",
                                                             "co_yield",
                                                             "decltype",
                                                             "default",
                                                             "delete",
                                                             "do",
                                                             "double",
                                                             "dynamic_cast",
                                                             "else",
                                                             "enum",
                                                             "explicit",
                                                             "export",
                                                             "extern",
                                                             "false",
                                                             "float",
                                                             "for",
                                                             "friend",
                                                             "goto",
                                                             "if",
                                                             "inline",
                                                             "int",
                                                             "long",
                                                             "mutable",
                                                             "namespace",
                                                             "new",
                                                             "noexcept",
                                                             "not",
                                                             "not_eq",
                                                             "nullptr",
                                                             "operator",
                                                             "or",
                                                             "or_eq",
                                                             "private",
                                                             "protected",
                                                             "public",
                                                             "register",
                                                             "reinterpret_cast",
                                                             "requires",
                                                             "return",
                                                             "short",
                                                             "signed",
                                                             "sizeof",
                                                             "static",
                                                             "static_assert",
                                                             "static_cast",
                                                             "struct",
                                                             "switch",
                                                             "template",
                                                             "this",
                                                             "thread_local",
                                                             "throw",
                                                             "true",
                                                             "try",
                                                             "typedef",
                                                             "typeid",
                                                             "typename",
                                                             "union",
                                                             "unsigned",
                                                             "using",
                                                             "virtual",
                                                             "void",
                                                             "volatile",
                                                             "wchar_t",
                                                             "while",
                                                             "xor",
                                                             "xor_eq",
                                                             "final",
                                                             "override",
                                                             "import",
                                                             "module",
                                                             "std"};
  for (std::size_t i = 0, start = 0; ok && i <= ns.size(); ++i)
    if (i == ns.size() || ns[i] == ':') {
      const std::string_view id = ns.substr(start, i - start);
      ok = std::find(keywords.begin(), keywords.end(), id) == keywords.end();
      start = i + 2;
      ++i;
    }
  if (!ok)
    detail::throw_invalid_argument(
        "ns", "\"" + std::string(ns) + "\" is not a C++ namespace name (a::b)");
  using detail::append_number;
  using detail::pose_code;
  using detail::triple_code;
  const auto quoted = [](const Name& n) {
    std::string q(1, '"');
    q += n.view();
    q += '"';
    return q;
  };
  // Generated code keeps the tool's layout: clang-format would join the comment lines.
  std::string s = "// clang-format off\n";
  for (const std::string& c : comments) {
    std::string line = c;
    std::replace(line.begin(), line.end(), '\n', ' ');
    s += "// " + line + "\n";
  }
  s += "// Generated by topograsp_import_hand from " +
       std::filesystem::path(hand.source).filename().string() + " (" +
       std::string(to_string(hand.format)) + "). Do not edit: edit the file and import it again.\n";
  for (std::string n : hand.notes) {
    std::replace_if(n.begin(), n.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    s += "// Note: " + n + "\n";
  }
  s += "#pragma once\n\n#include <topograsp/model/spec.hpp>\n\nnamespace " + std::string(ns) +
       " {\n\nusing namespace topograsp;\n\n";
  s += "/// The links of " + std::filesystem::path(hand.source).filename().string() +
       ", parents first; each moving link carries its joint.\n";
  s += "inline constexpr auto links = topograsp::links(";
  for (std::size_t i = 0; i < hand.links.size(); ++i) {
    const LinkSpec& l = hand.links[i];
    s += i == 0 ? "\n    " : ",\n    ";
    if (!hand.joint_names[i].empty() && hand.joint_names[i] != l.name.view())
      s += "// joint " + hand.joint_names[i] + "\n    ";
    if (l.parent.empty()) {
      s += "root(" + quoted(l.name) + ")";
    } else if (l.type == JointType::fixed) {
      s += "fixed(" + quoted(l.name) + ", " + quoted(l.parent) + ", " + pose_code(l.origin) + ")";
    } else {
      s += std::string(l.type == JointType::revolute ? "revolute(" : "prismatic(") +
           quoted(l.name) + ", " + quoted(l.parent) + ", " + pose_code(l.origin) + ", " +
           triple_code(l.axis) + ", ";
      append_number(s, l.lower);
      s += ", ";
      append_number(s, l.upper);
      s += ")";
    }
    if (!l.mimic.empty()) {
      s += ".mimics(" + quoted(l.mimic) + ", ";
      append_number(s, l.multiplier);
      s += ", ";
      append_number(s, l.offset);
      s += ")";
    }
    if (l.effort != 0.0 || l.velocity != 0.0 || l.armature != 0.0) {
      s += ".actuator(";
      append_number(s, l.effort);
      s += ", ";
      append_number(s, l.velocity);
      s += ", ";
      append_number(s, l.armature);
      s += ")";
    }
    if (l.mass != 0.0) {
      s += ".inertial(";
      append_number(s, l.mass);
      s += ", " + triple_code(l.com) + ")";
    }
  }
  s += ");\n\n/// Their collision shapes.\ninline constexpr auto shapes = topograsp::shapes(";
  for (std::size_t i = 0; i < hand.shapes.size(); ++i) {
    const ShapeSpec& sh = hand.shapes[i];
    s += i == 0 ? "\n    " : ",\n    ";
    s += "ShapeSpec{" + quoted(sh.link) + ", ShapeType::" + std::string(to_string(sh.type)) + ", " +
         pose_code(sh.pose) + ", " + triple_code(sh.size) + "}";
  }
  s += ");\n\n/// The file's named frames (MJCF sites).\ninline constexpr auto frames = "
       "topograsp::frames(";
  for (std::size_t i = 0; i < hand.frames.size(); ++i) {
    const FrameSpec& f = hand.frames[i];
    s += i == 0 ? "\n    " : ",\n    ";
    s += "frame(" + quoted(f.name) + ", " + quoted(f.link) + ", " + pose_code(f.offset) + ")";
  }
  s += ");\n\n}  // namespace " + std::string(ns) + "\n";
  return s;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The body tree of the MJCF reader of the hand import (internal): bodies, their joints, geoms
/// and sites, with default classes and the compiler's angle and inertia settings.
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <topograsp/core/constants.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/io/hand_import/common.hpp>
#include <topograsp/io/xml.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp::detail {

// An element's attributes by name (its own over its class's defaults).
using Attributes = std::map<std::string, std::string>;

// The state of an MJCF import: the compiler's settings, the default classes, the mesh assets and
// the hand read so far; read_body() reads the body tree.
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
      const TriangleMesh mesh = read_mesh(im, g, path);
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
    // A primitive's volume: its mass properties at unit density (geometry/mass_properties.hpp).
    return mass_of(shape_mass_properties(s, 1.0).mass, pose.translation());
  }
};

}  // namespace topograsp::detail

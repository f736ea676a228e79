// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The URDF reader of the hand import (internal): a <robot> document to an ImportedHand.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <topograsp/core/constants.hpp>
#include <topograsp/io/hand_import/common.hpp>
#include <topograsp/io/xml.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp::detail {

// The pose of the <origin> child of `parent` (the identity without one).
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

// Refuses links of the file that the import from `root` did not reach (out.links holds those it
// did), naming each and why: part of a cycle of joints, below one, or (without --root, whose
// purpose is to cut a hand off an arm) on no chain of joints from the root. A link the file
// leaves out this way would be missing from the model without a word.
inline void check_all_links_reached(const Importer& im, const XmlElement& robot,
                                    const std::map<std::string, const XmlElement*>& links,
                                    const std::map<std::string, const XmlElement*>& joint_of_child,
                                    const ImportedHand& out, const std::string& root,
                                    bool root_chosen) {
  if (out.links.size() == links.size()) return;
  std::string refused;
  for (const auto& entry : links) {
    const std::string& name = entry.first;
    if (std::any_of(out.links.begin(), out.links.end(),
                    [&](const LinkSpec& l) { return l.name.view() == name; }))
      continue;
    // Up the chain of parents until a link without one or a link seen before (a cycle).
    std::vector<std::string> chain{name};
    for (;;) {
      const auto j = joint_of_child.find(chain.back());
      if (j == joint_of_child.end()) break;
      const std::string& parent = *child(*j->second, "parent")->attribute("link");
      if (std::find(chain.begin(), chain.end(), parent) != chain.end()) {
        chain.push_back(parent);
        break;
      }
      chain.push_back(parent);
    }
    const bool cycle = joint_of_child.count(chain.back()) != 0;
    if (!cycle && root_chosen) continue;  // above or beside the chosen root: cut off
    refused += (refused.empty() ? "" : ", ") + name +
               (!cycle                 ? " (on no chain of joints from the root)"
                : chain.back() == name ? " (part of a cycle of joints)"
                                       : " (below a cycle of joints)");
  }
  if (!refused.empty())
    im.fail(robot, "links not reached from the root \"" + root + "\": " + refused);
}

// The links, shapes and notes of the URDF document doc, from options.root or its one root link.
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
    } else if (child(link, "collision") != nullptr) {
      // MJCF derives a body's mass from its geoms; URDF has no such rule, so say it.
      out.notes.push_back("the link " + std::string(l.name.view()) +
                          " has no <inertial>: it is massless (a hand description's "
                          "defaults.density gives it the mass of its collision shapes)");
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
  check_all_links_reached(im, robot, links, joint_of_child, out, root, !options.root.empty());
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

}  // namespace topograsp::detail

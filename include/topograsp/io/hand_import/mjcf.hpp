// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The MJCF reader of the hand import (internal): a <mujoco> document to an ImportedHand, its
/// compiler settings, assets, root body, couplings and actuators (the body tree:
/// hand_import/mjcf_body.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <topograsp/io/hand_import/common.hpp>
#include <topograsp/io/hand_import/mjcf_body.hpp>
#include <topograsp/io/xml.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp::detail {

// The links, shapes, frames and notes of the MJCF document doc, from options.root or the one
// top-level body of its worldbody.
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

}  // namespace topograsp::detail

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The check of an imported hand against what make_model() accepts (internal), so that a header
/// written from an import always compiles.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/io/hand_import/common.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp::detail {

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

}  // namespace topograsp::detail

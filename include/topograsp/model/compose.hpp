// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Compile-time compositions of models: a hand attached to a frame of an arm, a model on a free
/// 6-DOF base. The result goes through make_model() again, so it is checked like any model.
#pragma once

#include <topograsp/model/model.hpp>

namespace topograsp {

namespace detail {
template <std::size_t NL, std::size_t NS, std::size_t NF, std::size_t NH>
constexpr HandSpec<NH> hand_spec(const Model<NL, NS, NF, NH>& m) {
  HandSpec<NH> h;
  h.palm = m.palm_name;
  for (std::size_t i = 0; i < NH; ++i) h.fingers[i] = m.fingers[i].spec;
  return h;
}
}  // namespace detail

/// Attaches \p child by its root link to the frame (or link) \p at of \p parent, with the extra
/// transform \p mount. Links, shapes and frames are concatenated (names must stay unique); the
/// result is a hand if the child is (the parent must not be one), and the configuration is the
/// parent's entries followed by the child's.
template <std::size_t NL1, std::size_t NS1, std::size_t NF1, std::size_t NL2, std::size_t NS2,
          std::size_t NF2, std::size_t NH2>
[[nodiscard]] consteval Model<NL1 + NL2, NS1 + NS2, NF1 + NF2, NH2> attach(
    const Model<NL1, NS1, NF1, 0>& parent, Name at, const Model<NL2, NS2, NF2, NH2>& child,
    Pose mount = {}, Name name = {}) {
  std::array<LinkSpec, NL1 + NL2> l{};
  std::array<ShapeSpec, NS1 + NS2> s{};
  std::array<FrameSpec, NF1 + NF2> f{};
  for (std::size_t i = 0; i < NL1; ++i) l[i] = parent.links[i].spec;
  for (std::size_t i = 0; i < NL2; ++i) l[NL1 + i] = child.links[i].spec;
  for (std::size_t i = 0; i < NS1; ++i) s[i] = parent.shapes[i].spec;
  for (std::size_t i = 0; i < NS2; ++i) s[NS1 + i] = child.shapes[i].spec;
  for (std::size_t i = 0; i < NF1; ++i) f[i] = parent.frames[i].spec;
  for (std::size_t i = 0; i < NF2; ++i) f[NF1 + i] = child.frames[i].spec;
  // The child's root hangs from the frame's link at frame offset * mount * root origin.
  LinkSpec& root_link = l[NL1];
  const int fi = parent.find_frame(at.view());
  if (fi >= 0) {
    const Frame& fr = parent.frames[static_cast<std::size_t>(fi)];
    root_link.parent = fr.spec.link;
    root_link.origin = fr.spec.offset * mount * root_link.origin;
  } else {
    if (parent.find_link(at.view()) < 0) detail::model_error("attach: no such frame or link");
    root_link.parent = at;
    root_link.origin = mount * root_link.origin;
  }
  return make_model(name.empty() ? child.name : name, l, s, f, detail::hand_spec(child));
}

/// Limits of the free base's translations (m) and rotations (rad).
inline constexpr double free_base_reach = 10.0;
inline constexpr double free_base_turn = 2.0 * pi;

/// Puts \p m on a free 6-DOF base: three prismatic joints along the world x, y, z
/// ("base_x", "base_y", "base_z") then three revolute joints about z, y, x ("base_rz", "base_ry",
/// "base_rx", so the base orientation is Rz Ry Rx), then the model's root. The base entries come
/// first in the configuration.
template <std::size_t NL, std::size_t NS, std::size_t NF, std::size_t NH>
[[nodiscard]] consteval Model<NL + 6, NS, NF, NH> on_free_base(const Model<NL, NS, NF, NH>& m) {
  std::array<LinkSpec, NL + 6> l{};
  const double r = free_base_reach, t = free_base_turn;
  l[0] = prismatic("base_x", "", {}, {1.0, 0.0, 0.0}, -r, r);
  l[0].parent = Name{};
  l[1] = prismatic("base_y", "base_x", {}, {0.0, 1.0, 0.0}, -r, r);
  l[2] = prismatic("base_z", "base_y", {}, {0.0, 0.0, 1.0}, -r, r);
  l[3] = revolute("base_rz", "base_z", {}, {0.0, 0.0, 1.0}, -t, t);
  l[4] = revolute("base_ry", "base_rz", {}, {0.0, 1.0, 0.0}, -t, t);
  l[5] = revolute("base_rx", "base_ry", {}, {1.0, 0.0, 0.0}, -t, t);
  for (std::size_t i = 0; i < NL; ++i) l[6 + i] = m.links[i].spec;
  l[6].parent = "base_rx";
  std::array<ShapeSpec, NS> s{};
  std::array<FrameSpec, NF> f{};
  for (std::size_t i = 0; i < NS; ++i) s[i] = m.shapes[i].spec;
  for (std::size_t i = 0; i < NF; ++i) f[i] = m.frames[i].spec;
  return make_model(m.name, l, s, f, detail::hand_spec(m));
}

}  // namespace topograsp

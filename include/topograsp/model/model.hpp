// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Model: the checked, resolved description of a kinematic tree, a constexpr value of a
/// structural type (so it can be a template argument), built by make_model().
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include <topograsp/model/spec.hpp>

namespace topograsp {

/// How a joint axis is stored, so kinematics can skip the general rotation for the common axes.
enum class AxisKind : std::uint8_t { x, y, z, general };

/// A link of a checked model: its spec plus the resolved indices.
struct Link {
  LinkSpec spec;
  int parent = -1;  ///< index of the parent link, -1 for the root; always smaller than this index
  int q = -1;       ///< index of the configuration entry that drives the joint; -1 if fixed
  bool actuated = false;  ///< true if the joint owns entry q (false for fixed and mimic joints)
  std::array<double, 3> axis{0.0, 0.0, 0.0};  ///< unit axis in the link frame
  AxisKind axis_kind = AxisKind::general;     ///< x, y, z when axis is +-e_i (sign in axis)
  friend constexpr bool operator==(const Link&, const Link&) = default;
};

/// A joint on the path from a link to the root, with what a Jacobian column needs of it.
struct SupportJoint {
  int link = -1;  ///< the link whose joint this is (its world axis and origin are in the data)
  int q = -1;     ///< the configuration entry that drives the joint
  JointType type = JointType::revolute;  ///< revolute or prismatic (fixed joints are left out)
  /// d(joint value) / d q[q]: 1 for an actuated joint, the mimic multiplier for a mimic joint.
  double multiplier = 1.0;
  double offset = 0.0;  ///< the joint value is multiplier * q[q] + offset (0 unless mimic)
  friend constexpr bool operator==(const SupportJoint&, const SupportJoint&) = default;
};

/// The support of a link in a model of NL links: the joints that move it, which are its own joint
/// and those of its ancestors with fixed joints left out, the link's own first and the one
/// nearest the root last (the order of a walk up the tree, which is the order in which the
/// Jacobians add their columns). Iterate it with a range-for.
template <std::size_t NL>
struct Support {
  std::array<SupportJoint, NL> joints{};
  int size = 0;  ///< how many entries of joints are used

  [[nodiscard]] constexpr const SupportJoint* begin() const noexcept { return joints.data(); }
  [[nodiscard]] constexpr const SupportJoint* end() const noexcept { return joints.data() + size; }
  friend constexpr bool operator==(const Support&, const Support&) = default;
};

/// A shape of a checked model.
struct Shape {
  ShapeSpec spec;
  int link = -1;
  friend constexpr bool operator==(const Shape&, const Shape&) = default;
};

/// A frame of a checked model.
struct Frame {
  FrameSpec spec;
  int link = -1;
  friend constexpr bool operator==(const Frame&, const Frame&) = default;
};

/// A point fixed to a link: a joint origin or a frame origin.
struct LinkPoint {
  int link = -1;
  std::array<double, 3> offset{0.0, 0.0, 0.0};  ///< in the link frame
  friend constexpr bool operator==(const LinkPoint&, const LinkPoint&) = default;
};

/// A finger of a checked model: the points of its chain, base first.
struct Finger {
  FingerSpec spec;
  std::array<LinkPoint, max_finger_points> points{};
  int size = 0;  ///< how many entries of points are used
  friend constexpr bool operator==(const Finger&, const Finger&) = default;
};

/// A checked kinematic tree with NL links, NS shapes, NF frames and NH fingers.
///
/// Links are in topological order (a parent always comes before its children). The configuration
/// vector q has one entry per actuated joint, in link order; mimic joints follow their source.
/// Build one with make_model(); every field is public so that the type is structural.
template <std::size_t NL, std::size_t NS, std::size_t NF, std::size_t NH>
struct Model {
  static constexpr std::size_t n_links = NL;
  static constexpr std::size_t n_shapes = NS;
  static constexpr std::size_t n_frames = NF;
  static constexpr std::size_t n_fingers = NH;

  Name name;
  std::array<Link, NL> links{};
  std::array<Shape, NS> shapes{};
  std::array<Frame, NF> frames{};
  std::array<Finger, NH> fingers{};
  Name palm_name;    ///< the palm centre as written (a link or frame name); empty if not a hand
  LinkPoint palm{};  ///< the palm centre, resolved
  int thumb = -1;    ///< index of the thumb in fingers; -1 if not a hand
  int nq = 0;        ///< number of configuration entries (actuated joints)
  std::array<int, NL> q_link{};  ///< for each configuration entry, the link whose joint owns it
  /// The support of each link (the joints that move it), computed once by make_model().
  std::array<Support<NL>, NL> supports{};

  /// True if the model declares fingers (and so a thumb and a palm centre).
  [[nodiscard]] constexpr bool is_hand() const noexcept { return NH > 0; }

  /// Index of the link named \p n, or -1.
  [[nodiscard]] constexpr int find_link(std::string_view n) const noexcept {
    for (std::size_t i = 0; i < NL; ++i)
      if (links[i].spec.name.view() == n) return static_cast<int>(i);
    return -1;
  }
  /// Index of the frame named \p n, or -1.
  [[nodiscard]] constexpr int find_frame(std::string_view n) const noexcept {
    for (std::size_t i = 0; i < NF; ++i)
      if (frames[i].spec.name.view() == n) return static_cast<int>(i);
    return -1;
  }
  /// Index of the configuration entry of the joint named \p n, or -1 (fixed, mimic or unknown).
  [[nodiscard]] constexpr int find_joint(std::string_view n) const noexcept {
    const int l = find_link(n);
    return l >= 0 && links[static_cast<std::size_t>(l)].actuated
               ? links[static_cast<std::size_t>(l)].q
               : -1;
  }
  /// Index of the link named \p n; a compile error if there is none (use in constant expressions).
  [[nodiscard]] consteval int link(std::string_view n) const {
    const int i = find_link(n);
    if (i < 0) detail::model_error("no link of that name");
    return i;
  }
  /// Index of the frame named \p n; a compile error if there is none.
  [[nodiscard]] consteval int frame(std::string_view n) const {
    const int i = find_frame(n);
    if (i < 0) detail::model_error("no frame of that name");
    return i;
  }
  /// Index of the configuration entry of the actuated joint \p n; a compile error if there is none.
  [[nodiscard]] consteval int joint(std::string_view n) const {
    const int i = find_joint(n);
    if (i < 0) detail::model_error("no actuated joint of that name");
    return i;
  }
  /// The support of link \p l: the joints that move it, its own first, the root's last.
  [[nodiscard]] constexpr const Support<NL>& support(int l) const noexcept {
    return supports[static_cast<std::size_t>(l)];
  }
  /// The name of configuration entry \p i.
  [[nodiscard]] constexpr std::string_view joint_name(int i) const noexcept {
    return links[static_cast<std::size_t>(q_link[static_cast<std::size_t>(i)])].spec.name.view();
  }
  /// The spec of the joint that owns configuration entry \p i.
  [[nodiscard]] constexpr const LinkSpec& joint_spec(int i) const noexcept {
    return links[static_cast<std::size_t>(q_link[static_cast<std::size_t>(i)])].spec;
  }

  friend constexpr bool operator==(const Model&, const Model&) = default;
};

namespace detail {

template <std::size_t N>
constexpr int index_of(const std::array<LinkSpec, N>& l, const Name& n, std::size_t end) {
  for (std::size_t i = 0; i < end && i < N; ++i)
    if (l[i].name == n) return static_cast<int>(i);
  return -1;
}

constexpr double norm3(const std::array<double, 3>& a) {
  return cmath::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

}  // namespace detail

/// Checks and resolves a model. Called in a constant expression (it is consteval), a malformed
/// model does not compile; the error points at the check that failed, whose message says why:
/// "the first link must be the root", "parent is not an earlier link", "joint axis is zero",
/// "lower limit above upper limit", "duplicate name", "mimic of a missing joint",
/// "a hand needs a thumb", and the others below.
template <std::size_t NL, std::size_t NS, std::size_t NF, std::size_t NH>
[[nodiscard]] consteval Model<NL, NS, NF, NH> make_model(Name name,
                                                         const std::array<LinkSpec, NL>& links,
                                                         const std::array<ShapeSpec, NS>& shapes,
                                                         const std::array<FrameSpec, NF>& frames,
                                                         const HandSpec<NH>& hand) {
  static_assert(NL > 0, "a model needs at least one link");
  Model<NL, NS, NF, NH> m;
  m.name = name;
  // Links: order, parents, axes, limits, names.
  for (std::size_t i = 0; i < NL; ++i) {
    const LinkSpec& s = links[i];
    Link& l = m.links[i];
    l.spec = s;
    if (s.name.empty()) detail::model_error("a link has an empty name");
    if (detail::index_of(links, s.name, i) >= 0) detail::model_error("duplicate name");
    if (i == 0) {
      if (!s.parent.empty()) detail::model_error("the first link must be the root (no parent)");
    } else {
      if (s.parent.empty()) detail::model_error("only the first link may be a root");
      l.parent = detail::index_of(links, s.parent, i);
      if (l.parent < 0) detail::model_error("parent is not an earlier link");
    }
    if (!(s.mass >= 0.0 && s.mass < 1e6))
      detail::model_error("link mass must be finite and >= 0 (kg)");
    for (double c : s.com)
      if (!(c == c) || cmath::abs(c) > 1e6) detail::model_error("link com must be finite (m)");
    if (s.type == JointType::fixed) {
      if (s.effort != 0.0 || s.velocity != 0.0 || s.armature != 0.0)
        detail::model_error("a fixed joint has no actuator");
      if (!s.mimic.empty()) detail::model_error("a fixed joint cannot mimic");
      continue;
    }
    const double n = detail::norm3(s.axis);
    if (!(n > 1e-12)) detail::model_error("joint axis is zero");
    l.axis = {s.axis[0] / n, s.axis[1] / n, s.axis[2] / n};
    l.axis_kind = AxisKind::general;
    for (std::size_t k = 0; k < 3; ++k)
      if (cmath::abs(l.axis[k]) == 1.0) l.axis_kind = static_cast<AxisKind>(k);
    if (s.lower > s.upper) detail::model_error("lower limit above upper limit");
    if (!(s.effort >= 0.0 && s.effort < 1e9 && s.velocity >= 0.0 && s.velocity < 1e9 &&
          s.armature >= 0.0 && s.armature < 1e9))
      detail::model_error("effort, velocity and armature must be in [0, 1e9)");
    if (!s.mimic.empty() && (s.effort != 0.0 || s.velocity != 0.0 || s.armature != 0.0))
      detail::model_error("a mimic joint has no actuator of its own (give its source one)");
    if (s.closing != 0.0 && s.closing != 1.0 && s.closing != -1.0)
      detail::model_error("closing direction must be +1, -1 or 0");
    if (s.mimic.empty()) {
      l.actuated = true;
      l.q = m.nq;
      m.q_link[static_cast<std::size_t>(m.nq)] = static_cast<int>(i);
      ++m.nq;
    }
  }
  // Mimic joints take the configuration entry of their source.
  for (std::size_t i = 0; i < NL; ++i) {
    Link& l = m.links[i];
    if (l.spec.type == JointType::fixed || l.spec.mimic.empty()) continue;
    const int src = detail::index_of(links, l.spec.mimic, NL);
    if (src < 0) detail::model_error("mimic of a missing joint");
    const Link& s = m.links[static_cast<std::size_t>(src)];
    if (!s.actuated) detail::model_error("mimic of a joint that is fixed or itself a mimic");
    l.q = s.q;
  }
  // Supports: a link's own joint (unless fixed), then its parent's support. This is the one
  // walk up the tree; Jacobians, gradients and the "links moved by a joint" masks read it.
  for (std::size_t i = 0; i < NL; ++i) {
    const Link& l = m.links[i];
    Support<NL>& s = m.supports[i];
    if (l.spec.type != JointType::fixed)
      s.joints[static_cast<std::size_t>(s.size++)] = {static_cast<int>(i), l.q, l.spec.type,
                                                      l.actuated ? 1.0 : l.spec.multiplier,
                                                      l.actuated ? 0.0 : l.spec.offset};
    if (l.parent < 0) continue;
    for (const SupportJoint& j : m.supports[static_cast<std::size_t>(l.parent)])
      s.joints[static_cast<std::size_t>(s.size++)] = j;
  }
  // Shapes.
  for (std::size_t i = 0; i < NS; ++i) {
    m.shapes[i].spec = shapes[i];
    m.shapes[i].link = detail::index_of(links, shapes[i].link, NL);
    if (m.shapes[i].link < 0) detail::model_error("a shape is on an unknown link");
    const auto& sz = shapes[i].size;
    const bool ok = shapes[i].type == ShapeType::box ? (sz[0] > 0.0 && sz[1] > 0.0 && sz[2] > 0.0)
                    : shapes[i].type == ShapeType::sphere ? sz[0] > 0.0
                                                          : (sz[0] > 0.0 && sz[1] >= 0.0);
    if (!ok) detail::model_error("a shape has a non-positive size");
  }
  // Frames.
  for (std::size_t i = 0; i < NF; ++i) {
    m.frames[i].spec = frames[i];
    m.frames[i].link = detail::index_of(links, frames[i].link, NL);
    if (m.frames[i].link < 0) detail::model_error("a frame is on an unknown link");
    if (frames[i].name.empty()) detail::model_error("a frame has an empty name");
    if (detail::index_of(links, frames[i].name, NL) >= 0) detail::model_error("duplicate name");
    for (std::size_t j = 0; j < i; ++j)
      if (frames[j].name == frames[i].name) detail::model_error("duplicate name");
  }
  // The hand: palm centre, fingers, exactly one thumb.
  const auto resolve_point = [&](const Name& n) {
    LinkPoint p;
    for (std::size_t j = 0; j < NF; ++j)
      if (m.frames[j].spec.name == n) {
        p.link = m.frames[j].link;
        p.offset = m.frames[j].spec.offset.p;
        return p;
      }
    p.link = detail::index_of(links, n, NL);
    if (p.link < 0) detail::model_error("a finger or palm point names no link or frame");
    return p;
  };
  if constexpr (NH > 0) {
    if (NH < 2) detail::model_error("a hand needs at least two fingers, one of them the thumb");
    m.palm_name = hand.palm;
    m.palm = resolve_point(hand.palm);
    for (std::size_t f = 0; f < NH; ++f) {
      Finger& fi = m.fingers[f];
      fi.spec = hand.fingers[f];
      for (std::size_t j = 0; j < f; ++j)
        if (hand.fingers[j].name == fi.spec.name) detail::model_error("duplicate name");
      for (std::size_t k = 0; k < max_finger_points && !fi.spec.chain[k].empty(); ++k) {
        fi.points[k] = resolve_point(fi.spec.chain[k]);
        ++fi.size;
      }
      if (fi.size < 1) detail::model_error("a finger lists no points");
      if (fi.spec.thumb) {
        if (m.thumb >= 0) detail::model_error("a hand has more than one thumb");
        m.thumb = static_cast<int>(f);
      }
    }
    if (m.thumb < 0) detail::model_error("a hand needs a thumb");
  }
  return m;
}

/// make_model() for a model that is not a hand (an arm, a base, a tool).
template <std::size_t NL, std::size_t NS, std::size_t NF>
[[nodiscard]] consteval Model<NL, NS, NF, 0> make_model(Name name,
                                                        const std::array<LinkSpec, NL>& links,
                                                        const std::array<ShapeSpec, NS>& shapes,
                                                        const std::array<FrameSpec, NF>& frames) {
  return make_model(name, links, shapes, frames, HandSpec<0>{});
}

/// True for the specialisations of Model.
template <class T>
inline constexpr bool is_model = false;
template <std::size_t NL, std::size_t NS, std::size_t NF, std::size_t NH>
inline constexpr bool is_model<Model<NL, NS, NF, NH>> = true;

/// A kinematic model type (a specialisation of Model).
template <class T>
concept KinematicModel = is_model<std::remove_cvref_t<T>>;

/// A kinematic model type that describes a hand (fingers, a thumb, a palm centre).
template <class T>
concept HandModel = KinematicModel<T> && (std::remove_cvref_t<T>::n_fingers >= 2);

}  // namespace topograsp

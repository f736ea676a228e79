// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The pieces a model is written from: links with their joints, collision shapes, named frames and
/// fingers. All are literal types built by constexpr functions; make_model() (model.hpp) checks
/// them and resolves the names.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string_view>

#include <topograsp/core/pose.hpp>
#include <topograsp/model/name.hpp>

namespace topograsp {

/// How a link moves relative to its parent.
enum class JointType : std::uint8_t {
  fixed,      ///< rigidly attached
  revolute,   ///< rotates by the joint value (rad) about the axis
  prismatic,  ///< slides by the joint value (m) along the axis
};

/// One link and the joint that connects it to its parent; the link and its joint share a name.
/// The link frame is parent_frame * origin * motion(value), where motion is a rotation about (or a
/// translation along) \c axis, given in the link frame.
struct LinkSpec {
  Name name;
  Name parent;  ///< empty for the root link
  Pose origin;  ///< the joint frame in the parent link's frame at value 0
  JointType type = JointType::fixed;
  std::array<double, 3> axis{0.0, 0.0, 0.0};
  double lower = 0.0;  ///< joint limits (rad or m)
  double upper = 0.0;
  Name mimic;               ///< if not empty: value = multiplier * value(mimic) + offset
  double multiplier = 1.0;  ///< only for mimic joints
  double offset = 0.0;      ///< only for mimic joints
  double closing =
      0.0;  ///< +1: increasing the value closes the hand, -1: decreasing does, 0: neither
  /// The joint's actuator (actuated joints only; a mimic joint is driven through its source):
  /// the largest torque (N m, revolute) or force (N, prismatic) it gives; 0 if not given, and
  /// then the joint cannot be simulated with motors (HandScene says so).
  double effort = 0.0;
  /// The actuator's speed limit (rad/s or m/s); 0 if not given.
  double velocity = 0.0;
  /// The actuator's reflected rotor inertia (kg m^2 or kg), added to the joint's inertia as
  /// MuJoCo's joint `armature` is; 0 if not given.
  double armature = 0.0;
  /// The link's mass (kg); 0 if not given (a massless link).
  double mass = 0.0;
  /// The link's centre of mass in the link frame (m).
  std::array<double, 3> com{0.0, 0.0, 0.0};

  /// This joint with its closing direction set (+1, -1 or 0).
  [[nodiscard]] constexpr LinkSpec closes(double direction) const noexcept {
    LinkSpec out = *this;
    out.closing = direction;
    return out;
  }
  /// This joint driven by an actuator of at most \p max_effort (N m or N), at most
  /// \p max_velocity (rad/s or m/s), with reflected rotor inertia \p rotor_inertia.
  [[nodiscard]] constexpr LinkSpec actuator(double max_effort, double max_velocity,
                                            double rotor_inertia = 0.0) const noexcept {
    LinkSpec out = *this;
    out.effort = max_effort;
    out.velocity = max_velocity;
    out.armature = rotor_inertia;
    return out;
  }
  /// This link with mass \p link_mass (kg) whose centre is at \p centre (link frame, m).
  [[nodiscard]] constexpr LinkSpec inertial(double link_mass,
                                            std::array<double, 3> centre) const noexcept {
    LinkSpec out = *this;
    out.mass = link_mass;
    out.com = centre;
    return out;
  }

  /// This joint driven by joint \p source: value = multiplier * value(source) + offset.
  [[nodiscard]] constexpr LinkSpec mimics(Name source, double mult = 1.0,
                                          double off = 0.0) const noexcept {
    LinkSpec out = *this;
    out.mimic = source;
    out.multiplier = mult;
    out.offset = off;
    return out;
  }
  friend constexpr bool operator==(const LinkSpec&, const LinkSpec&) = default;
};

/// The root link of a model (no parent, no joint).
[[nodiscard]] constexpr LinkSpec root(Name name) noexcept {
  LinkSpec l;
  l.name = name;
  return l;
}

/// A link rigidly attached to \p parent at \p origin.
[[nodiscard]] constexpr LinkSpec fixed(Name name, Name parent, Pose origin) noexcept {
  LinkSpec l;
  l.name = name;
  l.parent = parent;
  l.origin = origin;
  return l;
}

/// A link on a revolute joint about \p axis with limits [lower, upper] (rad).
[[nodiscard]] constexpr LinkSpec revolute(Name name, Name parent, Pose origin,
                                          std::array<double, 3> axis, double lower,
                                          double upper) noexcept {
  LinkSpec l = fixed(name, parent, origin);
  l.type = JointType::revolute;
  l.axis = axis;
  l.lower = lower;
  l.upper = upper;
  return l;
}

/// A link on a prismatic joint along \p axis with limits [lower, upper] (m).
[[nodiscard]] constexpr LinkSpec prismatic(Name name, Name parent, Pose origin,
                                           std::array<double, 3> axis, double lower,
                                           double upper) noexcept {
  LinkSpec l = revolute(name, parent, origin, axis, lower, upper);
  l.type = JointType::prismatic;
  return l;
}

/// The kinds of collision shape. Every shape is centred at its pose; capsules and cylinders run
/// along the pose's z axis.
enum class ShapeType : std::uint8_t {
  sphere,    ///< size = {radius, -, -}
  capsule,   ///< size = {radius, half length of the segment, -}
  box,       ///< size = half extents {x, y, z}
  cylinder,  ///< size = {radius, half height, -}
};

/// The shape type's name ("sphere", "capsule", "box", "cylinder"; MJCF's geom types use the same).
[[nodiscard]] constexpr std::string_view to_string(ShapeType t) noexcept {
  switch (t) {
    case ShapeType::sphere:
      return "sphere";
    case ShapeType::capsule:
      return "capsule";
    case ShapeType::box:
      return "box";
    case ShapeType::cylinder:
      return "cylinder";
  }
  return "unknown";
}

/// A collision shape fixed to a link.
struct ShapeSpec {
  Name link;
  ShapeType type = ShapeType::sphere;
  Pose pose;  ///< in the link frame
  std::array<double, 3> size{0.0, 0.0, 0.0};
  friend constexpr bool operator==(const ShapeSpec&, const ShapeSpec&) = default;
};

/// A sphere of \p radius centred at \p centre in the frame of \p link.
[[nodiscard]] constexpr ShapeSpec sphere(Name link, std::array<double, 3> centre,
                                         double radius) noexcept {
  return {link, ShapeType::sphere, at(centre[0], centre[1], centre[2]), {radius, 0.0, 0.0}};
}

/// A box with half extents \p half at \p pose in the frame of \p link.
[[nodiscard]] constexpr ShapeSpec box(Name link, Pose pose, std::array<double, 3> half) noexcept {
  return {link, ShapeType::box, pose, half};
}

/// A cylinder of \p radius and height 2 * half_height along the z axis of \p pose.
[[nodiscard]] constexpr ShapeSpec cylinder(Name link, Pose pose, double radius,
                                           double half_height) noexcept {
  return {link, ShapeType::cylinder, pose, {radius, half_height, 0.0}};
}

/// The pose whose origin is the midpoint of a and b and whose z axis points from a to b.
[[nodiscard]] constexpr Pose segment_pose(std::array<double, 3> a,
                                          std::array<double, 3> b) noexcept {
  const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  const double len = cmath::sqrt(dx * dx + dy * dy + dz * dz);
  Pose pose = at(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]));
  if (!(len > 0.0)) return pose;
  const double ux = dx / len, uy = dy / len, uz = dz / len;
  // Rotate z onto u about the axis z x u = (-uy, ux, 0).
  const double s = cmath::sqrt(ux * ux + uy * uy);
  if (s < 1e-12) return uz > 0.0 ? pose : pose * rotation_axis_angle(1.0, 0.0, 0.0, pi);
  // Rodrigues with cos(angle) = uz and sin(angle) = s about the unit axis k.
  const double kx = -uy / s, ky = ux / s, c = uz, t = 1.0 - c;
  Pose rot;
  rot.R = {t * kx * kx + c, t * kx * ky, ky * s, t * kx * ky, t * ky * ky + c, -kx * s,
           -ky * s,         kx * s,      c};
  return pose * rot;
}

/// A capsule of \p radius around the segment from \p a to \p b, in the frame of \p link.
[[nodiscard]] constexpr ShapeSpec capsule(Name link, std::array<double, 3> a,
                                          std::array<double, 3> b, double radius) noexcept {
  const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  return {link,
          ShapeType::capsule,
          segment_pose(a, b),
          {radius, 0.5 * cmath::sqrt(dx * dx + dy * dy + dz * dz), 0.0}};
}

/// A named frame fixed to a link: fingertips, the palm centre, a grasp centre, a flange.
struct FrameSpec {
  Name name;
  Name link;
  Pose offset;  ///< in the link frame
  friend constexpr bool operator==(const FrameSpec&, const FrameSpec&) = default;
};

/// The frame \p name at \p offset in the frame of \p link.
[[nodiscard]] constexpr FrameSpec frame(Name name, Name link, Pose offset = {}) noexcept {
  return {name, link, offset};
}

/// The most points a finger chain may list.
inline constexpr std::size_t max_finger_points = 6;

/// A finger: the points its hand curve passes, from the base (next to the palm) to the tip, each
/// the name of a link (its joint's origin) or of a frame.
struct FingerSpec {
  Name name;
  std::array<Name, max_finger_points> chain{};
  bool thumb = false;
  friend constexpr bool operator==(const FingerSpec&, const FingerSpec&) = default;
};

/// A finger through the named links or frames, base first, tip last.
[[nodiscard]] constexpr FingerSpec finger(Name name,
                                          std::array<Name, max_finger_points> chain) noexcept {
  return {name, chain, false};
}

/// The thumb: the finger the hand curves start from.
[[nodiscard]] constexpr FingerSpec thumb(Name name,
                                         std::array<Name, max_finger_points> chain) noexcept {
  return {name, chain, true};
}

/// The hand part of a model: the palm centre (a link or frame name) and the fingers.
template <std::size_t NH>
struct HandSpec {
  Name palm;
  std::array<FingerSpec, NH> fingers{};
};

/// Collects links into an array for make_model().
template <class... L>
[[nodiscard]] constexpr std::array<LinkSpec, sizeof...(L)> links(L... l) noexcept {
  return {LinkSpec(l)...};
}
/// Collects shapes into an array for make_model().
template <class... S>
[[nodiscard]] constexpr std::array<ShapeSpec, sizeof...(S)> shapes(S... s) noexcept {
  return {ShapeSpec(s)...};
}
/// Collects frames into an array for make_model().
template <class... F>
[[nodiscard]] constexpr std::array<FrameSpec, sizeof...(F)> frames(F... f) noexcept {
  return {FrameSpec(f)...};
}
/// The arrays \p a and \p b as one (an imported hand's frames and the fingertips added to them).
template <class T, std::size_t N, std::size_t M>
[[nodiscard]] constexpr std::array<T, N + M> join(const std::array<T, N>& a,
                                                  const std::array<T, M>& b) noexcept {
  std::array<T, N + M> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = a[i];
  for (std::size_t i = 0; i < M; ++i) out[N + i] = b[i];
  return out;
}

/// A joint's closing direction by the joint's (its link's) name, for with_closing().
struct Closing {
  Name joint;
  double direction = 1.0;  ///< +1: increasing the value closes the hand, -1: decreasing does
};

/// \p links with the closing directions \p closing set (an imported hand, whose file cannot say
/// which way its joints close). A name that is no link of \p links does not compile.
template <std::size_t N>
[[nodiscard]] constexpr std::array<LinkSpec, N> with_closing(
    std::array<LinkSpec, N> links, std::initializer_list<Closing> closing) noexcept {
  for (const Closing& c : closing) {
    bool found = false;
    for (LinkSpec& l : links)
      if (l.name == c.joint) {
        l.closing = c.direction;
        found = true;
      }
    if (!found) detail::model_error("with_closing: no link of that name");
  }
  return links;
}

/// Declares a hand: its palm centre and its fingers (exactly one of them the thumb).
template <class... F>
[[nodiscard]] constexpr HandSpec<sizeof...(F)> hand(Name palm, F... f) noexcept {
  return {palm, {FingerSpec(f)...}};
}

}  // namespace topograsp

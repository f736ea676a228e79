// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// GraspObject: an everyday object made of primitives, with its mass and its box decomposition
/// (for box-based grasp hypotheses); and the built-in objects.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/composite.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {

/// An oriented box of an object's decomposition (object frame), as BADGr uses them.
struct GraspBox {
  Pose pose;                     ///< centre and axes of the box in the object frame
  std::array<double, 3> half{};  ///< half extents along the box axes (m)
};

/// A rigid object to grasp: primitives in the object frame, a total mass spread uniformly over
/// their volume, a friction coefficient, and the boxes that approximate its parts.
struct GraspObject {
  std::string name;
  std::vector<ShapeSpec> parts;  ///< the object's shapes (ShapeSpec::link unused), object frame
  double mass = 0.0;             ///< kg
  double friction = 0.8;         ///< Coulomb coefficient against a hand
  std::vector<GraspBox> boxes;   ///< the box decomposition, object frame

  /// The object placed at \p T_world_object, as a geometry Composite (world frame).
  [[nodiscard]] Composite composite(
      const Eigen::Isometry3d& T_world_object = Eigen::Isometry3d::Identity()) const {
    std::vector<Primitive> prims;
    prims.reserve(parts.size());
    const Mat3 R = T_world_object.linear();
    const Vec3 p = T_world_object.translation();
    for (const ShapeSpec& s : parts) prims.push_back(Primitive::from_spec(s, R, p));
    return Composite(std::move(prims));
  }

  /// The centre of mass in the object frame (the volume-weighted centroid of the parts).
  [[nodiscard]] Vec3 centre_of_mass() const { return composite().centroid(); }

  /// Throws topograsp::invalid_argument naming the object unless it has parts, a finite positive
  /// mass and friction, and valid shapes.
  void validate() const {
    if (parts.empty()) detail::throw_invalid_argument(name, "an object needs at least one part");
    require_positive(mass, name + ".mass");
    require_positive(friction, name + ".friction");
    (void)composite();  // checks every part
    for (const GraspBox& b : boxes)
      for (const double h : b.half) require_positive(h, name + ".boxes");
  }
};

namespace objects {

namespace detail {
// A box of the decomposition around a primitive shape: its bounding box in the object frame.
inline GraspBox box_of(const ShapeSpec& s) {
  GraspBox b;
  b.pose = s.pose;
  switch (s.type) {
    case ShapeType::sphere:
      b.half = {s.size[0], s.size[0], s.size[0]};
      break;
    case ShapeType::box:
      b.half = s.size;
      break;
    case ShapeType::capsule:
      b.half = {s.size[0], s.size[0], s.size[1] + s.size[0]};
      break;
    case ShapeType::cylinder:
      b.half = {s.size[0], s.size[0], s.size[1]};
      break;
  }
  return b;
}
// Splits a box along its longest axis into equal pieces no longer than max_length, as BADGr's
// fit-and-split decomposes long parts (a hand grasps a part of a handle, not all of it).
inline void split_box(const GraspBox& b, double max_length, std::vector<GraspBox>& out) {
  std::size_t axis = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (b.half[k] > b.half[axis]) axis = k;
  const int n = static_cast<int>(std::ceil(2.0 * b.half[axis] / max_length - 1e-9));
  if (n <= 1) {
    out.push_back(b);
    return;
  }
  const Vec3 dir = b.pose.rotation().col(static_cast<Eigen::Index>(axis));
  for (int i = 0; i < n; ++i) {
    GraspBox piece = b;
    piece.half[axis] = b.half[axis] / n;
    const Vec3 centre = b.pose.translation() + ((2.0 * i + 1.0) / n - 1.0) * b.half[axis] * dir;
    piece.pose.p = {centre.x(), centre.y(), centre.z()};
    out.push_back(piece);
  }
}
/// Parts longer than this are split into boxes for the hypotheses (m).
inline constexpr double max_box_length = 0.12;
inline GraspObject make(std::string name, std::vector<ShapeSpec> parts, double mass,
                        double friction) {
  GraspObject o{std::move(name), std::move(parts), mass, friction, {}};
  for (const ShapeSpec& s : o.parts) split_box(box_of(s), max_box_length, o.boxes);
  return o;
}
}  // namespace detail

/// A 0.5 l plastic bottle, full: body r 0.032 m, 0.17 m tall; shoulder r 0.022 m; neck r 0.014 m;
/// 0.23 m in all, 0.55 kg. Standing on its base at the origin, axis +z.
inline GraspObject bottle() {
  return detail::make(
      "bottle",
      {cylinder("", at(0, 0, 0.085), 0.032, 0.085), cylinder("", at(0, 0, 0.185), 0.022, 0.015),
       cylinder("", at(0, 0, 0.215), 0.014, 0.015)},
      0.55, 0.8);
}

/// A claw hammer: a wooden handle r 0.014 m, 0.28 m long along x, and a steel head 0.11 m long
/// along y, 0.026 x 0.032 m in section, at the handle's end; 0.6 kg.
inline GraspObject hammer() {
  return detail::make("hammer",
                      {cylinder("", at(0, 0, 0).rpy(0, pi / 2, 0), 0.014, 0.14),
                       box("", at(0.153, 0, 0), {0.016, 0.055, 0.013})},
                      0.6, 0.8);
}

/// A mug: a cylindrical cup r 0.041 m, 0.095 m tall, and a handle (a capsule loop approximated by
/// a vertical capsule and two short arms) on +x; 0.35 kg.
inline GraspObject mug() {
  return detail::make("mug",
                      {cylinder("", at(0, 0, 0.0475), 0.041, 0.0475),
                       capsule("", {0.068, 0, 0.025}, {0.068, 0, 0.075}, 0.007),
                       capsule("", {0.04, 0, 0.08}, {0.068, 0, 0.075}, 0.007),
                       capsule("", {0.04, 0, 0.02}, {0.068, 0, 0.025}, 0.007)},
                      0.35, 0.7);
}

/// A cereal-size box 0.19 x 0.07 x 0.27 m, 0.45 kg.
inline GraspObject box() {
  return detail::make("box", {topograsp::box("", at(0, 0, 0.135), {0.095, 0.035, 0.135})}, 0.45,
                      0.6);
}

/// A ball r 0.045 m (a tennis-ball-sized ball, heavier), 0.2 kg.
inline GraspObject ball() {
  return detail::make("ball", {sphere("", {0, 0, 0.045}, 0.045)}, 0.2, 0.9);
}

/// A 0.33 l drink can r 0.033 m, 0.115 m tall, full: 0.37 kg.
inline GraspObject can() {
  return detail::make("can", {cylinder("", at(0, 0, 0.0575), 0.033, 0.0575)}, 0.37, 0.6);
}

/// The names of the built-in objects; the paper's are "hammer" and "bottle".
inline std::vector<std::string> names() {
  return {"hammer", "bottle", "mug", "box", "ball", "can"};
}

/// The built-in object called \p name, or nothing.
inline std::optional<GraspObject> find(std::string_view name) {
  if (name == "hammer") return hammer();
  if (name == "bottle") return bottle();
  if (name == "mug") return mug();
  if (name == "box") return box();
  if (name == "ball") return ball();
  if (name == "can") return can();
  return std::nullopt;
}

}  // namespace objects

}  // namespace topograsp

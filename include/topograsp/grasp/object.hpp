// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// GraspObject: an everyday object made of primitives, with its mass and its box decomposition
/// (for box-based grasp hypotheses); and the built-in objects.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/composite.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {

/// An oriented box of an object's decomposition (object frame), as BADGr uses them.
struct GraspBox {
  Pose pose;                     ///< centre and axes of the box in the object frame
  std::array<double, 3> half{};  ///< half extents along the box axes (m)
};

/// What an object's surface is made of, for friction against a hand (friction_coefficient()).
enum class Surface : std::uint8_t {
  steel,
  wood,
  glass,
  pet,
  ceramic,
  aluminium,
  cardboard,
  rubber
};

/// The name of a surface ("steel", "wood", "glass", "pet", "ceramic", "aluminium", "cardboard",
/// "rubber").
[[nodiscard]] constexpr std::string_view to_string(Surface s) noexcept {
  switch (s) {
    case Surface::steel:
      return "steel";
    case Surface::wood:
      return "wood";
    case Surface::glass:
      return "glass";
    case Surface::pet:
      return "pet";
    case Surface::ceramic:
      return "ceramic";
    case Surface::aluminium:
      return "aluminium";
    case Surface::cardboard:
      return "cardboard";
    case Surface::rubber:
      return "rubber";
  }
  return "?";
}

/// The contact surface of a hand's links.
enum class HandSurface : std::uint8_t {
  human_skin,  ///< the glabrous skin of finger pads and palm
  sdh_pad,     ///< the SDH's elastomer-covered tactile pads (treated as rubber)
  barrett,     ///< the BarrettHand's bare finger links (treated as aluminium)
};

/// The name of a hand surface ("human_skin", "sdh_pad", "barrett").
[[nodiscard]] constexpr std::string_view to_string(HandSurface h) noexcept {
  switch (h) {
    case HandSurface::human_skin:
      return "human_skin";
    case HandSurface::sdh_pad:
      return "sdh_pad";
    case HandSurface::barrett:
      return "barrett";
  }
  return "?";
}

/// The Coulomb friction coefficient of hand surface \p hand on object surface \p object: the
/// table of docs/objects.md, each row with its source (skin: Buchholz, Frederick and Armstrong
/// 1988; Seo and Armstrong 2009; rubber and metal: engineering friction tables). Dry, clean
/// surfaces; one value per pair (no static/kinetic distinction: the stepper has one coefficient).
/// Every entry is in (0, 2); both enums are closed, so there is no bad input.
[[nodiscard]] constexpr double friction_coefficient(HandSurface hand, Surface object) noexcept {
  // Columns: steel, wood, glass, pet, ceramic, aluminium, cardboard, rubber.
  constexpr double skin[8] = {0.5, 0.6, 0.6, 0.5, 0.6, 0.5, 0.35, 0.9};
  constexpr double sdh[8] = {0.8, 0.8, 0.9, 0.8, 0.9, 0.8, 0.6, 1.16};
  constexpr double barrett[8] = {0.5, 0.45, 0.5, 0.3, 0.5, 0.6, 0.4, 0.8};
  const auto k = static_cast<std::size_t>(object);
  switch (hand) {
    case HandSurface::human_skin:
      return skin[k];
    case HandSurface::sdh_pad:
      return sdh[k];
    case HandSurface::barrett:
      return barrett[k];
  }
  return skin[k];
}

/// A material of an object's part: its name, the density of the solid material (kg/m^3), its
/// surface for friction, and where the density comes from (docs/objects.md).
struct Material {
  std::string_view name;
  double density = 0.0;  ///< kg/m^3 of the solid material
  Surface surface = Surface::steel;
  std::string_view source;
};

/// The materials of the built-in objects (densities: docs/objects.md gives each source).
namespace materials {
inline constexpr Material steel{"steel", 7860.0, Surface::steel,
                                "LUST CDA3000 Engineering Guide, Table 7.23 (steel 7860)"};
inline constexpr Material hickory{"hickory", 800.0, Surface::wood,
                                  "USDA Wood Handbook FPL-GTR-190 (2010), Table 5-3a: shagbark "
                                  "hickory, specific gravity 0.72, at 12 % moisture"};
inline constexpr Material pet{"PET", 1380.0, Surface::pet,
                              "polyethylene terephthalate, 1.38 g/cm^3 (polymer handbooks)"};
inline constexpr Material water{"water", 1000.0, Surface::pet, "water at 4-20 C"};
inline constexpr Material ceramic{"stoneware", 2400.0, Surface::ceramic,
                                  "glazed stoneware/porcelain, 2.3-2.5 g/cm^3"};
inline constexpr Material aluminium{"aluminium", 2700.0, Surface::aluminium,
                                    "LUST CDA3000 Engineering Guide, Table 7.23 (aluminium 2700)"};
inline constexpr Material cardboard{"paperboard", 700.0, Surface::cardboard,
                                    "folding boxboard, about 0.7 g/cm^3"};
inline constexpr Material rubber{"rubber", 1100.0, Surface::rubber,
                                 "filled natural rubber compound, 1.1 g/cm^3"};
}  // namespace materials

/// A rigid object to grasp: primitives in the object frame, each of a material with an effective
/// density (a hollow part or a part with contents, modelled as a solid primitive, has the real
/// mass over the primitive's volume: docs/objects.md), its total mass, and the boxes that
/// approximate its parts.
struct GraspObject {
  std::string name;
  std::vector<ShapeSpec> parts;     ///< the object's shapes (ShapeSpec::link unused), object frame
  double mass = 0.0;                ///< kg, the sum of the parts' density times volume
  std::vector<GraspBox> boxes;      ///< the box decomposition, object frame
  std::vector<Material> materials;  ///< one per part: what its surface and body are made of
  std::vector<double> densities;    ///< one per part: its effective density (kg/m^3)
  /// The mass properties (object frame) when the parts only approximate the object: a mesh
  /// object's boxes (mesh_object()) stand in for its surface, its closed mesh gives its mass,
  /// centre of mass and inertia. Empty for an object made of its parts.
  std::optional<MassProperties<double>> inertial{};

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

  /// The centre of mass in the object frame: the inertial's when given, else the parts weighted by
  /// density times volume (the volume-weighted centroid when no densities are given). Throws as
  /// validate() for a bad object.
  [[nodiscard]] Vec3 centre_of_mass() const {
    if (inertial) return inertial->com;
    if (densities.empty()) return composite().centroid();
    validate();
    const MassProperties<double> mp = body_mass_properties<double>(parts, 0.0, 0.0, densities);
    return mp.com;
  }

  /// The Coulomb friction coefficient of each part against a hand of surface \p hand
  /// (friction_coefficient() of the part's material); empty when the object has no materials.
  [[nodiscard]] std::vector<double> part_friction(HandSurface hand) const {
    std::vector<double> mu;
    mu.reserve(materials.size());
    for (const Material& m : materials) mu.push_back(friction_coefficient(hand, m.surface));
    return mu;
  }

  /// Throws topograsp::invalid_argument naming the object unless it has parts, a finite positive
  /// mass, valid shapes, and either no materials and densities or one of each per part with a
  /// positive finite density ("<name>.densities[i]"), and an inertial, if any, of the object's
  /// mass ("<name>.inertial.mass"; the scene checks the rest of it, HandScene).
  void validate() const {
    if (parts.empty()) detail::throw_invalid_argument(name, "an object needs at least one part");
    require_positive(mass, name + ".mass");
    (void)composite();  // checks every part
    for (const GraspBox& b : boxes)
      for (const double h : b.half) require_positive(h, name + ".boxes");
    if (materials.size() != densities.size() ||
        (!materials.empty() && materials.size() != parts.size()))
      detail::throw_invalid_argument(name + ".materials",
                                     "expected one material and one density per part (" +
                                         std::to_string(parts.size()) + "), got " +
                                         std::to_string(materials.size()) + " and " +
                                         std::to_string(densities.size()));
    for (std::size_t i = 0; i < densities.size(); ++i)
      require_positive(densities[i], name + ".densities[" + std::to_string(i) + "]");
    if (inertial && !(std::abs(inertial->mass - mass) <= 1e-9 * mass))
      detail::throw_invalid_argument(name + ".inertial.mass",
                                     "expected the object's mass " + std::to_string(mass) +
                                         " kg, got " + std::to_string(inertial->mass));
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
/// One part of a built-in object: its shape, its material and its effective density (kg/m^3;
/// 0 = the material's own density, for a solid part).
struct Part {
  ShapeSpec shape;
  Material material;
  double density = 0.0;
};
inline GraspObject make(std::string name, const std::vector<Part>& parts) {
  GraspObject o;
  o.name = std::move(name);
  for (const Part& p : parts) {
    o.parts.push_back(p.shape);
    o.materials.push_back(p.material);
    o.densities.push_back(p.density > 0.0 ? p.density : p.material.density);
  }
  o.mass = body_mass_properties<double>(o.parts, 0.0, 0.0, o.densities).mass;
  for (const ShapeSpec& s : o.parts) split_box(box_of(s), max_box_length, o.boxes);
  return o;
}
// The volume of shape s (m^3): the mass of density 1.
inline double volume(const ShapeSpec& s) { return shape_mass_properties<double>(s, 1.0).mass; }
}  // namespace detail

/// A 0.5 l PET drink bottle, full of water (the paper's bottle is most likely a full plastic drink
/// bottle): body r 0.032 m, 0.17 m tall; shoulder r 0.022 m; neck r 0.014 m; 0.23 m in all.
/// 0.5 kg of water and 15 g of PET fill the body and shoulder (effective density 869 kg/m^3); the
/// neck holds air, the cap and the PET of the neck, 5 g. 0.52 kg in all. Standing on its base at
/// the origin, axis +z. docs/objects.md.
inline GraspObject bottle() {
  const ShapeSpec body = cylinder("", at(0, 0, 0.085), 0.032, 0.085);
  const ShapeSpec shoulder = cylinder("", at(0, 0, 0.185), 0.022, 0.015);
  const ShapeSpec neck = cylinder("", at(0, 0, 0.215), 0.014, 0.015);
  const double filled = (0.5 + 0.015) / (detail::volume(body) + detail::volume(shoulder));
  return detail::make("bottle", {{body, materials::pet, filled},
                                 {shoulder, materials::pet, filled},
                                 {neck, materials::pet, 0.005 / detail::volume(neck)}});
}

/// A 16 oz claw hammer: a hickory handle r 0.014 m, 0.28 m long along x (solid hickory, 0.14 kg),
/// and a steel head 0.11 m long along y, 0.026 x 0.032 m in section, at the handle's end. The
/// head is a 454 g (16 oz) head; its box also covers the claw's and the eye's air, so its
/// effective density is 454 g over the box's 91.5 cm^3. 0.59 kg in all, the centre of mass
/// 0.117 m along the handle, 3.6 cm from the head. docs/objects.md.
inline GraspObject hammer() {
  const ShapeSpec handle = cylinder("", at(0, 0, 0).rpy(0, pi / 2, 0), 0.014, 0.14);
  const ShapeSpec head = box("", at(0.153, 0, 0), {0.016, 0.055, 0.013});
  return detail::make("hammer", {{handle, materials::hickory, 0.0},
                                 {head, materials::steel, 0.454 / detail::volume(head)}});
}

/// An empty stoneware mug: a cylindrical cup r 0.041 m, 0.095 m tall (0.30 kg: its wall and base
/// spread over the solid cylinder) and a solid stoneware handle (a capsule loop approximated by a
/// vertical capsule and two short arms) on +x, about 0.05 kg. 0.35 kg in all. docs/objects.md.
inline GraspObject mug() {
  const ShapeSpec cup = cylinder("", at(0, 0, 0.0475), 0.041, 0.0475);
  return detail::make(
      "mug", {{cup, materials::ceramic, 0.30 / detail::volume(cup)},
              {capsule("", {0.068, 0, 0.025}, {0.068, 0, 0.075}, 0.007), materials::ceramic, 0.0},
              {capsule("", {0.04, 0, 0.08}, {0.068, 0, 0.075}, 0.007), materials::ceramic, 0.0},
              {capsule("", {0.04, 0, 0.02}, {0.068, 0, 0.025}, 0.007), materials::ceramic, 0.0}});
}

/// A cereal box 0.19 x 0.07 x 0.27 m of paperboard with its contents, 0.45 kg in all (a 375 g
/// pack and its 75 g box), spread evenly. docs/objects.md.
inline GraspObject box() {
  const ShapeSpec b = topograsp::box("", at(0, 0, 0.135), {0.095, 0.035, 0.135});
  return detail::make("box", {{b, materials::cardboard, 0.45 / detail::volume(b)}});
}

/// A hollow rubber ball r 0.045 m (tennis-ball size, thicker-walled), 0.2 kg. docs/objects.md.
inline GraspObject ball() {
  const ShapeSpec b = sphere("", {0, 0, 0.045}, 0.045);
  return detail::make("ball", {{b, materials::rubber, 0.2 / detail::volume(b)}});
}

/// A full 0.33 l aluminium drink can r 0.033 m, 0.115 m tall: 0.33 l of a soft drink (1.04 kg/l)
/// and a 13 g can, 0.356 kg, spread evenly. docs/objects.md.
inline GraspObject can() {
  const ShapeSpec c = cylinder("", at(0, 0, 0.0575), 0.033, 0.0575);
  return detail::make("can",
                      {{c, materials::aluminium, (0.33 * 1.04 + 0.013) / detail::volume(c)}});
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

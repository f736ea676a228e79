// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// ObjectSpec: an object to grasp, the checks of a HandScene's object, and how it becomes the
/// dynamic body of a World (internal, topograsp::detail).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/core/pose.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/model/spec.hpp>
#include <topograsp/physics/world.hpp>

namespace topograsp {

/// An object to grasp: shapes in the object frame, its pose, and its mass or density.
struct ObjectSpec {
  std::vector<ShapeSpec> shapes;  ///< in the object frame; ShapeSpec::link is ignored
  Pose pose{};                    ///< the object frame in the world
  double mass = 0.0;              ///< kg; if 0 the mass comes from density
  double density = 0.0;           ///< kg/m^3, used when mass is 0
  /// Density of each shape (kg/m^3), one per shape, for an object of several materials; empty =
  /// uniform (density, or mass spread evenly). With a mass they share it out; without, they give
  /// it.
  std::vector<double> part_density{};
  /// Coulomb friction coefficient of each shape against every hand link, one per shape; empty =
  /// HandSceneOptions::friction for every pair.
  std::vector<double> part_friction{};
  /// The object's mass, centre of mass and inertia when its shapes only approximate it (a mesh
  /// object: GraspObject::inertial); then mass, density and part_density are not used.
  std::optional<MassProperties<double>> inertial{};
};

namespace detail {

/// Throws topograsp::invalid_argument naming the field of \p object ("object.shapes", ...) for
/// no shapes, a part_density or part_friction whose size is not the number of shapes, an entry of
/// them that is not positive and finite (part_density) or not in [0, 1e6] (part_friction), or a
/// non-positive mass (or density when the mass is 0 and no part densities are given) without an
/// inertial. The World checks the rest when the object is added (add_object_body()).
inline void require_object_spec(const ObjectSpec& object) {
  if (object.shapes.empty()) throw_invalid_argument("object.shapes", "expected at least one shape");
  const std::size_t n_parts = object.shapes.size();
  const auto require_per_part = [n_parts](const std::vector<double>& v, const char* field) {
    if (!v.empty() && v.size() != n_parts)
      throw_invalid_argument(std::string("object.") + field,
                             "expected one value per shape (" + std::to_string(n_parts) +
                                 "), got " + std::to_string(v.size()));
  };
  require_per_part(object.part_density, "part_density");
  require_per_part(object.part_friction, "part_friction");
  for (std::size_t i = 0; i < object.part_density.size(); ++i)
    require_positive(object.part_density[i], "object.part_density[" + std::to_string(i) + "]");
  for (std::size_t i = 0; i < object.part_friction.size(); ++i) {
    const std::string name = "object.part_friction[" + std::to_string(i) + "]";
    require_non_negative(object.part_friction[i], name);
    if (object.part_friction[i] > 1e6)
      throw_invalid_argument(
          name, "expected at most 1e6, got " + std::to_string(object.part_friction[i]));
  }
  if (!object.inertial && !(object.mass > 0.0)) {
    if (object.mass != 0.0) require_positive(object.mass, "object.mass");
    if (object.part_density.empty())
      require_positive(object.density, "object.density (the mass is 0)");
  }
}

/// Adds \p object to \p world as a dynamic body of friction \p friction and returns its index.
/// Throws what World::add_body() throws, an argument of the body's description renamed as the
/// object's field ("desc.mass" -> "object.mass") with the same problem.
template <class S>
int add_object_body(World<S>& world, const ObjectSpec& object, double friction) {
  BodyDesc o;
  o.type = BodyType::dynamic;
  o.pose = object.pose;
  o.shapes = object.shapes;
  o.mass = object.mass;
  o.density = object.density;
  o.shape_density = object.part_density;
  o.inertial = object.inertial;
  o.friction = friction;
  try {
    return world.add_body(o);
  } catch (const invalid_argument& e) {
    constexpr std::string_view world_name = "desc.";
    if (!e.argument().starts_with(world_name)) throw;
    throw_invalid_argument("object." + std::string(e.argument().substr(world_name.size())),
                           e.problem());
  }
}

}  // namespace detail

}  // namespace topograsp

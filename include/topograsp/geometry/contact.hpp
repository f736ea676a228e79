// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Contact: the result of a signed-distance query between two shapes.
#pragma once

#include <topograsp/core/eigen.hpp>

namespace topograsp {

/// The signed distance between shapes A and B with its witness points and normal.
///
/// distance > 0: the shapes are apart and point_a, point_b are closest points; distance < 0: they
/// overlap by -distance (the penetration depth: the shortest translation that separates them) and
/// point_a, point_b are the deepest points of each shape in the other. In both cases
/// point_b - point_a = distance * normal, and normal (unit, from A toward B) is the direction in
/// which moving B increases the distance: d distance = normal . (v_B(point_b) - v_A(point_a)) for
/// rigid motions with point velocities v_A, v_B, which is how Jacobians of the distance are built.
struct Contact {
  double distance = 0.0;        ///< signed distance (m)
  Vec3 normal = Vec3::UnitZ();  ///< unit, from A toward B
  Vec3 point_a = Vec3::Zero();  ///< witness point on A (world, m)
  Vec3 point_b = Vec3::Zero();  ///< witness point on B (world, m)
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The narrow phase's input and output types: ShapeView (a shape placed in the world) and
/// ContactSet (up to 4 ContactFeature points of one pair of shapes).
#pragma once

#include <array>
#include <cstdint>

#include <topograsp/geometry/detail/closest.hpp>
#include <topograsp/geometry/primitive.hpp>
#include <topograsp/physics/polytope.hpp>

namespace topograsp {

/// One contact point found by the narrow phase, in the world frame.
template <class S = double>
struct ContactFeature {
  Vec<3, S> point;       ///< midway between the two surfaces (m)
  Vec<3, S> normal;      ///< unit, pointing from shape A into shape B
  S separation = S(0);   ///< gap along the normal (m); negative when overlapping
  std::uint32_t id = 0;  ///< feature id, stable while the touching features stay the same
};

/// The contact points of one pair of shapes (at most 4).
template <class S = double>
struct ContactSet {
  int count = 0;
  std::array<ContactFeature<S>, 4> points{};
  void add(const Vec<3, S>& point, const Vec<3, S>& normal, S separation,
           std::uint32_t id) noexcept {
    if (count < 4) points[static_cast<std::size_t>(count++)] = {point, normal, separation, id};
  }
};

/// A shape placed in the world, what the narrow phase reads: the geometry module's shape (type,
/// world rotation R, world position p, size as ShapeSpec::size) with the local polytope of a box
/// or cylinder, which the polytope collider needs.
template <class S = double>
struct ShapeView : BasicPrimitive<S> {
  const Polytope<S>* polytope = nullptr;  ///< local polytope for boxes and cylinders
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Collider: one shape of a body of a World, and how a World builds its shapes, places them where
/// their body is and shows them to the narrow phase (internal, topograsp::detail).
#pragma once

#include <span>
#include <vector>

#include <topograsp/core/assert.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/pose.hpp>
#include <topograsp/geometry/primitive.hpp>
#include <topograsp/model/spec.hpp>
#include <topograsp/physics/contact_set.hpp>
#include <topograsp/physics/polytope.hpp>
#include <topograsp/physics/rigid_body.hpp>

namespace topograsp {

/// A shape attached to a body of a World.
template <class S = double>
struct Collider {
  int body = -1;
  ShapeType type = ShapeType::sphere;
  Vec<3, S> size = Vec<3, S>::Zero();               ///< as ShapeSpec::size
  Mat<3, 3, S> local_R = Mat<3, 3, S>::Identity();  ///< in body axes
  Vec<3, S> local_p = Vec<3, S>::Zero();            ///< from the centre of mass
  S bounding_radius = S(0);  ///< of a sphere about the shape's centre that contains it (m)
  int polytope = -1;         ///< index into World's polytopes (boxes and cylinders)
  Mat<3, 3, S> R = Mat<3, 3, S>::Identity();  ///< world rotation (current)
  Vec<3, S> p = Vec<3, S>::Zero();            ///< world position (current)
  ShapeSpec spec{};                           ///< the shape as given, in the body frame
};

namespace detail {

/// The collider of shape \p s of body \p body whose centre of mass is \p local_com (body frame);
/// a box or a cylinder appends its polytope to \p polytopes. Allocates.
template <class S>
[[nodiscard]] Collider<S> make_collider(const ShapeSpec& s, int body, const Vec<3, S>& local_com,
                                        std::vector<Polytope<S>>& polytopes) {
  Collider<S> c;
  c.body = body;
  c.spec = s;
  c.type = s.type;
  c.size =
      Vec<3, S>(static_cast<S>(s.size[0]), static_cast<S>(s.size[1]), static_cast<S>(s.size[2]));
  c.local_R = rotation_of<S>(s.pose);
  c.local_p = translation_of<S>(s.pose) - local_com;
  c.bounding_radius = bounding_radius<S>(s.type, c.size);
  if (s.type == ShapeType::box || s.type == ShapeType::cylinder) {
    c.polytope = static_cast<int>(polytopes.size());
    polytopes.push_back(s.type == ShapeType::box ? box_polytope<S>(c.size)
                                                 : cylinder_polytope<S>(c.size[0], c.size[1]));
  }
  return c;
}

/// Places the shapes of body \p b (of \p colliders) where the body is now.
template <class S>
void place_colliders(const RigidBody<S>& b, std::span<Collider<S>> colliders) noexcept {
  for (int c = b.first_collider; c < b.first_collider + b.n_colliders; ++c) {
    Collider<S>& col = colliders[static_cast<std::size_t>(c)];
    col.R.noalias() = b.R * col.local_R;
    col.p = b.x + b.R * col.local_p;
  }
}

/// The collider \p c at its current pose as the narrow phase reads it, with its polytope from
/// \p polytopes.
template <class S>
[[nodiscard]] ShapeView<S> shape_view(const Collider<S>& c,
                                      std::span<const Polytope<S>> polytopes) noexcept {
  ShapeView<S> v;
  v.type = c.type;
  v.size = c.size;
  v.R = c.R;
  v.p = c.p;
  TOPOGRASP_ASSERT((c.polytope >= 0) == (c.type == ShapeType::box || c.type == ShapeType::cylinder),
                   "boxes and cylinders, and only they, have a polytope");
  v.polytope = c.polytope >= 0 ? &polytopes[static_cast<std::size_t>(c.polytope)] : nullptr;
  return v;
}

}  // namespace detail

}  // namespace topograsp

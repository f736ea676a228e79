// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The contact slots of a World (internal): one Manifold per pair of shapes that can touch, made
/// when a body is added, and the narrow-phase pass that fills them at the start of each step.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include <topograsp/core/eigen.hpp>
#include <topograsp/physics/collider.hpp>
#include <topograsp/physics/contact.hpp>
#include <topograsp/physics/narrow_phase.hpp>
#include <topograsp/physics/polytope.hpp>
#include <topograsp/physics/rigid_body.hpp>

namespace topograsp::detail {

/// Appends to \p manifolds a slot for every pair of a shape of body \p index (the last of
/// \p bodies) and a shape of an earlier body, when one of the two bodies is dynamic; friction
/// sqrt(mu_a mu_b). Allocates.
template <class S>
void add_contact_slots(std::vector<Manifold<S>>& manifolds, std::span<const RigidBody<S>> bodies,
                       int index) {
  const RigidBody<S>& b = bodies[static_cast<std::size_t>(index)];
  for (int j = 0; j < index; ++j) {
    const RigidBody<S>& o = bodies[static_cast<std::size_t>(j)];
    if (o.type != BodyType::dynamic && b.type != BodyType::dynamic) continue;
    for (int ca = o.first_collider; ca < o.first_collider + o.n_colliders; ++ca)
      for (int cb = b.first_collider; cb < b.first_collider + b.n_colliders; ++cb) {
        Manifold<S> m;
        m.body_a = j;
        m.body_b = index;
        m.collider_a = ca;
        m.collider_b = cb;
        m.friction = std::sqrt(o.friction * b.friction);
        m.kinematic = o.type == BodyType::kinematic || b.type == BodyType::kinematic;
        manifolds.push_back(m);
      }
  }
}

/// Keeps the contact points of \p cs near the smaller of shapes \p ca and \p cb. A contact point
/// lies midway between the two surfaces; when the smaller shape lies deep inside the larger one (a
/// sphere of radius 1e127 around a ball of 0.4 m: an overlap of 1e127 m) that point lies far
/// outside both bodies, and its lever arms turn the solver's impulses into overflow. Points
/// farther than twice the smaller shape's bounding radius (plus \p margin) from its centre are
/// moved back to that distance along the same line; no overlap shallower than the smaller shape's
/// own size is touched.
template <class S>
void keep_points_near(const Collider<S>& ca, const Collider<S>& cb, S margin,
                      ContactSet<S>& cs) noexcept {
  const Collider<S>& small = ca.bounding_radius <= cb.bounding_radius ? ca : cb;
  const S reach = S(2) * small.bounding_radius + margin;
  for (int k = 0; k < cs.count; ++k) {
    Vec<3, S>& p = cs.points[static_cast<std::size_t>(k)].point;
    const Vec<3, S> d = p - small.p;
    const S r = d.norm();
    if (r > reach) p = small.p + d * (reach / r);
  }
}

/// The narrow phase on every slot of \p manifolds whose shapes' bounding spheres are within
/// \p margin, with each new point matched to the previous step's by feature id
/// (match_contacts()); other slots are emptied. Allocates nothing.
template <class S>
void find_contacts(std::span<Manifold<S>> manifolds, std::span<const Collider<S>> colliders,
                   std::span<const Polytope<S>> polytopes, S margin) noexcept {
  for (Manifold<S>& m : manifolds) {
    const Collider<S>& ca = colliders[static_cast<std::size_t>(m.collider_a)];
    const Collider<S>& cb = colliders[static_cast<std::size_t>(m.collider_b)];
    const S reach = ca.bounding_radius + cb.bounding_radius + margin;
    if ((ca.p - cb.p).squaredNorm() > reach * reach) {
      m.count = 0;
      m.twist_impulse = S(0);
      continue;
    }
    ContactSet<S> cs;
    collide<S>(shape_view(ca, polytopes), shape_view(cb, polytopes), margin, cs);
    keep_points_near(ca, cb, margin, cs);
    match_contacts<S>(m, cs);
  }
}

}  // namespace topograsp::detail

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The narrow phase: contact points, normals, separations and stable feature ids for every pair of
/// sphere, capsule, box and cylinder, up to 4 points a pair. collide() dispatches each pair to its
/// family's collider: rounded shapes (physics/detail/collide_rounded.hpp) and polytopes
/// (physics/detail/collide_polytopes.hpp).
#pragma once

#include <topograsp/model/spec.hpp>
#include <topograsp/physics/contact_set.hpp>
#include <topograsp/physics/detail/collide_polytopes.hpp>
#include <topograsp/physics/detail/collide_rounded.hpp>

namespace topograsp {

/// Finds the contacts between two shapes whose surfaces are closer than \p margin (m): up to 4
/// points with normals from \p a into \p b, separations (negative when overlapping) and feature
/// ids. Appends to \p out (which the caller clears). Exact for pairs of spheres and capsules, and
/// for those against boxes and cylinders while the sphere's centre or the capsule's segment is
/// outside the solid; once it is inside, the contact takes the shallowest face exit, which can be
/// deeper than the true overlap and differently oriented. Box and cylinder pairs use the
/// cylinder's prism (cylinder_prism_sides) and the face and edge-edge axes of the two polytopes,
/// but not the cap-edge pairs of two prisms. How far off these approximations are:
/// docs/stepper.md. Never produces a NaN for finite input.
template <class S>
void collide(const ShapeView<S>& a, const ShapeView<S>& b, S margin, ContactSet<S>& out) noexcept {
  using namespace detail;
  const bool ra = is_rounded(a.type), rb = is_rounded(b.type);
  if (ra && rb) {
    collide_rounded_rounded<S>(a, b, margin, out);
  } else if (ra) {
    collide_rounded_solid<S>(a, b, margin, out);
  } else if (rb) {
    const int before = out.count;
    collide_rounded_solid<S>(b, a, margin, out);
    for (int i = before; i < out.count; ++i)
      out.points[static_cast<std::size_t>(i)].normal *= S(-1);
  } else {
    collide_polytopes<S>(a, b, margin, out);
  }
}

}  // namespace topograsp

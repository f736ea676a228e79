// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The contacts of one body: the contact points of the manifolds (World::manifolds()) that touch
/// it, visited in the World's order, the one loop behind every per-body and per-pair contact
/// query.
#pragma once

#include <cstddef>
#include <span>

#include <topograsp/physics/contact.hpp>

namespace topograsp {

/// The body that manifold \p m joins to \p body (one of its two bodies).
template <class S>
[[nodiscard]] int other_body(const Manifold<S>& m, int body) noexcept {
  return m.body_a == body ? m.body_b : m.body_a;
}

/// Calls \p f(m, p) for every point p in use of every manifold m of \p manifolds between
/// \p body and another body, in order.
template <class S, class F>
void for_each_contact(std::span<const Manifold<S>> manifolds, int body, F&& f) {
  for (const Manifold<S>& m : manifolds)
    if (m.body_a == body || m.body_b == body)
      for (int k = 0; k < m.count; ++k) f(m, m.points[static_cast<std::size_t>(k)]);
}

}  // namespace topograsp

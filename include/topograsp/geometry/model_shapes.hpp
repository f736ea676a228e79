// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// world_shapes(): a model's link shapes as world-frame primitives at a kinematics result.
#pragma once

#include <array>

#include <topograsp/geometry/primitive.hpp>
#include <topograsp/kinematics/data.hpp>

namespace topograsp {

/// Shape \p i of the model \p M in the world frame. Requires forward_kinematics(d, q) first.
template <const auto& M>
[[nodiscard]] Primitive world_shape(const KinematicsData<M>& d, std::size_t i) noexcept {
  const Shape& s = M.shapes[i];
  const auto l = static_cast<std::size_t>(s.link);
  return Primitive::from_spec(s.spec, d.R[l], d.p[l]);
}

/// Every shape of the model \p M in the world frame, in model order. Requires
/// forward_kinematics(d, q) first.
template <const auto& M>
[[nodiscard]] std::array<Primitive, std::remove_cvref_t<decltype(M)>::n_shapes> world_shapes(
    const KinematicsData<M>& d) noexcept {
  std::array<Primitive, std::remove_cvref_t<decltype(M)>::n_shapes> out{};
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = world_shape(d, i);
  return out;
}

}  // namespace topograsp

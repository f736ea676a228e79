// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// WindingDescriptor and winding_descriptor(): the paper's topological descriptor y of a grasp.
#pragma once

#include <array>

#include <topograsp/core/error.hpp>
#include <topograsp/task/winding_task.hpp>

namespace topograsp {

/// The topological state descriptor of a grasp (paper III.A): the two largest windings of the
/// hand curves around the object's centre of mass, and which curves they are.
struct WindingDescriptor {
  Vec2 values = Vec2::Zero();         ///< w of the two curves, largest first
  std::array<int, 2> curves{-1, -1};  ///< their indices in hand_curves<M>()
};

/// The descriptor y = (w(gamma_i), w(gamma_j)) of the hand \p M at the configuration in \p d around
/// \p point: the two curves with the largest windings, largest first (on a tie the lower index
/// first). Requires forward_kinematics(d, q) first; \p M needs at least two hand curves (three
/// fingers).
/// \throws topograsp::invalid_argument naming "point" if it is not finite.
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] WindingDescriptor winding_descriptor(const KinematicsData<M>& d, const Vec3& point) {
  static_assert(hand_curve_count<M> >= 2, "the descriptor needs a hand with at least two curves");
  const WindingTask<M> task(point);
  const Vec<hand_curve_count<M>> w = task.value(d);
  WindingDescriptor y;
  int first = 0;
  for (int i = 1; i < w.size(); ++i)
    if (w[i] > w[first]) first = i;
  int second = first == 0 ? 1 : 0;
  for (int i = 0; i < w.size(); ++i)
    if (i != first && w[i] > w[second]) second = i;
  y.curves = {first, second};
  y.values = Vec2(w[first], w[second]);
  return y;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TopologyMode: how the topological layer supplies winding targets to AICO.
#pragma once

#include <string_view>

namespace topograsp {

/// How the topological layer (paper Fig. 4) supplies targets y_t for the topology variable.
enum class TopologyMode {
  /// y_t interpolated linearly from phi(q_0) to the goal: the topology variable is one more task.
  direct,
  /// y_t inferred by a Gaussian smoother in topology space (a random-walk prior pinned at
  /// phi(q_0) and at the goal, observations phi(q_t) with the coupling precision), alternating
  /// with AICO on the state layer until both settle.
  coupled,
};

/// "direct" or "coupled".
[[nodiscard]] constexpr std::string_view to_string(TopologyMode m) noexcept {
  return m == TopologyMode::direct ? "direct" : "coupled";
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// How AICO splits a stack's residual into the costs of its tasks (internal).
#pragma once

#include <array>
#include <cstddef>

#include <topograsp/core/eigen.hpp>

namespace topograsp::detail {

/// A TaskStack that says which rows of its residual belong to which task: a constexpr
/// `std::array<int, n> task_dims` whose entries add up to dim, in residual order.
template <class S>
concept HasTaskDims = requires {
  { S::task_dims.size() } -> std::convertible_to<std::size_t>;
  { S::task_dims[0] } -> std::convertible_to<int>;
};

/// The number of tasks AICO reports costs for: task_dims.size(), or 1 for an opaque stack.
template <class S>
[[nodiscard]] constexpr std::size_t task_count() noexcept {
  if constexpr (HasTaskDims<S>)
    return S::task_dims.size();
  else
    return 1;
}

/// Adds the squared norm of each task's rows of the residual \p e to \p costs.
template <class S, class Costs>
void add_task_costs(const Vec<S::dim>& e, Costs& costs) noexcept {
  if constexpr (HasTaskDims<S>) {
    int row = 0;
    for (std::size_t i = 0; i < S::task_dims.size(); ++i) {
      const int n = S::task_dims[i];
      costs[i] += e.segment(row, n).squaredNorm();
      row += n;
    }
  } else {
    costs[0] += e.squaredNorm();
  }
}

}  // namespace topograsp::detail

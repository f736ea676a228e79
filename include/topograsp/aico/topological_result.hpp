// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TopologicalResult: the outcome of a plan through the topological layer.
#pragma once

#include <vector>

#include <topograsp/aico/result.hpp>
#include <topograsp/core/eigen.hpp>

namespace topograsp {

/// The outcome of solve_topological() for a robot with \p NQ joints and a topology space of
/// dimension \p K.
template <int NQ, int K>
struct [[nodiscard]] TopologicalResult {
  AicoResult<NQ> aico;          ///< the state layer's last solve (trajectory, costs, status)
  std::vector<Vec<K>> targets;  ///< y_0..y_T: the topology targets of that solve
  std::vector<Vec<K>> values;   ///< phi(q_0)..phi(q_T) along the returned trajectory
  int rounds = 0;               ///< alternations between the layers (1 in direct mode)
  bool settled = false;         ///< coupled mode: y stopped moving within max_rounds

  /// The final configuration q_T (rad).
  [[nodiscard]] const Vec<NQ>& final_configuration() const { return aico.final_configuration(); }
  /// phi(q_T).
  [[nodiscard]] const Vec<K>& final_value() const { return values.back(); }
};

}  // namespace topograsp

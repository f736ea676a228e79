// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TopologyOptions: the parameters of the topological layer.
#pragma once

#include <topograsp/aico/topology_mode.hpp>

namespace topograsp {

/// The parameters of the topological layer (solve_topological()), with their defaults.
struct TopologyOptions {
  /// Direct interpolation of the targets or the coupled y layer.
  TopologyMode mode = TopologyMode::direct;
  /// Coupling precision rho (> 0) between phi(q_t) and y_t for t < T: how closely the state layer
  /// follows the topology trajectory on the way.
  double precision = 1e2;
  /// Coupling precision (> 0) at t = T: how exactly the goal windings are reached.
  double end_precision = 1e5;
  /// Coupled mode: precision (> 0) of the random-walk prior |y_{t+1} - y_t|^2 of the y layer.
  /// Large values keep y close to the straight interpolation; small ones let it follow what the
  /// state layer can do.
  double prior_precision = 1e3;
  /// Coupled mode: largest number of alternations (>= 1) between the two layers.
  int max_rounds = 8;
  /// Coupled mode: the layers have settled when no y_t moved by this much (> 0) in a round.
  double tolerance = 1e-3;
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// solve_topological(): AICO with the topological layer of the paper's Fig. 4, direct or coupled.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <topograsp/aico/problem.hpp>
#include <topograsp/aico/solver.hpp>
#include <topograsp/aico/topological_result.hpp>
#include <topograsp/aico/topological_stack.hpp>
#include <topograsp/aico/topology_options.hpp>
#include <topograsp/kinematics/forward.hpp>

namespace topograsp {

namespace detail {

/// The y layer's smoother: the minimiser over y_1..y_{T-1} of
/// sum_t w |y_{t+1} - y_t|^2 + rho sum_{0<t<T} |phi_t - y_t|^2 with y_0 and y_T fixed. Every
/// precision is a scalar, so each coordinate is an independent tridiagonal system (Thomas).
template <int K>
void smooth_topology(std::vector<Vec<K>>& y, const std::vector<Vec<K>>& phi, double w, double rho) {
  const std::size_t n = y.size();
  if (n < 3) return;
  const std::size_t m = n - 2;  // unknowns y_1..y_{T-1}
  std::vector<double> c(m), d(m);
  for (int j = 0; j < K; ++j) {
    // Rows: (2w + rho) y_t - w y_{t-1} - w y_{t+1} = rho phi_t (+ w y_0 or w y_T at the ends).
    const double diag = 2.0 * w + rho;
    for (std::size_t i = 0; i < m; ++i) {
      double rhs = rho * phi[i + 1][j];
      if (i == 0) rhs += w * y[0][j];
      if (i + 1 == m) rhs += w * y[n - 1][j];
      const double denom = i == 0 ? diag : diag + w * c[i - 1];
      c[i] = -w / denom;
      d[i] = i == 0 ? rhs / denom : (rhs + w * d[i - 1]) / denom;
    }
    for (std::size_t i = m; i-- > 0;) {
      const double next = i + 1 < m ? y[i + 2][j] : 0.0;
      y[i + 1][j] = i + 1 < m ? d[i] - c[i] * next : d[i];
    }
  }
}

}  // namespace detail

/// Plans a motion of the robot \p M from \p q_start (rad) whose topology variable \p variable
/// (e.g. a WindingTask of two hand curves around the object) ends at \p goal, under the other
/// tasks \p base (collision, limits, pose...), with AICO in mode \p Mode.
///
/// TopologyMode::direct: one AICO solve of TopologicalStack with targets interpolated linearly
/// from phi(q_start) to \p goal. TopologyMode::coupled: the targets are the mean of a process y_t
/// in topology space with a random-walk prior (prior_precision) pinned at phi(q_start) and
/// \p goal, observing phi(q_t) with the coupling precision; rounds alternate the y smoother and a
/// warm-started AICO solve of the state layer until no y_t moves by tolerance (settled) or
/// max_rounds. Each round lowers the joint objective of both layers.
/// \throws topograsp::invalid_argument naming the bad argument ("q_start", "goal",
///         "topology.<field>", "options.<field>").
template <const auto& M, AicoMode Mode = AicoMode::dynamic, TaskStack Base, TaskVariable Var>
TopologicalResult<M.nq, Var::dim> solve_topological(const Base& base, const Var& variable,
                                                    const Vec<Var::dim>& goal,
                                                    const Vec<M.nq>& q_start,
                                                    const AicoOptions& options,
                                                    const TopologyOptions& topology = {}) {
  constexpr int K = Var::dim;
  using Stack = TopologicalStack<Base, Var>;
  require_configuration<M>(q_start, "q_start");
  require_finite(goal, "goal");
  require_positive(topology.precision, "topology.precision");
  require_positive(topology.end_precision, "topology.end_precision");
  require_positive(topology.prior_precision, "topology.prior_precision");
  require_positive(topology.tolerance, "topology.tolerance");
  if (topology.max_rounds < 1)
    detail::throw_invalid_argument("topology.max_rounds", "expected >= 1");
  if (options.steps < 1)
    detail::throw_invalid_argument(
        "options.steps", "expected at least 1 step, got " + std::to_string(options.steps));
  const int T = options.steps;
  const auto n = static_cast<std::size_t>(T + 1);

  KinematicsData<M> d;
  forward_kinematics(d, q_start);
  const Vec<K> y0 = variable.value(d);
  Stack stack{base, variable, std::vector<Vec<K>>(n), topology.precision, topology.end_precision};
  for (std::size_t u = 0; u < n; ++u)
    stack.targets[u] = y0 + (static_cast<double>(u) / T) * (goal - y0);

  const auto values_of = [&](const AicoResult<M.nq>& r) {
    std::vector<Vec<K>> v(n);
    for (std::size_t u = 0; u < n; ++u) {
      forward_kinematics(d, r.q[u]);
      v[u] = variable.value(d);
    }
    return v;
  };

  TopologicalResult<M.nq, K> out;
  AicoProblem<M, Stack, Mode> problem(stack, q_start, options);
  AicoWorkspace ws(problem);
  out.aico = solve(problem, ws);
  out.rounds = 1;
  out.values = values_of(out.aico);
  if (topology.mode == TopologyMode::coupled) {
    for (int round = 1; round < topology.max_rounds && out.aico.status != Status::numerical_issue;
         ++round) {
      std::vector<Vec<K>> y = stack.targets;
      y.back() = goal;
      detail::smooth_topology(y, out.values, topology.prior_precision, topology.precision);
      double moved = 0.0;
      for (std::size_t u = 0; u < n; ++u)
        moved = std::max(moved, (y[u] - stack.targets[u]).template lpNorm<Eigen::Infinity>());
      if (moved < topology.tolerance) {
        out.settled = true;
        break;
      }
      stack.targets = y;
      AicoProblem<M, Stack, Mode> next(stack, q_start, options);
      out.aico = solve(next, ws, out.aico);
      out.values = values_of(out.aico);
      ++out.rounds;
    }
  }
  out.targets = stack.targets;
  return out;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The topological layer of the paper (Fig. 4): a process y_t in topology space (the winding
/// values) coupled to the AICO state layer. TopologicalMode and TopologicalOptions (how the layer
/// supplies targets), TopologicalStack (the coupling factors as a TaskStack), TopologicalResult,
/// and solve_topological(), which plans through the layer, direct or coupled. See docs/aico.md.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/aico/detail/task_parts.hpp>
#include <topograsp/aico/problem.hpp>
#include <topograsp/aico/result.hpp>
#include <topograsp/aico/solver.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/task/concepts.hpp>

namespace topograsp {

/// How the topological layer (paper Fig. 4) supplies targets y_t for the topological variable.
enum class TopologicalMode {
  /// y_t interpolated linearly from phi(q_0) to the goal: the topological variable is one more
  /// task.
  direct,
  /// y_t inferred by a Gaussian smoother in topology space (a random-walk prior pinned at
  /// phi(q_0) and at the goal, observations phi(q_t) with the coupling precision), alternating
  /// with AICO on the state layer until both settle.
  coupled,
};

/// "direct" or "coupled".
[[nodiscard]] constexpr std::string_view to_string(TopologicalMode m) noexcept {
  switch (m) {
    case TopologicalMode::direct:
      return "direct";
    case TopologicalMode::coupled:
      return "coupled";
  }
  return "unknown";
}

/// The parameters of the topological layer (solve_topological()), with their defaults.
struct TopologicalOptions {
  /// Direct interpolation of the targets or the coupled y layer.
  TopologicalMode mode = TopologicalMode::direct;
  /// Coupling precision rho (> 0) between phi(q_t) and y_t for t < T: how closely the state layer
  /// follows the topological trajectory on the way.
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

namespace detail {

/// The task_dims of TopologicalStack<Base, Var>: Base's tasks (or Base as one task), then the
/// topological variable's K rows.
template <class Base, int K>
constexpr auto topological_task_dims() noexcept {
  if constexpr (HasTaskDims<Base>) {
    std::array<int, Base::task_dims.size() + 1> d{};
    for (std::size_t i = 0; i < Base::task_dims.size(); ++i) d[i] = Base::task_dims[i];
    d[Base::task_dims.size()] = K;
    return d;
  } else {
    return std::array<int, 2>{Base::dim, K};
  }
}

/// The y layer's smoother: the minimiser over y_1..y_{T-1} of
/// sum_t w |y_{t+1} - y_t|^2 + rho sum_{0<t<T} |phi_t - y_t|^2 with y_0 and y_T fixed. Every
/// precision is a scalar, so each coordinate is an independent tridiagonal system (Thomas).
template <int K>
void smooth_topological_targets(std::vector<Vec<K>>& y, const std::vector<Vec<K>>& phi, double w,
                                double rho) {
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

/// The TaskStack \p Base with one more task: the topological variable \p Var (e.g. the windings of
/// two hand curves, WindingTask) pulled toward targets y_t, i.e. the factors
/// \f$\exp(-\frac{\rho_t}{2} |\varphi(q_t) - y_t|^2)\f$ of the paper's eq. (1). Its residual is
/// Base's rows, then \f$\sqrt{\rho_t} (\varphi(q_t) - y_t)\f$ with \f$\rho_t\f$ = precision for
/// t < T and end_precision at t = T. The per-task costs of an AICO result list Base's tasks, then
/// this one.
template <TaskStack Base, TaskVariable Var>
  requires std::same_as<typename Base::Kinematics, typename Var::Kinematics>
struct TopologicalStack {
  using Kinematics = typename Base::Kinematics;
  static constexpr int nq = Kinematics::nq;
  static constexpr int k = Var::dim;  ///< dimension of the topology space
  static constexpr int dim = Base::dim + Var::dim;
  static constexpr auto task_dims = detail::topological_task_dims<Base, Var::dim>();

  Base base;                    ///< the other tasks
  Var variable;                 ///< phi: configuration -> topology space
  std::vector<Vec<k>> targets;  ///< y_0..y_T (T + 1 of them)
  double precision = 1e2;       ///< coupling precision rho for t < T
  double end_precision = 1e4;   ///< coupling precision at t = T

  /// The stacked residual at step t of T. Requires forward_kinematics(d, q) first and
  /// targets.size() == T + 1.
  void residual(const Kinematics& d, int t, int T, Vec<dim>& e, Mat<dim, nq>& J) const noexcept {
    Vec<Base::dim> eb;
    Mat<Base::dim, nq> Jb;
    base.residual(d, t, T, eb, Jb);
    e.template head<Base::dim>() = eb;
    J.template topRows<Base::dim>() = Jb;
    Vec<k> phi;
    Mat<k, nq> Jv;
    variable.evaluate(d, phi, Jv);
    const double s = std::sqrt(t == T ? end_precision : precision);
    e.template tail<k>() = s * (phi - targets[static_cast<std::size_t>(t)]);
    J.template bottomRows<k>() = s * Jv;
  }
};

/// The outcome of solve_topological() for a robot with \p NQ joints and a topology space of
/// dimension \p K.
template <int NQ, int K>
struct [[nodiscard]] TopologicalResult {
  AicoResult<NQ> aico;          ///< the state layer's last solve (trajectory, costs, status)
  std::vector<Vec<K>> targets;  ///< y_0..y_T: the topological targets of that solve
  std::vector<Vec<K>> values;   ///< phi(q_0)..phi(q_T) along the returned trajectory
  int rounds = 0;               ///< alternations between the layers (1 in direct mode)
  bool settled = false;         ///< coupled mode: y stopped moving within max_rounds

  /// The final configuration q_T (rad).
  [[nodiscard]] const Vec<NQ>& final_configuration() const { return aico.final_configuration(); }
  /// phi(q_T).
  [[nodiscard]] const Vec<K>& final_value() const { return values.back(); }
};

/// Plans a motion of the robot \p M from \p q_start (rad) whose topological variable \p variable
/// (e.g. a WindingTask of two hand curves around the object) ends at \p goal, under the other
/// tasks \p base (collision, limits, pose...), with AICO in mode \p Mode.
///
/// TopologicalMode::direct: one AICO solve of TopologicalStack with targets interpolated linearly
/// from phi(q_start) to \p goal. TopologicalMode::coupled: the targets are the mean of a process
/// y_t in topology space with a random-walk prior (prior_precision) pinned at phi(q_start) and
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
                                                    const TopologicalOptions& topology = {}) {
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
  if (topology.mode == TopologicalMode::coupled) {
    for (int round = 1; round < topology.max_rounds && out.aico.status != Status::numerical_issue;
         ++round) {
      std::vector<Vec<K>> y = stack.targets;
      y.back() = goal;
      detail::smooth_topological_targets(y, out.values, topology.prior_precision,
                                         topology.precision);
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

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The AICO smoother over an AicoProblem and an AicoWorkspace: initialise(), sweep(),
/// continue_solve() and solve(), which sequence the stages of a sweep (detail::AicoAlgorithm,
/// aico/detail/algorithm.hpp). Equation numbers refer to docs/aico.md.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <topograsp/aico/detail/algorithm.hpp>
#include <topograsp/aico/problem.hpp>
#include <topograsp/aico/result.hpp>
#include <topograsp/aico/workspace.hpp>

namespace topograsp {

/// Sets the accepted trajectory of \p ws to \p q (T + 1 configurations, rad) with velocities
/// \p qdot (dim nq each, rad/s; ignored in kinematic mode), its linearisation and its task
/// messages, the damping reference and the damping; the first entries are replaced by the
/// problem's start. Returns the cost of that trajectory (NaN if a task is not finite there).
/// Allocates only when \p ws was sized for another number of steps.
/// \throws topograsp::invalid_argument naming "initial" for a trajectory of the wrong length or
/// with non-finite entries.
template <const auto& M, TaskStack Stack, AicoMode Mode>
double initialise(const AicoProblem<M, Stack, Mode>& problem, AicoWorkspace<M, Stack, Mode>& ws,
                  const std::vector<Vec<M.nq>>& q, const std::vector<Vec<M.nq>>& qdot) {
  using Alg = detail::AicoAlgorithm<M, Stack, Mode>;
  constexpr int nq = M.nq;
  constexpr int nx = Alg::nx;
  const int T = problem.steps();
  const auto n = static_cast<std::size_t>(T + 1);
  if (q.size() != n || qdot.size() != n)
    detail::throw_invalid_argument(
        "initial", "expected " + std::to_string(n) + " configurations and velocities, got " +
                       std::to_string(q.size()) + " and " + std::to_string(qdot.size()));
  for (std::size_t u = 1; u < n; ++u) {
    require_finite(q[u], "initial");
    require_finite(qdot[u], "initial");
  }
  if (ws.steps() != T) ws.resize(T);
  auto& in = ws.accepted();
  for (std::size_t u = 0; u < n; ++u) {
    Vec<nx> x;
    if (u == 0) {
      x = problem.x_start();
    } else if constexpr (Mode == AicoMode::dynamic) {
      x << q[u], qdot[u];
    } else {
      x = q[u];
    }
    in.b[u] = x;
    ws.b_ref[u] = x;
    in.q_hat[u] = x.template head<nq>();
    in.S_inv[u].setZero();
    in.h[u].setZero();
    const double prec =
        u + 1 == n ? problem.options().terminal_precision : detail::k_initial_message_precision;
    in.V_inv[u] = prec * Mat<nx, nx>::Identity();
    in.hv[u] = prec * x;
    if (!Alg::task_message(problem, ws, static_cast<int>(u), in.q_hat[u], in.R[u], in.r[u],
                           in.c[u])) {
      in.R[u].setZero();
      in.r[u].setZero();
      in.c[u] = std::nan("");
    }
  }
  ws.alpha = problem.options().damping;
  ws.cost = Alg::trajectory_cost(problem, ws, in);
  return ws.cost;
}

/// Sets the accepted trajectory of \p ws to the problem's start held for all T + 1 steps (at
/// rest), the usual cold start. Returns its cost.
template <const auto& M, TaskStack Stack, AicoMode Mode>
double initialise(const AicoProblem<M, Stack, Mode>& problem, AicoWorkspace<M, Stack, Mode>& ws) {
  const auto n = static_cast<std::size_t>(problem.steps() + 1);
  const std::vector<Vec<M.nq>> q(n, problem.q_start());
  const std::vector<Vec<M.nq>> qdot(n, Vec<M.nq>::Zero());
  return initialise(problem, ws, q, qdot);
}

/// One AICO sweep (docs/aico.md, "Sweeps"): the passes (a forward pass t = 1..T of messages (3),
/// in SweepMode::local_gauss_newton with up to local_iterations relocations of each step toward
/// its belief; a backward pass t = T-1..1 of beliefs, by (6) or by (4) and (5), relinearising each
/// step at its new belief with steps (7) capped at max_step), then the true cost (1) of the new
/// beliefs and the acceptance rule (8): if the cost did not rise, the new trajectory is accepted
/// and the damping divided by damping_decrease, else the accepted trajectory stays as it was and
/// the damping is multiplied by damping_increase. Requires initialise() first. Allocates
/// nothing. A non-finite task value or cost rejects the sweep and sets ws.non_finite.
template <const auto& M, TaskStack Stack, AicoMode Mode>
AicoSweepRecord sweep(const AicoProblem<M, Stack, Mode>& problem,
                      AicoWorkspace<M, Stack, Mode>& ws) noexcept {
  using Alg = detail::AicoAlgorithm<M, Stack, Mode>;
  const auto start = std::chrono::steady_clock::now();
  AicoSweepRecord rec;
  rec.damping = ws.alpha;
  const bool ok = Alg::passes(problem, ws, true);
  rec.task_evaluations = ws.task_evaluations;
  double cost = std::nan("");
  if (ok) {
    cost = Alg::trajectory_cost(problem, ws, ws.candidate());
    if (!std::isfinite(cost)) ws.non_finite = true;
  }
  rec.cost = cost;
  if (ok && std::isfinite(cost)) {
    const auto& cand = ws.candidate().b;
    const auto& acc = ws.accepted().b;
    for (std::size_t u = 0; u < cand.size(); ++u)
      rec.step = std::max(
          rec.step, (cand[u] - acc[u]).template head<M.nq>().template lpNorm<Eigen::Infinity>());
  }
  rec.accepted = Alg::accept_or_reject(problem, ws, ok, cost);
  rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return rec;
}

/// Builds the result from the accepted trajectory of \p ws (allocates).
template <const auto& M, TaskStack Stack, AicoMode Mode>
[[nodiscard]] AicoResult<M.nq> make_result(const AicoProblem<M, Stack, Mode>& problem,
                                           AicoWorkspace<M, Stack, Mode>& ws) {
  using Alg = detail::AicoAlgorithm<M, Stack, Mode>;
  constexpr int nq = M.nq;
  AicoResult<nq> res;
  const auto& acc = ws.accepted();
  const std::size_t n = acc.b.size();
  res.q.resize(n);
  res.qdot.resize(n);
  for (std::size_t u = 0; u < n; ++u) res.q[u] = acc.b[u].template head<nq>();
  if constexpr (Mode == AicoMode::dynamic) {
    for (std::size_t u = 0; u < n; ++u) res.qdot[u] = acc.b[u].template tail<nq>();
  } else {
    const double tau = problem.step_length();
    res.qdot[0].setZero();
    for (std::size_t u = 1; u < n; ++u) res.qdot[u] = (res.q[u] - res.q[u - 1]) / tau;
  }
  res.cost = Alg::trajectory_cost(problem, ws, acc, &res.control_cost, true);
  res.task_costs.assign(ws.task_costs.begin(), ws.task_costs.end());
  res.damping = ws.alpha;
  return res;
}

/// Runs sweeps from the trajectory initialise() set until one of the stopping rules of docs/aico.md
/// holds, and returns the best trajectory with the reason it stopped. The returned cost is never
/// above the initial cost and the accepted costs in cost_history never rise.
template <const auto& M, TaskStack Stack, AicoMode Mode>
[[nodiscard]] AicoResult<M.nq> continue_solve(const AicoProblem<M, Stack, Mode>& problem,
                                              AicoWorkspace<M, Stack, Mode>& ws) {
  const AicoOptions& o = problem.options();
  std::vector<double> history;
  std::vector<AicoSweepRecord> log;
  history.reserve(static_cast<std::size_t>(o.max_sweeps) + 1);
  log.reserve(static_cast<std::size_t>(o.max_sweeps));
  history.push_back(ws.cost);
  AicoTermination why = AicoTermination::max_sweeps;
  int rejected = 0, in_a_row = 0;
  if (!std::isfinite(ws.cost)) {
    why = AicoTermination::non_finite;
  } else {
    for (int k = 0; k < o.max_sweeps; ++k) {
      const double before = ws.cost;
      const AicoSweepRecord rec = sweep(problem, ws);
      log.push_back(rec);
      if (ws.non_finite) {
        ++rejected;
        why = AicoTermination::non_finite;
        break;
      }
      if (!rec.accepted) {
        ++rejected;
        // At a fixed point a sweep may raise the cost by rounding alone: a rejected sweep that
        // neither moves the trajectory nor changes the cost beyond the tolerances ends the solve.
        if (rec.step < o.tolerance && rec.damping <= o.damping &&
            rec.cost - ws.cost <= o.cost_tolerance * std::abs(ws.cost)) {
          why = AicoTermination::step_tolerance;
          break;
        }
        if (++in_a_row >= o.max_rejections) {
          why = ws.factor_failed ? AicoTermination::factorisation : AicoTermination::max_rejections;
          break;
        }
        continue;
      }
      in_a_row = 0;
      history.push_back(ws.cost);
      // A small step only means convergence when damping did not make it small.
      if (rec.step < o.tolerance && rec.damping <= o.damping) {
        why = AicoTermination::step_tolerance;
        break;
      }
      if (before - ws.cost <= o.cost_tolerance * std::abs(before)) {
        why = AicoTermination::cost_tolerance;
        break;
      }
    }
  }
  AicoResult<M.nq> res = make_result(problem, ws);
  res.termination = why;
  res.status = status_of(why);
  res.cost_history = std::move(history);
  res.sweep_log = std::move(log);
  res.sweeps = static_cast<int>(res.sweep_log.size());
  res.rejected = rejected;
  return res;
}

/// Solves \p problem from a cold start (the start configuration held at rest).
template <const auto& M, TaskStack Stack, AicoMode Mode>
[[nodiscard]] AicoResult<M.nq> solve(const AicoProblem<M, Stack, Mode>& problem,
                                     AicoWorkspace<M, Stack, Mode>& ws) {
  (void)initialise(problem, ws);
  return continue_solve(problem, ws);
}

/// Solves \p problem warm-started from the configurations \p q (T + 1 of them, rad); velocities
/// are central finite differences (zero at the start).
/// \throws topograsp::invalid_argument naming "initial" for a wrong length or non-finite entries.
template <const auto& M, TaskStack Stack, AicoMode Mode>
[[nodiscard]] AicoResult<M.nq> solve(const AicoProblem<M, Stack, Mode>& problem,
                                     AicoWorkspace<M, Stack, Mode>& ws,
                                     const std::vector<Vec<M.nq>>& q) {
  const std::size_t n = q.size();
  std::vector<Vec<M.nq>> qdot(n, Vec<M.nq>::Zero());
  const double tau = problem.step_length();
  for (std::size_t u = 1; u < n; ++u)
    qdot[u] =
        u + 1 < n ? ((q[u + 1] - q[u - 1]) / (2.0 * tau)).eval() : ((q[u] - q[u - 1]) / tau).eval();
  (void)initialise(problem, ws, q, qdot);
  return continue_solve(problem, ws);
}

/// Solves \p problem warm-started from an earlier result (its q and qdot).
/// \throws topograsp::invalid_argument naming "initial" if its length does not match.
template <const auto& M, TaskStack Stack, AicoMode Mode>
[[nodiscard]] AicoResult<M.nq> solve(const AicoProblem<M, Stack, Mode>& problem,
                                     AicoWorkspace<M, Stack, Mode>& ws,
                                     const AicoResult<M.nq>& warm) {
  (void)initialise(problem, ws, warm.q, warm.qdot);
  return continue_solve(problem, ws);
}

}  // namespace topograsp

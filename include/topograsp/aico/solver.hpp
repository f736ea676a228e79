// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The AICO smoother over an AicoProblem and an AicoWorkspace: the stages of a sweep
/// (detail::AicoAlgorithm: forward pass, the two backward passes, the capped relinearisation step,
/// the acceptance rule), and initialise(), sweep(), continue_solve() and solve() that sequence
/// them. Equation numbers refer to docs/aico.md.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <topograsp/aico/detail/messages.hpp>
#include <topograsp/aico/detail/task_parts.hpp>
#include <topograsp/aico/problem.hpp>
#include <topograsp/aico/result.hpp>
#include <topograsp/aico/workspace.hpp>
#include <topograsp/kinematics/forward.hpp>

namespace topograsp {

namespace detail {

/// Precision of the backward messages before the first sweep: a small multiple of the identity,
/// so that the first beliefs exist before any backward pass has run.
inline constexpr double k_initial_message_precision = 1e-6;

/// The stages of an AICO sweep (docs/aico.md, "The messages" and "Sweeps"), as Crocoddyl splits
/// its solvers: the task message (2), the belief (5), the capped relinearisation step (7), the
/// forward pass (3), the two backward passes (4: messages; 6: Rauch-Tung-Striebel), and the true
/// cost that the acceptance rule (8) compares. passes() sequences them; sweep() adds the
/// acceptance. Grouped in one struct so that they share the template parameters. Every stage
/// reads the accepted buffers of the workspace and writes its candidate buffers; none allocates.
template <const auto& M, TaskStack Stack, AicoMode Mode>
struct AicoAlgorithm {
  using Problem = AicoProblem<M, Stack, Mode>;
  using Workspace = AicoWorkspace<M, Stack, Mode>;
  using Buffers = typename Workspace::Buffers;
  static constexpr int nq = Problem::nq;
  static constexpr int nx = Problem::nx;
  using Config = Vec<nq>;
  using State = Vec<nx>;
  using StateMatrix = Mat<nx, nx>;

  static auto q_of(const State& x) noexcept { return x.template head<nq>(); }

  /// The task message (2) at configuration \p q of step \p t: R = J'J, r = J'(J q - e),
  /// c = |e|^2. False (and nothing written) if the residual or its Jacobian is not finite.
  static bool task_message(const Problem& p, Workspace& ws, int t, const Config& q, Mat<nq, nq>& R,
                           Config& r, double& c) noexcept {
    forward_kinematics(ws.kinematics, q);
    p.stack().residual(ws.kinematics, t, p.steps(), ws.e, ws.J);
    ++ws.task_evaluations;
    if (!ws.e.allFinite() || !ws.J.allFinite()) return false;
    c = ws.e.squaredNorm();
    R.noalias() = ws.J.transpose() * ws.J;
    ws.e = -ws.e;
    ws.e.noalias() += ws.J * q;  // J q - e
    r.noalias() = ws.J.transpose() * ws.e;
    return std::isfinite(c);
  }

  /// The task cost |e|^2 at \p q of step \p t (NaN if not finite), optionally split per task.
  static double task_cost(const Problem& p, Workspace& ws, int t, const Config& q,
                          bool per_task) noexcept {
    forward_kinematics(ws.kinematics, q);
    p.stack().residual(ws.kinematics, t, p.steps(), ws.e, ws.J);
    if (per_task) add_task_costs<Stack>(ws.e, ws.task_costs);
    return ws.e.squaredNorm();
  }

  /// The belief (5) of step \p t into out.b[t], from the forward message of \p out, the backward
  /// message (\p V_inv, \p hv), the task message of \p out and the damping toward b_ref:
  /// b = (S^-1 + V^-1 + R + alpha I)^-1 (S^-1 s + V^-1 v + r + alpha b_ref). False if the matrix
  /// is not positive definite.
  static bool belief(Workspace& ws, Buffers& out, int t, const StateMatrix& V_inv,
                     const State& hv) noexcept {
    const auto u = static_cast<std::size_t>(t);
    ws.L = out.S_inv[u] + V_inv;
    ws.L.template topLeftCorner<nq, nq>() += out.R[u];
    ws.L.diagonal().array() += ws.alpha;
    ws.rhs = out.h[u] + hv + ws.alpha * ws.b_ref[u];
    ws.rhs.template head<nq>() += out.r[u];
    if (!cholesky_in_place(ws.L)) return false;
    cholesky_solve_in_place(ws.L, ws.rhs);
    out.b[u] = ws.rhs;
    return true;
  }

  /// The capped relinearisation step (7) of step \p t: moves its linearisation point q_hat by
  /// \p d = q(b_t) - q_hat, shortened to length max_step if \p dist = |d|_inf is longer, and
  /// evaluates the task message (2) there. The belief is left as it is. False, with
  /// ws.non_finite set, if the task is not finite at the new point.
  static bool relinearisation_step(const Problem& p, Workspace& ws, Buffers& out, int t,
                                   const Config& d, double dist) noexcept {
    const auto u = static_cast<std::size_t>(t);
    const double max_step = p.options().max_step;
    if (dist > max_step)
      out.q_hat[u] += (max_step / dist) * d;
    else
      out.q_hat[u] = q_of(out.b[u]);
    if (!task_message(p, ws, t, out.q_hat[u], out.R[u], out.r[u], out.c[u])) {
      ws.non_finite = true;
      return false;
    }
    return true;
  }

  /// Relocation of step \p t (local Gauss-Newton sweeps): while its belief is at least tolerance
  /// from its linearisation point, a relinearisation step (7) and a new belief (5) with the
  /// backward message (\p V_inv, \p hv); at most \p times times.
  static bool relocate(const Problem& p, Workspace& ws, Buffers& out, int t,
                       const StateMatrix& V_inv, const State& hv, int times) noexcept {
    const auto u = static_cast<std::size_t>(t);
    for (int k = 0; k < times; ++k) {
      const Config d = q_of(out.b[u]) - out.q_hat[u];
      const double dist = d.template lpNorm<Eigen::Infinity>();
      if (!(dist >= p.options().tolerance)) break;
      if (!relinearisation_step(p, ws, out, t, d, dist)) return false;
      if (!belief(ws, out, t, V_inv, hv)) {
        ws.factor_failed = true;
        return false;
      }
    }
    return true;
  }

  /// Relinearises step \p t at its new belief for the next sweep, keeping the belief: one
  /// relinearisation step (7) whenever the belief moved at all, not only beyond the tolerance:
  /// the true cost of the sweep needs the tasks at the belief anyway (it reuses c), and a model
  /// linearised exactly at the accepted trajectory makes a strongly damped sweep a descent step.
  static bool move_linearisation(const Problem& p, Workspace& ws, Buffers& out, int t) noexcept {
    const auto u = static_cast<std::size_t>(t);
    const Config d = q_of(out.b[u]) - out.q_hat[u];
    const double dist = d.template lpNorm<Eigen::Infinity>();
    if (dist == 0.0) return true;
    return relinearisation_step(p, ws, out, t, d, dist);
  }

  /// The forward pass t = 1..T (3): copies each step's linearisation and belief from the
  /// accepted buffers, then computes its forward message. x_0 is fixed (S_0^-1 -> infinity), so
  /// S_1^-1 = W and S_1^-1 s_1 = W A x_0; for t > 1, with P = S_{t-1}^-1 + R_{t-1} + alpha I and
  /// eta = S_{t-1}^-1 s_{t-1} + r_{t-1} + alpha b_ref_{t-1},
  /// S_t^-1 = A^-T (P - P (K + P)^-1 P) A^-1 = (W^-1 + A P^-1 A')^-1, K = A'WA, and
  /// S_t^-1 s_t = A^-T (eta - P (K + P)^-1 eta). The factor of K + P and eta are kept in
  /// ws.L_forward and ws.eta_forward for the RTS backward pass (6). The belief (5) of a step is
  /// only computed where it is needed: at t = T, and at every step with \p local (local
  /// Gauss-Newton sweeps, with the accepted backward messages), followed by up to \p times
  /// relocations. False if a factorisation failed or a task turned non-finite.
  static bool forward_pass(const Problem& p, Workspace& ws, bool local, int times) noexcept {
    const Buffers& in = ws.accepted();
    Buffers& out = ws.candidate();
    const auto& tr = p.transition();
    const int T = p.steps();
    const auto add_K = [&tr](StateMatrix& m) { tr.add_K(m); };
    auto copy_step = [&](std::size_t u) {
      out.q_hat[u] = in.q_hat[u];
      out.R[u] = in.R[u];
      out.r[u] = in.r[u];
      out.c[u] = in.c[u];
      out.b[u] = in.b[u];
    };
    copy_step(0);
    for (int t = 1; t <= T; ++t) {
      const auto u = static_cast<std::size_t>(t);
      copy_step(u);
      StateMatrix& P = out.S_inv[u];
      State& eta = out.h[u];
      if (t == 1) {
        P = tr.dense_W();
        eta = tr.W_A(p.x_start());
      } else {
        P = out.S_inv[u - 1];
        P.template topLeftCorner<nq, nq>() += out.R[u - 1];
        P.diagonal().array() += ws.alpha;
        eta = out.h[u - 1] + ws.alpha * ws.b_ref[u - 1];
        eta.template head<nq>() += out.r[u - 1];
        ws.eta_forward[u - 1] = eta;
        if (!woodbury_update(P, eta, ws.L_forward[u - 1], ws.Y, ws.z, add_K))
          return ws.factor_failed = true, false;
        tr.congruence_A_inv(P);
        tr.apply_A_inv_transpose(eta);
      }
      if (t < T && !local) continue;
      if (!belief(ws, out, t, in.V_inv[u], in.hv[u])) return ws.factor_failed = true, false;
      if (times > 0 && !relocate(p, ws, out, t, in.V_inv[u], in.hv[u], times)) return false;
    }
    return true;
  }

  /// The Rauch-Tung-Striebel backward pass t = T-1..1 (6) of symmetric sweeps. Given b_{t+1},
  /// x_t only sees its filtered information (P_t, eta_t) and the transition, so
  /// b_t = (K + P_t)^-1 (eta_t + A'W b_{t+1}), with the factor of the forward pass: O(n^2) a
  /// step, the same beliefs as the backward messages (4) and (5) give. With \p relinearise, each
  /// step (T first) is then relinearised at its new belief. Requires forward_pass() first.
  static bool backward_rts(const Problem& p, Workspace& ws, bool relinearise) noexcept {
    Buffers& out = ws.candidate();
    const auto& tr = p.transition();
    const int T = p.steps();
    if (relinearise && !move_linearisation(p, ws, out, T)) return false;
    for (int t = T - 1; t >= 1; --t) {
      const auto u = static_cast<std::size_t>(t);
      ws.rhs = ws.eta_forward[u] + tr.At_W(out.b[u + 1]);
      cholesky_solve_in_place(ws.L_forward[u], ws.rhs);
      out.b[u] = ws.rhs;
      if (relinearise && !move_linearisation(p, ws, out, t)) return false;
    }
    return true;
  }

  /// The backward-message pass t = T-1..1 of local Gauss-Newton sweeps: the backward messages
  /// (4), which the next sweep's forward beliefs need, and the beliefs (5) from them: the exact
  /// smoother at the linearisation the forward pass left, so that b_1..b_T are the damped
  /// Gauss-Newton step of one quadratic model (and dynamically consistent). With
  /// P = V_{t+1}^-1 + R_{t+1} + alpha I and eta = V_{t+1}^-1 v_{t+1} + r_{t+1} + alpha b_ref_{t+1},
  /// V_t^-1 = A' (P - P (W + P)^-1 P) A = A' (W^-1 + P^-1)^-1 A and V_t^-1 v_t =
  /// A' (eta - P (W + P)^-1 eta). The terminal message is the one b_T was computed with. With
  /// \p relinearise, each step t + 1, which no later message of the pass uses, is relinearised at
  /// its new belief (its belief stays the smoother's), and step 1 at the end. Requires
  /// forward_pass() first.
  static bool backward_messages(const Problem& p, Workspace& ws, bool relinearise) noexcept {
    const Buffers& in = ws.accepted();
    Buffers& out = ws.candidate();
    const auto& tr = p.transition();
    const int T = p.steps();
    const auto uT = static_cast<std::size_t>(T);
    const auto add_W = [&tr](StateMatrix& m) { tr.add_W(m); };
    out.V_inv[uT] = in.V_inv[uT];
    out.hv[uT] = in.hv[uT];
    for (int t = T - 1; t >= 1; --t) {
      const auto u = static_cast<std::size_t>(t);
      StateMatrix& P = out.V_inv[u];
      State& eta = out.hv[u];
      P = out.V_inv[u + 1];
      P.template topLeftCorner<nq, nq>() += out.R[u + 1];
      P.diagonal().array() += ws.alpha;
      eta = out.hv[u + 1] + ws.alpha * ws.b_ref[u + 1];
      eta.template head<nq>() += out.r[u + 1];
      if (!woodbury_update(P, eta, ws.L, ws.Y, ws.z, add_W)) return ws.factor_failed = true, false;
      tr.congruence_A(P);
      tr.apply_A_transpose(eta);
      if (relinearise && !move_linearisation(p, ws, out, t + 1)) return false;
      if (!belief(ws, out, t, P, eta)) return ws.factor_failed = true, false;
    }
    if (relinearise && !move_linearisation(p, ws, out, 1)) return false;
    return true;
  }

  /// The terminal message V_T^-1 = terminal_precision I at the new belief of x_T, for the next
  /// sweep (docs/aico.md, after (4)).
  static void refresh_terminal_message(const Problem& p, Buffers& out) noexcept {
    const auto uT = static_cast<std::size_t>(p.steps());
    const double tp = p.options().terminal_precision;
    out.V_inv[uT] = tp * StateMatrix::Identity();
    out.hv[uT] = tp * out.b[uT];
  }

  /// One forward and one backward pass from the accepted buffers into the candidate buffers:
  /// forward_pass(), then backward_rts() in symmetric sweeps or backward_messages() in local
  /// Gauss-Newton sweeps, then the terminal message. Forward relocations: none in symmetric
  /// sweeps (every step is relinearised once, in the backward pass, so a sweep is one damped
  /// Gauss-Newton step of the whole trajectory); up to local_iterations local Gauss-Newton steps
  /// on each step's marginal otherwise. With \p relinearise false the task messages stay fixed:
  /// the message algebra alone.
  static bool passes(const Problem& p, Workspace& ws, bool relinearise) noexcept {
    const bool local = p.options().sweep == SweepMode::local_gauss_newton;
    const int times = relinearise && local ? p.options().local_iterations : 0;
    ws.task_evaluations = 0;
    ws.non_finite = false;
    ws.factor_failed = false;
    if (!forward_pass(p, ws, local, times)) return false;
    if (local ? !backward_messages(p, ws, relinearise) : !backward_rts(p, ws, relinearise))
      return false;
    refresh_terminal_message(p, ws.candidate());
    return true;
  }

  /// The acceptance rule (8), Levenberg-Marquardt on the whole trajectory: if the passes
  /// succeeded (\p ok) and the true cost \p cost of the candidate is finite and not above the
  /// accepted cost, the candidate becomes the accepted trajectory and the damping reference, and
  /// alpha /= damping_decrease; otherwise the accepted buffers stay and alpha *= damping_increase
  /// (alpha = 1 if it was 0). Returns whether the candidate was accepted.
  static bool accept_or_reject(const Problem& p, Workspace& ws, bool ok, double cost) noexcept {
    const AicoOptions& o = p.options();
    if (ok && std::isfinite(cost) && cost <= ws.cost) {
      const auto& cand = ws.candidate().b;
      for (std::size_t u = 0; u < cand.size(); ++u) ws.b_ref[u] = cand[u];
      ws.current = 1 - ws.current;
      ws.cost = cost;
      ws.alpha /= o.damping_decrease;
      return true;
    }
    ws.alpha = ws.alpha > 0.0 ? ws.alpha * o.damping_increase : 1.0;
    return false;
  }

  /// The true objective (1) of the beliefs of \p buf, rolling the task maps out (NaN if not
  /// finite); the task cost of a step linearised at its belief is the c of its task message.
  static double trajectory_cost(const Problem& p, Workspace& ws, const Buffers& buf,
                                double* control = nullptr, bool per_task = false) noexcept {
    const int T = p.steps();
    const auto& tr = p.transition();
    double transition = 0.0, tasks = 0.0;
    if (per_task) ws.task_costs.fill(0.0);
    for (int t = 0; t <= T; ++t) {
      const auto u = static_cast<std::size_t>(t);
      if (t < T) transition += tr.cost(buf.b[u], buf.b[u + 1]);
      const Config q = q_of(buf.b[u]);
      if (!per_task && q == buf.q_hat[u])
        tasks += buf.c[u];
      else
        tasks += task_cost(p, ws, t, q, per_task);
    }
    if (control != nullptr) *control = transition;
    const double total = transition + tasks;
    return std::isfinite(total) ? total : std::nan("");
  }
};

}  // namespace detail

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

namespace detail {

// The message algebra of a sweep alone, for the benchmarks and the tests of the passes: the forward
// and backward passes with their beliefs from the accepted buffers into the candidate buffers, with
// no task re-evaluation and no acceptance step; false if a factorisation failed. Allocates
// nothing.
template <const auto& M, TaskStack Stack, AicoMode Mode>
bool message_passes(const AicoProblem<M, Stack, Mode>& problem,
                    AicoWorkspace<M, Stack, Mode>& ws) noexcept {
  return AicoAlgorithm<M, Stack, Mode>::passes(problem, ws, false);
}

// The candidate beliefs of the last sweep or message pass (T + 1 states, dim nx), accepted or not.
template <const auto& M, TaskStack Stack, AicoMode Mode>
[[nodiscard]] const std::vector<Vec<AicoProblem<M, Stack, Mode>::nx>>& candidate_beliefs(
    AicoWorkspace<M, Stack, Mode>& ws) noexcept {
  return ws.candidate().b;
}

}  // namespace detail

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

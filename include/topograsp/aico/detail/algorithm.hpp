// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The stages of an AICO sweep (internal): detail::AicoAlgorithm (the task message, the belief,
/// the capped relinearisation step, the forward pass, the two backward passes, the acceptance rule
/// and the true cost), and the message algebra alone for the benchmarks and the tests of the
/// passes. aico/solver.hpp sequences them. Equation numbers refer to docs/aico.md.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <topograsp/aico/detail/messages.hpp>
#include <topograsp/aico/detail/task_parts.hpp>
#include <topograsp/aico/problem.hpp>
#include <topograsp/aico/workspace.hpp>
#include <topograsp/kinematics/forward.hpp>

namespace topograsp::detail {

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

}  // namespace topograsp::detail

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// AicoWorkspace: every buffer an AICO solve needs, allocated once.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <topograsp/aico/detail/task_parts.hpp>
#include <topograsp/aico/problem.hpp>

namespace topograsp {

/// Every buffer of an AICO solve for problems of type AicoProblem<M, Stack, Mode>: messages,
/// beliefs, task messages, damping reference and scratch, sized for a number of steps once, so
/// that sweeps allocate nothing. Reusable across solves and problems of the same type (it resizes
/// itself when the number of steps changes). Its contents are internal.
template <const auto& M, TaskStack Stack, AicoMode Mode = AicoMode::dynamic>
struct AicoWorkspace {
  using Problem = AicoProblem<M, Stack, Mode>;
  static constexpr int nq = Problem::nq;
  static constexpr int nx = Problem::nx;
  static constexpr int dim = Problem::task_dim;
  static constexpr std::size_t n_tasks = detail::task_count<Stack>();
  using Config = Vec<nq>;
  using State = Vec<nx>;
  using StateMatrix = Mat<nx, nx>;
  using JointMatrix = Mat<nq, nq>;

  /// Messages, beliefs and linearisation of one trajectory; the workspace keeps two of them, the
  /// accepted one and the one a sweep writes, and swaps them when a sweep is accepted.
  struct Buffers {
    std::vector<StateMatrix> S_inv;  ///< forward message precisions S_t^-1
    std::vector<State> h;            ///< forward information vectors S_t^-1 s_t
    std::vector<StateMatrix> V_inv;  ///< backward message precisions V_t^-1
    std::vector<State> hv;           ///< backward information vectors V_t^-1 v_t
    std::vector<State> b;            ///< belief means b_t
    std::vector<Config> q_hat;       ///< linearisation points (q part of xhat_t)
    std::vector<JointMatrix> R;      ///< task precisions R_t = J'J at q_hat
    std::vector<Config> r;           ///< task information vectors r_t = J'(J q_hat - e)
    std::vector<double> c;           ///< task costs |e|^2 at q_hat

    void resize(std::size_t n) {
      S_inv.resize(n);
      h.resize(n);
      V_inv.resize(n);
      hv.resize(n);
      b.resize(n);
      q_hat.resize(n);
      R.resize(n);
      r.resize(n);
      c.resize(n);
    }
  };

  AicoWorkspace() = default;
  /// A workspace sized for \p problem.
  explicit AicoWorkspace(const Problem& problem) { resize(problem.steps()); }

  /// Sizes every buffer for \p steps time steps (allocates; not needed before solve()). Throws
  /// topograsp::invalid_argument naming "steps" unless it is 1 to k_max_aico_steps.
  void resize(int steps) {
    if (steps < 1 || steps > k_max_aico_steps)
      detail::throw_invalid_argument("steps", "expected 1 to " + std::to_string(k_max_aico_steps) +
                                                  ", got " + std::to_string(steps));
    const auto n = static_cast<std::size_t>(steps + 1);
    buffers[0].resize(n);
    buffers[1].resize(n);
    b_ref.resize(n);
    L_forward.resize(n);
    eta_forward.resize(n);
  }
  /// The number of steps the buffers are sized for.
  [[nodiscard]] int steps() const noexcept { return static_cast<int>(b_ref.size()) - 1; }

  /// The accepted buffers.
  [[nodiscard]] Buffers& accepted() noexcept { return buffers[current]; }
  [[nodiscard]] const Buffers& accepted() const noexcept { return buffers[current]; }
  /// The buffers the next sweep writes.
  [[nodiscard]] Buffers& candidate() noexcept { return buffers[1 - current]; }

  std::array<Buffers, 2> buffers;  ///< accepted and candidate
  int current = 0;                 ///< index of the accepted buffers
  std::vector<State> b_ref;        ///< damping reference: the last accepted beliefs
  /// Cholesky factors of K + P_t (P_t = S_t^-1 + R_t + alpha I) from the forward pass, reused by
  /// the Rauch-Tung-Striebel backward pass of symmetric sweeps.
  std::vector<StateMatrix> L_forward;
  std::vector<State> eta_forward;  ///< the matching S_t^-1 s_t + r_t + alpha b_ref_t

  double alpha = 0.0;          ///< current damping
  double cost = 0.0;           ///< true cost of the accepted trajectory
  int task_evaluations = 0;    ///< task evaluations in the running sweep
  bool non_finite = false;     ///< a task turned non-finite in the running sweep
  bool factor_failed = false;  ///< a Cholesky factorisation failed in the running sweep

  typename Problem::Kinematics kinematics{};  ///< forward-kinematics scratch
  Vec<dim> e = Vec<dim>::Zero();              ///< residual scratch
  Mat<dim, nq> J = Mat<dim, nq>::Zero();      ///< Jacobian scratch
  StateMatrix L = StateMatrix::Zero();        ///< Cholesky factor scratch
  StateMatrix Y = StateMatrix::Zero();        ///< triangular-solve scratch
  State rhs = State::Zero();                  ///< vector scratch
  State z = State::Zero();                    ///< vector scratch
  std::array<double, n_tasks> task_costs{};   ///< per-task cost scratch
};

template <const auto& M, TaskStack Stack, AicoMode Mode>
AicoWorkspace(const AicoProblem<M, Stack, Mode>&) -> AicoWorkspace<M, Stack, Mode>;

}  // namespace topograsp

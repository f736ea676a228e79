// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The linear-Gaussian transition prior of AICO and its structured algebra (internal).
#pragma once

#include <topograsp/aico/options.hpp>
#include <topograsp/core/eigen.hpp>

namespace topograsp::detail {

/// The transition x' = A x + noise(W^-1) of AICO with every matrix kept as scalar blocks.
///
/// Dynamic mode: A = [[I, tau I], [0, I]], W^-1 = Q + B H^-1 B' = [[a I, b I], [b I, c I]] with
/// a = q tau + tau^4 / (4h), b = tau^3 / (2h), c = q tau + tau^2 / h, so W and K = A' W A are
/// also 2 x 2 block matrices of scaled identities and every product with A, W or K costs
/// O(nq^2) instead of O(nq^3). Kinematic mode: A = I, W = K = h I.
template <int NQ, AicoMode Mode>
struct Transition {
  static constexpr int nq = NQ;
  static constexpr int nx = Mode == AicoMode::dynamic ? 2 * NQ : NQ;
  using State = Vec<nx>;
  using StateMatrix = Mat<nx, nx>;

  double tau = 0.0;                        ///< step length (s); unused in kinematic mode
  double h = 0.0;                          ///< control precision
  double qt = 0.0;                         ///< process noise variance q tau (dynamic mode)
  double w11 = 0.0, w12 = 0.0, w22 = 0.0;  ///< W blocks (kinematic: w11 = h)
  double k11 = 0.0, k12 = 0.0, k22 = 0.0;  ///< K = A' W A blocks (kinematic: k11 = h)

  /// The constants for step length \p step (s), control precision \p h and noise rate \p q.
  [[nodiscard]] static Transition make(double step, double h, double q) noexcept {
    Transition tr;
    tr.tau = step;
    tr.h = h;
    tr.qt = q * step;
    if constexpr (Mode == AicoMode::dynamic) {
      const double t2 = step * step, qt = q * step;
      const double a = qt + t2 * t2 / (4.0 * h), b = t2 * step / (2.0 * h), c = qt + t2 / h;
      // det = ac - b^2 written without its cancelling terms (tau^6 / 4h^2 drops out exactly).
      const double det = qt * qt + qt * (t2 * t2 / (4.0 * h) + t2 / h);
      tr.w11 = c / det;
      tr.w12 = -b / det;
      tr.w22 = a / det;
      tr.k11 = tr.w11;
      tr.k12 = step * tr.w11 + tr.w12;
      tr.k22 = t2 * tr.w11 + 2.0 * step * tr.w12 + tr.w22;
    } else {
      tr.w11 = h;
      tr.k11 = h;
    }
    return tr;
  }

  /// m += [[d11 I, d12 I], [d12 I, d22 I]] (kinematic: m += d11 I).
  static void add_blocks(StateMatrix& m, double d11, double d12, double d22) noexcept {
    if constexpr (Mode == AicoMode::dynamic) {
      m.template topLeftCorner<NQ, NQ>().diagonal().array() += d11;
      m.template topRightCorner<NQ, NQ>().diagonal().array() += d12;
      m.template bottomLeftCorner<NQ, NQ>().diagonal().array() += d12;
      m.template bottomRightCorner<NQ, NQ>().diagonal().array() += d22;
    } else {
      m.diagonal().array() += d11;
    }
  }
  /// m += K = A' W A.
  void add_K(StateMatrix& m) const noexcept { add_blocks(m, k11, k12, k22); }
  /// m += W.
  void add_W(StateMatrix& m) const noexcept { add_blocks(m, w11, w12, w22); }

  /// X <- A' X A (X symmetric, dim nx x nx), in O(nq^2).
  void congruence_A(StateMatrix& X) const noexcept { congruence(X, tau); }
  /// X <- A^-T X A^-1, in O(nq^2).
  void congruence_A_inv(StateMatrix& X) const noexcept { congruence(X, -tau); }

  /// v <- A' v.
  void apply_A_transpose(State& v) const noexcept {
    if constexpr (Mode == AicoMode::dynamic) v.template tail<NQ>() += tau * v.template head<NQ>();
  }
  /// v <- A^-T v.
  void apply_A_inv_transpose(State& v) const noexcept {
    if constexpr (Mode == AicoMode::dynamic) v.template tail<NQ>() -= tau * v.template head<NQ>();
  }
  /// W A x.
  [[nodiscard]] State W_A(const State& x) const noexcept {
    State out;
    if constexpr (Mode == AicoMode::dynamic) {
      const Vec<NQ> q = x.template head<NQ>() + tau * x.template tail<NQ>();
      out.template head<NQ>() = w11 * q + w12 * x.template tail<NQ>();
      out.template tail<NQ>() = w12 * q + w22 * x.template tail<NQ>();
    } else {
      out = w11 * x;
    }
    return out;
  }
  /// A' W x.
  [[nodiscard]] State At_W(const State& x) const noexcept {
    State out;
    if constexpr (Mode == AicoMode::dynamic) {
      const auto q = x.template head<NQ>();
      const auto v = x.template tail<NQ>();
      out.template head<NQ>() = w11 * q + w12 * v;
      out.template tail<NQ>() = (tau * w11 + w12) * q + (tau * w12 + w22) * v;
    } else {
      out = w11 * x;
    }
    return out;
  }
  /// W as a dense matrix.
  [[nodiscard]] StateMatrix dense_W() const noexcept {
    StateMatrix m = StateMatrix::Zero();
    add_W(m);
    return m;
  }
  /// The transition cost |x1 - A x0|^2_W. Dynamic mode, without the cancellation of the three
  /// huge W blocks: |d|^2_W = min_u h |u|^2 + |d - B u|^2 / (q tau), attained at
  /// u = B'd / (h q tau + B'B) (B'B = (tau^4/4 + tau^2) I is a scalar), so it is the control cost
  /// of the best control plus the process-noise cost of what no control explains.
  [[nodiscard]] double cost(const State& x0, const State& x1) const noexcept {
    if constexpr (Mode == AicoMode::dynamic) {
      const double t2 = tau * tau, btb = 0.25 * t2 * t2 + t2;
      const Vec<NQ> dq =
          x1.template head<NQ>() - x0.template head<NQ>() - tau * x0.template tail<NQ>();
      const Vec<NQ> dv = x1.template tail<NQ>() - x0.template tail<NQ>();
      const Vec<NQ> u = (0.5 * t2 * dq + tau * dv) / (h * qt + btb);
      return h * u.squaredNorm() +
             ((dq - 0.5 * t2 * u).squaredNorm() + (dv - tau * u).squaredNorm()) / qt;
    } else {
      return w11 * (x1 - x0).squaredNorm();
    }
  }

 private:
  // X <- C' X C with C = [[I, s I], [0, I]]: a handful of scaled block additions.
  static void congruence(StateMatrix& X, double s) noexcept {
    if constexpr (Mode == AicoMode::dynamic) {
      auto X11 = X.template topLeftCorner<NQ, NQ>();
      auto X12 = X.template topRightCorner<NQ, NQ>();
      auto X21 = X.template bottomLeftCorner<NQ, NQ>();
      auto X22 = X.template bottomRightCorner<NQ, NQ>();
      X22 += s * X21;  // X22 + s X21
      X21 += s * X11;  // X21 + s X11
      X12 += s * X11;  // X12 + s X11
      X22 += s * X12;  // X22 + s X21 + s X12 + s^2 X11
    } else {
      (void)X;
      (void)s;
    }
  }
};

}  // namespace topograsp::detail

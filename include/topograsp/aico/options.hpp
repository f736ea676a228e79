// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The parameters of an AICO solve: AicoMode (the state planned over), SweepMode (how often a
/// sweep relinearises a step) and AicoOptions (every numeric parameter, with its default).
#pragma once

#include <string_view>

#include <topograsp/core/parameters.hpp>

namespace topograsp {

/// Which state AICO plans over (docs/aico.md, "The model").
enum class AicoMode {
  /// The state is x = (q, qdot) (2 nq) with the pseudo-dynamics x' = A x + B u + noise,
  /// A = [[I, tau I], [0, I]], B = [[tau^2/2 I], [tau I]]: the paper's mode.
  dynamic,
  /// The state is x = q (nq) with the random-walk prior x' = x + noise of covariance H^-1.
  kinematic,
};

/// How often a sweep relocates (moves the linearisation point and re-evaluates the tasks of) a
/// time step before moving on to the next one.
enum class SweepMode {
  /// At most one relocation per step and pass (Toussaint's "symmetric" sweeps).
  symmetric,
  /// Up to AicoOptions::local_iterations relocations per step and pass, each followed by a new
  /// belief: a few local Gauss-Newton steps on the step's marginal.
  local_gauss_newton,
};

/// "dynamic" or "kinematic".
[[nodiscard]] constexpr std::string_view to_string(AicoMode m) noexcept {
  switch (m) {
    case AicoMode::dynamic:
      return "dynamic";
    case AicoMode::kinematic:
      return "kinematic";
  }
  return "unknown";
}

/// "symmetric" or "local_gauss_newton".
[[nodiscard]] constexpr std::string_view to_string(SweepMode m) noexcept {
  switch (m) {
    case SweepMode::symmetric:
      return "symmetric";
    case SweepMode::local_gauss_newton:
      return "local_gauss_newton";
  }
  return "unknown";
}

/// The largest AicoOptions::steps: 100000 (the workspace holds T + 1 states and messages, so T
/// must stay far from INT_MAX; a motion of 100000 steps is already beyond any use).
inline constexpr int k_max_aico_steps = 100000;

/// The parameters of an AICO solve (docs/aico.md, "Parameters"). Every field has a usable default;
/// AicoProblem's constructor checks them and throws topograsp::invalid_argument naming the first
/// bad field.
///
/// The objective (1) is
/// \f$\sum_{t<T} |x_{t+1} - A x_t|^2_W + \sum_{t \le T} |e_t(q_t)|^2\f$, where \f$e_t\f$ is the
/// whitened task residual of the TaskStack and \f$W^{-1} = Q + B H^{-1} B'\f$ (dynamic mode) or
/// \f$W = H\f$ (kinematic mode).
struct AicoOptions {
  /// Number of time steps T, 1 to k_max_aico_steps; the trajectory has T + 1 states, x_0 being
  /// the fixed start.
  int steps = 50;
  /// Duration of the motion in seconds (1e-6 to 1e6); the step length is tau = duration / steps.
  double duration = 1.0;
  /// Control precision h, H = h I (> 0, at most 1e100). Dynamic mode: a step's control cost is
  /// h |u|^2 with u the joint acceleration (rad/s^2); kinematic mode: h |q_{t+1} - q_t|^2.
  /// Larger values give smoother, shorter motions that reach the task targets less exactly.
  double control_precision = 1.0;
  /// Process noise rate q (> 0 and at most 1e100, dynamic mode only): Q = q tau I. B H^-1 B' has
  /// rank nq only, so Q makes W^-1 invertible; it barely changes the optimum while it stays small.
  double process_noise = 1e-10;
  /// Initial damping alpha (0 to 1e100): the belief is pulled toward the last accepted trajectory
  /// by alpha I (Levenberg-Marquardt on the whole trajectory). 0 gives undamped Gauss-Newton
  /// sweeps.
  double damping = 1.0;
  /// Factor (> 1, at most 1e10) by which alpha grows after a rejected sweep.
  double damping_increase = 10.0;
  /// Divisor (1 to 1e10) by which alpha shrinks after an accepted sweep.
  double damping_decrease = 5.0;
  /// Step tolerance in rad (> 0): a time step is relinearised when its belief moved this far
  /// (infinity norm over q) from its linearisation point, and the solve converges when an
  /// accepted sweep moves no configuration by this much.
  double tolerance = 1e-3;
  /// Largest relinearisation step in rad (> 0, infinity norm over q): a far belief is approached in
  /// steps of at most this length, which keeps the linearisation of the tasks trustworthy.
  double max_step = 0.5;
  /// Relative cost decrease (>= 0) below which an accepted sweep ends the solve.
  double cost_tolerance = 1e-6;
  /// Largest number of sweeps (1 to 1000000), accepted or not.
  int max_sweeps = 60;
  /// Number of rejected sweeps in a row (1 to 1000000) after which the solve gives up.
  int max_rejections = 8;
  /// How often each step is relinearised within a pass.
  SweepMode sweep = SweepMode::symmetric;
  /// Relocations per step and pass in SweepMode::local_gauss_newton (1 to 1000).
  int local_iterations = 5;
  /// Precision (0 to 1e100) of the terminal message V_T^-1: a weak prior at the belief of x_T,
  /// refreshed every sweep. The message updates of this library never invert V_T^-1, so 0 (no
  /// message from beyond T, the exact objective above) is the default.
  double terminal_precision = 0.0;
};

/// The numeric fields of AicoOptions with their valid ranges (AicoProblem checks them;
/// process_noise only in dynamic mode).
inline constexpr ParameterTable<AicoOptions, 14> aico_parameters{{
    {"steps", &AicoOptions::steps, 1, k_max_aico_steps, "time steps T"},
    {"duration", &AicoOptions::duration, 1e-6, 1e6, "s: duration of the motion"},
    {"control_precision", &AicoOptions::control_precision, 0.0, 1e100, "control precision h", true},
    {"process_noise", &AicoOptions::process_noise, 0.0, 1e100,
     "process noise rate q (dynamic mode)", true},
    {"damping", &AicoOptions::damping, 0.0, 1e100, "initial damping alpha"},
    {"damping_increase", &AicoOptions::damping_increase, 1.0, 1e10,
     "alpha's factor after a rejected sweep", true},
    {"damping_decrease", &AicoOptions::damping_decrease, 1.0, 1e10,
     "alpha's divisor after an accepted sweep"},
    {"tolerance", &AicoOptions::tolerance, 0.0, unbounded, "rad: step tolerance", true},
    {"max_step", &AicoOptions::max_step, 0.0, unbounded, "rad: largest relinearisation step", true},
    {"cost_tolerance", &AicoOptions::cost_tolerance, 0.0, unbounded,
     "relative cost decrease that ends the solve"},
    {"max_sweeps", &AicoOptions::max_sweeps, 1, 1000000, "largest number of sweeps"},
    {"max_rejections", &AicoOptions::max_rejections, 1, 1000000,
     "rejected sweeps in a row that end the solve"},
    {"local_iterations", &AicoOptions::local_iterations, 1, 1000,
     "relocations per step and pass (local_gauss_newton)"},
    {"terminal_precision", &AicoOptions::terminal_precision, 0.0, 1e100,
     "precision of the terminal message"},
}};

}  // namespace topograsp

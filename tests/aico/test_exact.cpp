// SPDX-License-Identifier: BSD-3-Clause
// aico.md: for a linear task, one undamped sweep equals the exact minimiser of the quadratic
// objective (the dense normal equations of all states, solved with LDLT), in both modes.
#include <catch2/catch.hpp>

#include <random>
#include <topograsp/aico.hpp>
#include <topograsp/model/models.hpp>

#include "stacks.hpp"

namespace {

using namespace topograsp;

template <AicoMode Mode, const auto& M, int D>
void check_exact(std::uint32_t seed, SweepMode sweep_mode = SweepMode::symmetric) {
  constexpr int nq = M.nq;
  constexpr int nx = Mode == AicoMode::dynamic ? 2 * nq : nq;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const auto random = [&](auto m) {
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      for (Eigen::Index i = 0; i < m.rows(); ++i) m(i, j) = uni(rng);
    return m;
  };

  AicoOptions o;
  o.steps = 12;
  o.duration = 0.6;
  o.control_precision = 2.0;
  o.process_noise = 1e-6;
  o.damping = 0.0;
  o.sweep = sweep_mode;
  const int T = o.steps;
  const double tau = o.duration / T;

  test::LinearStack<M, D> stack;
  stack.C = random(Mat<D, nq>());
  stack.rho_mid = 3.0;
  stack.rho_end = 200.0;
  for (int t = 0; t <= T; ++t) stack.targets.push_back(random(Vec<D>()));
  const Vec<nq> q0 = random(Vec<nq>()), qd0 = 0.3 * random(Vec<nq>());
  AicoProblem<M, test::LinearStack<M, D>, Mode> problem(stack, q0, qd0, o);
  AicoWorkspace ws(problem);
  // A non-trivial initial trajectory: the exact answer must not depend on it.
  std::vector<Vec<nq>> qi, qdi;
  for (int t = 0; t <= T; ++t) {
    qi.push_back(random(Vec<nq>()));
    qdi.push_back(random(Vec<nq>()));
  }
  const double c0 = initialise(problem, ws, qi, qdi);
  const AicoSweepRecord rec = sweep(problem, ws);
  REQUIRE(rec.accepted);
  REQUIRE(rec.cost <= c0);

  // The dense normal equations over z = (x_1..x_T), built independently of the solver.
  Mat<nx, nx> A = Mat<nx, nx>::Identity(), W;
  if constexpr (Mode == AicoMode::dynamic) {
    A.template topRightCorner<nq, nq>() = tau * Mat<nq, nq>::Identity();
    Mat<nx, nq> B;
    B << 0.5 * tau * tau * Mat<nq, nq>::Identity(), tau * Mat<nq, nq>::Identity();
    const Mat<nx, nx> W_inv =
        o.process_noise * tau * Mat<nx, nx>::Identity() + B * B.transpose() / o.control_precision;
    W = W_inv.ldlt().solve(Mat<nx, nx>::Identity());
  } else {
    W = o.control_precision * Mat<nx, nx>::Identity();
  }
  Vec<nx> x0;
  if constexpr (Mode == AicoMode::dynamic)
    x0 << q0, qd0;
  else
    x0 = q0;
  const int n = T * nx;
  MatX H = MatX::Zero(n, n);
  VecX g = VecX::Zero(n);
  const auto blk = [&](int t) { return (t - 1) * nx; };
  for (int t = 0; t < T; ++t) {  // |x_{t+1} - A x_t|^2_W
    H.block(blk(t + 1), blk(t + 1), nx, nx) += W;
    if (t == 0) {
      g.segment(blk(1), nx) += W * A * x0;
    } else {
      H.block(blk(t), blk(t), nx, nx) += A.transpose() * W * A;
      H.block(blk(t), blk(t + 1), nx, nx) -= A.transpose() * W;
      H.block(blk(t + 1), blk(t), nx, nx) -= W * A;
    }
  }
  for (int t = 1; t <= T; ++t) {  // rho_t |C q_t - y_t|^2
    const double rho = t == T ? stack.rho_end : stack.rho_mid;
    H.block(blk(t), blk(t), nq, nq) += rho * stack.C.transpose() * stack.C;
    g.segment(blk(t), nq) += rho * stack.C.transpose() * stack.targets[static_cast<std::size_t>(t)];
  }
  const VecX z = H.ldlt().solve(g);
  double scale = 1.0, err = 0.0;
  for (int t = 1; t <= T; ++t) {
    const Vec<nx> exact = z.segment(blk(t), nx);
    const Vec<nx>& got = ws.accepted().b[static_cast<std::size_t>(t)];
    scale = std::max(scale, exact.template lpNorm<Eigen::Infinity>());
    err = std::max(err, (got - exact).template lpNorm<Eigen::Infinity>());
  }
  INFO("max error " << err << " scale " << scale);
  CHECK(err <= 1e-7 * scale);
  CHECK((ws.accepted().b[0] - x0).norm() == 0.0);
}

}  // namespace

TEST_CASE("one undamped sweep solves a linear task exactly in kinematic mode", "[aico][exact]") {
  check_exact<AicoMode::kinematic, models::schunk_arm, 3>(1);
  check_exact<AicoMode::kinematic, models::schunk_arm, 7>(2);
  check_exact<AicoMode::kinematic, models::schunk_arm_sdh, 5>(3);
}

TEST_CASE("one undamped sweep solves a linear task exactly in dynamic mode", "[aico][exact]") {
  check_exact<AicoMode::dynamic, models::schunk_arm, 3>(4);
  check_exact<AicoMode::dynamic, models::schunk_arm, 7>(5);
  check_exact<AicoMode::dynamic, models::schunk_arm_sdh, 5>(6);
}

TEST_CASE("the RTS and the backward-message passes give the same beliefs", "[aico][exact]") {
  constexpr const auto& arm = models::schunk_arm_sdh;
  using Stack = test::LinearStack<arm, 4>;
  Stack stack;
  stack.C = Mat<4, arm.nq>::Random();
  stack.targets.assign(31, Vec<4>::Random());
  AicoOptions o;
  o.steps = 30;
  o.damping = 0.3;
  const Vec<arm.nq> q0 = Vec<arm.nq>::Random();
  o.sweep = SweepMode::symmetric;
  AicoProblem<arm, Stack> rts(stack, q0, o);
  o.sweep = SweepMode::local_gauss_newton;
  AicoProblem<arm, Stack> messages(stack, q0, o);
  AicoWorkspace ws_a(rts), ws_b(messages);
  (void)initialise(rts, ws_a);
  (void)initialise(messages, ws_b);
  REQUIRE(detail::message_passes(rts, ws_a));
  REQUIRE(detail::message_passes(messages, ws_b));
  const auto& a = detail::candidate_beliefs(ws_a);
  const auto& b = detail::candidate_beliefs(ws_b);
  for (std::size_t u = 0; u < a.size(); ++u)
    CHECK((a[u] - b[u]).norm() <= 1e-8 * (1.0 + b[u].norm()));
}

TEST_CASE("one undamped local Gauss-Newton sweep is exact for a linear task", "[aico][exact]") {
  check_exact<AicoMode::dynamic, models::schunk_arm, 3>(9, SweepMode::local_gauss_newton);
  check_exact<AicoMode::kinematic, models::schunk_arm, 3>(10, SweepMode::local_gauss_newton);
}

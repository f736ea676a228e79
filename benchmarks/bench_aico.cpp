// SPDX-License-Identifier: BSD-3-Clause
// AICO sweeps for the 14-DOF arm + SDH in dynamic mode, T = 100: the message algebra alone, the
// same algebra written the straightforward way with dynamic-size Eigen matrices (the baseline),
// a full sweep with the transfer task set (collision, limits, posture, windings), a whole plan,
// one topological grasp transfer as the experiment runs it (to the SDH on the arm, and to the
// Allegro hand on a free base as grasp_transfer --hand allegro runs it), and the machine's Eigen
// GEMM rate measured in the same run.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <topograsp/aico.hpp>
#include <topograsp/grasp/transfer.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/model/models/allegro_hand.hpp>

#include "../tests/aico/wrap_scene.hpp"

namespace {

using namespace topograsp;
constexpr const auto& robot = models::schunk_arm_sdh;
constexpr int nq = robot.nq;
constexpr int nx = 2 * nq;
constexpr int k_steps = 100;

// Measured in this run by BM_eigen_gemm_256 (GFLOP/s); the sweeps report their share of it.
double g_gemm_gflops = 0.0;
double g_fixed_seconds = 0.0, g_baseline_seconds = 0.0;

// Flops of one symmetric message sweep of this library, n = 2 nq: T - 1 forward updates, each a
// Cholesky of K + P (n^3/3), the triangular solve Y = L^-1 P (n^3) and the rank update P - Y'Y
// (n^3); the belief at T (n^3/3); the Rauch-Tung-Striebel backward pass, two triangular solves a
// step (2 n^2). The O(n^2) block algebra of A, W and K is not counted.
constexpr double sweep_flops() {
  constexpr double n = nx, n3 = n * n * n;
  return (k_steps - 1) * (n3 / 3.0 + 2.0 * n3) + n3 / 3.0 + (k_steps - 1) * 2.0 * n * n;
}

// Process CPU time (s): the machine is shared, wall time would count other people's work.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

void BM_eigen_gemm_256(benchmark::State& state) {
  const MatX a = MatX::Random(256, 256), b = MatX::Random(256, 256);
  MatX c(256, 256);
  for (auto _ : state) {
    c.noalias() = a * b;
    benchmark::DoNotOptimize(c.data());
    benchmark::ClobberMemory();
  }
  const double flops = 2.0 * 256.0 * 256.0 * 256.0;
  state.counters["GFLOP/s"] =
      benchmark::Counter(flops, benchmark::Counter::kIsIterationInvariantRate);
  const double t0 = cpu_seconds();
  for (int i = 0; i < 200; ++i) {
    c.noalias() = a * b;
    benchmark::DoNotOptimize(c.data());
  }
  g_gemm_gflops = 200.0 * flops / (cpu_seconds() - t0) * 1e-9;
}
BENCHMARK(BM_eigen_gemm_256)->Unit(benchmark::kMicrosecond);

// A cheap joint-space stack: detail::message_passes() never evaluates it; it only fills the initial
// task messages with something positive definite.
struct PostureStack {
  using Kinematics = KinematicsData<robot>;
  static constexpr int dim = nq;
  Vec<nq> target = Vec<nq>::Constant(0.3);
  void residual(const Kinematics& d, int t, int T, Vec<nq>& e, Mat<nq, nq>& J) const noexcept {
    const double s = t == T ? 100.0 : 1.0;
    e = s * (d.q - target);
    J = s * Mat<nq, nq>::Identity();
  }
};

AicoOptions bench_options() {
  AicoOptions o;
  o.steps = k_steps;
  o.control_precision = 1e-2;
  return o;
}

void report_share(benchmark::State& state) {
  state.counters["MFLOP/sweep"] = sweep_flops() * 1e-6;
  state.counters["GFLOP/s"] =
      benchmark::Counter(sweep_flops(), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_message_sweep(benchmark::State& state) {
  AicoProblem<robot, PostureStack> problem(PostureStack{}, Vec<nq>::Constant(0.1), bench_options());
  AicoWorkspace ws(problem);
  (void)initialise(problem, ws);
  const double t0 = cpu_seconds();
  std::int64_t n = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(detail::message_passes(problem, ws));
    ++n;
  }
  g_fixed_seconds = (cpu_seconds() - t0) / static_cast<double>(n);
  report_share(state);
  state.counters["share of GEMM"] = sweep_flops() / g_fixed_seconds * 1e-9 / g_gemm_gflops;
}
BENCHMARK(BM_message_sweep)->Unit(benchmark::kMicrosecond);

// The straightforward implementation of the same messages with dynamic-size matrices and
// explicit inverses (aico.md's formulas as written), as the baseline.
struct BaselineSweep {
  int n = nx, T = k_steps;
  MatX A, Winv, Ainv;
  std::vector<MatX> S_inv, V_inv, R;
  std::vector<VecX> s, v, r, b, b_ref;
  double alpha = 0.0;

  BaselineSweep() {
    const double tau = 1.0 / T, h = 1e-2, q = 1e-10;
    A = MatX::Identity(n, n);
    A.topRightCorner(nq, nq) = tau * MatX::Identity(nq, nq);
    Ainv = A.inverse();
    MatX B(n, nq);
    B << 0.5 * tau * tau * MatX::Identity(nq, nq), tau * MatX::Identity(nq, nq);
    Winv = q * tau * MatX::Identity(n, n) + B * B.transpose() / h;
    const auto m = static_cast<std::size_t>(T + 1);
    S_inv.assign(m, 1e-3 * MatX::Identity(n, n));
    V_inv.assign(m, 1e-3 * MatX::Identity(n, n));
    R.assign(m, MatX::Zero(n, n));
    s.assign(m, VecX::Constant(n, 0.1));
    v = s;
    r.assign(m, VecX::Zero(n));
    b = s;
    b_ref = s;
    for (std::size_t t = 0; t < m; ++t) {
      R[t].topLeftCorner(nq, nq) = (t + 1 == m ? 1e4 : 1.0) * MatX::Identity(nq, nq);
      r[t].head(nq) = R[t].topLeftCorner(nq, nq) * VecX::Constant(nq, 0.3);
    }
    S_inv[0] = 1e10 * MatX::Identity(n, n);
  }
  void belief(std::size_t t) {
    const MatX B_inv = S_inv[t] + V_inv[t] + R[t] + alpha * MatX::Identity(n, n);
    b[t] = B_inv.llt().solve(S_inv[t] * s[t] + V_inv[t] * v[t] + r[t] + alpha * b_ref[t]);
  }
  void sweep() {
    const MatX I = MatX::Identity(n, n);
    for (int t = 1; t <= T; ++t) {
      const auto u = static_cast<std::size_t>(t);
      const MatX Sbar = (S_inv[u - 1] + R[u - 1]).llt().solve(I);
      s[u] = A * (Sbar * (S_inv[u - 1] * s[u - 1] + r[u - 1]));
      S_inv[u] = (Winv + A * Sbar * A.transpose()).llt().solve(I);
      belief(u);
    }
    for (int t = T - 1; t >= 0; --t) {
      const auto u = static_cast<std::size_t>(t);
      const MatX Vbar = (V_inv[u + 1] + R[u + 1]).llt().solve(I);
      v[u] = Ainv * (Vbar * (V_inv[u + 1] * v[u + 1] + r[u + 1]));
      V_inv[u] = (A.transpose() * (Winv + Vbar).llt().solve(I) * A);
      belief(u);
    }
  }
};

void BM_message_sweep_dynamic_size_baseline(benchmark::State& state) {
  BaselineSweep base;
  const double t0 = cpu_seconds();
  std::int64_t n = 0;
  for (auto _ : state) {
    base.sweep();
    benchmark::DoNotOptimize(base.b.back().data());
    ++n;
  }
  g_baseline_seconds = (cpu_seconds() - t0) / static_cast<double>(n);
}
BENCHMARK(BM_message_sweep_dynamic_size_baseline)->Unit(benchmark::kMicrosecond);

using TransferStack = TopologicalStack<test::WrapBase, WindingTask<test::wrap_robot, 2>>;

void BM_sweep_with_transfer_tasks(benchmark::State& state) {
  const test::WrapScene scene;
  TransferStack stack{scene.base(), scene.windings(), std::vector<Vec2>(k_steps + 1, scene.goal)};
  AicoProblem<robot, TransferStack> problem(stack, scene.home, bench_options());
  AicoWorkspace ws(problem);
  (void)initialise(problem, ws);
  int task_evaluations = 0;
  for (auto _ : state) {
    // From the same accepted state every time: sweep() writes the candidate buffers, and a
    // rejected sweep leaves the accepted ones as they were; force rejection by undoing accepts.
    const int current = ws.current;
    const double cost = ws.cost, alpha = ws.alpha;
    const AicoSweepRecord rec = sweep(problem, ws);
    task_evaluations = rec.task_evaluations;
    ws.current = current;
    ws.cost = cost;
    ws.alpha = alpha;
  }
  report_share(state);
  state.counters["task evaluations"] = task_evaluations;
}
BENCHMARK(BM_sweep_with_transfer_tasks)->Unit(benchmark::kMicrosecond);

void BM_whole_transfer_plan(benchmark::State& state) {
  const test::WrapScene scene;
  AicoOptions o = bench_options();
  o.max_sweeps = 100;
  int sweeps = 0;
  double error = 0.0;
  for (auto _ : state) {
    const auto r =
        solve_topological<robot>(scene.base(), scene.windings(), scene.goal, scene.home, o);
    sweeps = r.aico.sweeps;
    error = (r.final_value() - scene.goal).lpNorm<Eigen::Infinity>();
  }
  state.counters["sweeps"] = sweeps;
  state.counters["winding error"] = error;
}
BENCHMARK(BM_whole_transfer_plan)->Unit(benchmark::kMillisecond);

// The topological transfer of one human grasp of the hammer as grasp_transfer runs it (T = 40,
// up to 40 sweeps): the AICO plan of the 14-DOF arm + SDH, the final approach, closing and the
// stability suite. "plan ms" is the plan alone.
void BM_transfer_topological_hammer(benchmark::State& state) {
  const GraspObject hammer = objects::hammer();
  const HumanGrasp g = demonstrate(hammer, box_hypotheses(hammer)[26], 26);
  double plan_ms = 0.0;
  int sweeps = 0;
  for (auto _ : state) {
    const SdhTransfer r = transfer_topological(hammer, g);
    plan_ms = r.plan_ms;
    sweeps = r.sweeps;
    benchmark::DoNotOptimize(r.stability.stable);
  }
  state.counters["plan ms"] = plan_ms;
  state.counters["sweeps"] = sweeps;
}
BENCHMARK(BM_transfer_topological_hammer)->Unit(benchmark::kMillisecond);

// The same human grasp transferred to the Allegro hand on a free base (transfer_hand: 22
// coordinates, three winding targets, the same T and sweeps), as grasp_transfer --hand allegro runs
// it.
void BM_transfer_hand_topological_allegro(benchmark::State& state) {
  const GraspObject hammer = objects::hammer();
  const HumanGrasp g = demonstrate(hammer, box_hypotheses(hammer)[26], 26);
  double plan_ms = 0.0;
  int sweeps = 0;
  for (auto _ : state) {
    const auto r =
        transfer_hand<models::allegro_hand>(TransferMethod::topological, hammer, source_grasp(g));
    plan_ms = r.plan_ms;
    sweeps = r.sweeps;
    benchmark::DoNotOptimize(r.stability.stable);
  }
  state.counters["plan ms"] = plan_ms;
  state.counters["sweeps"] = sweeps;
}
BENCHMARK(BM_transfer_hand_topological_allegro)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (g_fixed_seconds > 0.0 && g_baseline_seconds > 0.0)
    std::printf(
        "message sweep (CPU time): %.3f ms fixed-size vs %.3f ms dynamic-size baseline (%.2fx)\n",
        g_fixed_seconds * 1e3, g_baseline_seconds * 1e3, g_baseline_seconds / g_fixed_seconds);
  if (g_fixed_seconds > 0.0 && g_gemm_gflops > 0.0)
    std::printf(
        "message sweep: %.1f MFLOP at %.2f GFLOP/s = %.0f%% of the %.2f GFLOP/s GEMM rate\n",
        sweep_flops() * 1e-6, sweep_flops() / g_fixed_seconds * 1e-9,
        100.0 * sweep_flops() / g_fixed_seconds * 1e-9 / g_gemm_gflops, g_gemm_gflops);
  return 0;
}

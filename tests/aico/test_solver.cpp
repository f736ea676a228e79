// SPDX-License-Identifier: BSD-3-Clause
// The AICO solver on a reaching task: monotone costs, convergence from random starts, warm start,
// bad input and non-finite tasks.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <topograsp/aico.hpp>
#include <topograsp/model/models.hpp>

#include "stacks.hpp"
#include "support/throws.hpp"

namespace {

using namespace topograsp;
constexpr const auto& arm = models::schunk_arm;
constexpr const auto& robot = models::schunk_arm_sdh;
using ArmReach = test::ReachStack<arm, arm.frame("flange")>;
using RobotReach = test::ReachStack<robot, robot.frame("grasp_centre")>;

template <const auto& M>
Vec<M.nq> random_configuration(std::mt19937& rng, double spread) {
  std::uniform_real_distribution<double> uni(-spread, spread);
  Vec<M.nq> q;
  for (int i = 0; i < M.nq; ++i) q[i] = uni(rng);
  return q;
}

template <const auto& M>
Vec3 frame_position(const Vec<M.nq>& q, int frame) {
  KinematicsData<M> d;
  forward_kinematics(d, q);
  return d.frame_p[static_cast<std::size_t>(frame)];
}

template <class Result>
void check_monotone(const Result& r) {
  REQUIRE(!r.cost_history.empty());
  CHECK(r.cost <= r.cost_history.front() * (1.0 + 1e-12));
  for (std::size_t k = 1; k < r.cost_history.size(); ++k)
    CHECK(r.cost_history[k] <= r.cost_history[k - 1]);
  CHECK(r.cost == Approx(r.cost_history.back()).epsilon(1e-9));
  for (const auto& q : r.q) CHECK(q.allFinite());
}

}  // namespace

TEST_CASE("reaching converges from random starts with monotone costs", "[aico][solver]") {
  std::mt19937 rng(42);
  for (AicoMode mode : {AicoMode::dynamic, AicoMode::kinematic}) {
    for (int trial = 0; trial < 4; ++trial) {
      const Vec<arm.nq> q0 = random_configuration<arm>(rng, 1.0);
      // A reachable target: the flange at another random configuration.
      const Vec<arm.nq> q_goal = q0 + random_configuration<arm>(rng, 0.6);
      ArmReach stack;
      stack.target = frame_position<arm>(q_goal, arm.frame("flange"));
      stack.posture = q0;
      AicoOptions o;
      o.steps = 40;
      o.control_precision = mode == AicoMode::dynamic ? 1e-2 : 1.0;
      INFO("mode " << to_string(mode) << " trial " << trial);
      auto check = [&](auto&& r) {
        check_monotone(r);
        CHECK(r.status == Status::success);
        const Vec3 p = frame_position<arm>(r.final_configuration(), arm.frame("flange"));
        CHECK((p - stack.target).norm() < 5e-3);
        REQUIRE(r.task_costs.size() == 2);
        CHECK(r.task_costs[0] + r.task_costs[1] + r.control_cost == Approx(r.cost).epsilon(1e-9));
      };
      if (mode == AicoMode::dynamic) {
        AicoProblem<arm, ArmReach, AicoMode::dynamic> problem(stack, q0, o);
        AicoWorkspace ws(problem);
        check(solve(problem, ws));
      } else {
        AicoProblem<arm, ArmReach, AicoMode::kinematic> problem(stack, q0, o);
        AicoWorkspace ws(problem);
        check(solve(problem, ws));
      }
    }
  }
}

TEST_CASE("both sweep modes reach with the 14-DOF arm and hand", "[aico][solver]") {
  const Vec<robot.nq> q0 = Vec<robot.nq>::Constant(0.2);
  RobotReach stack;
  stack.target = frame_position<robot>(q0, robot.frame("grasp_centre")) + Vec3(0.1, -0.15, -0.1);
  stack.posture = q0;
  for (SweepMode sm : {SweepMode::symmetric, SweepMode::local_gauss_newton}) {
    AicoOptions o;
    o.steps = 50;
    o.control_precision = 1e-2;
    o.sweep = sm;
    AicoProblem<robot, RobotReach> problem(stack, q0, o);
    AicoWorkspace ws(problem);
    const auto r = solve(problem, ws);
    INFO(to_string(sm) << ": " << to_string(r.termination) << " after " << r.sweeps);
    check_monotone(r);
    CHECK(r.ok());
    const Vec3 p = frame_position<robot>(r.final_configuration(), robot.frame("grasp_centre"));
    CHECK((p - stack.target).norm() < 5e-3);
    CHECK(r.q.front() == q0);
    CHECK(r.qdot.front().norm() == 0.0);
  }
}

TEST_CASE("a sweep never returns a worse trajectory, the first one included", "[aico][solver]") {
  // A far target and no damping: the first undamped Gauss-Newton sweep overshoots badly, and
  // must be rejected rather than returned.
  const Vec<arm.nq> q0 = Vec<arm.nq>::Zero();
  ArmReach stack;
  stack.target = Vec3(-0.3, -0.6, 0.4);
  stack.rho_end = 1e6;
  AicoOptions o;
  o.steps = 20;
  o.damping = 0.0;
  o.max_step = 3.0;
  o.control_precision = 1e-3;
  AicoProblem<arm, ArmReach> problem(stack, q0, o);
  AicoWorkspace ws(problem);
  const double c0 = initialise(problem, ws);
  double accepted = c0;
  int rejected = 0;
  for (int k = 0; k < 15; ++k) {
    const AicoSweepRecord rec = sweep(problem, ws);
    if (rec.accepted) {
      CHECK(rec.cost <= accepted);
      accepted = rec.cost;
    } else {
      ++rejected;
      CHECK(rec.cost > accepted);
    }
    CHECK(ws.cost == accepted);
  }
  CHECK(accepted < c0);
  const auto r = continue_solve(problem, ws);
  check_monotone(r);
  CHECK(r.cost <= accepted);
}

TEST_CASE("a warm start from a converged result converges at once", "[aico][solver]") {
  const Vec<arm.nq> q0 = Vec<arm.nq>::Constant(0.3);
  ArmReach stack;
  stack.target = frame_position<arm>(q0, arm.frame("flange")) + Vec3(0.05, 0.1, -0.05);
  AicoOptions o;
  o.steps = 30;
  o.control_precision = 1e-2;
  AicoProblem<arm, ArmReach> problem(stack, q0, o);
  AicoWorkspace ws(problem);
  const auto cold = solve(problem, ws);
  REQUIRE(cold.ok());
  const auto warm = solve(problem, ws, cold);
  check_monotone(warm);
  CHECK(warm.ok());
  CHECK(warm.sweeps < cold.sweeps);
  CHECK(warm.cost <= cold.cost * (1.0 + 1e-9));
  // A warm start from configurations only (velocities by finite differences).
  const auto warm_q = solve(problem, ws, cold.q);
  INFO(to_string(warm_q.termination)
       << " after " << warm_q.sweeps << " sweeps, " << warm_q.rejected << " rejected");
  check_monotone(warm_q);
  CHECK(warm_q.ok());
}

TEST_CASE("bad input throws invalid_argument naming the argument", "[aico][input]") {
  using Problem = AicoProblem<arm, ArmReach>;
  const ArmReach stack;
  const Vec<arm.nq> q0 = Vec<arm.nq>::Zero();
  Vec<arm.nq> nan_q = q0;
  nan_q[3] = std::nan("");
  test::check_throws_naming([&] { Problem p(stack, nan_q); }, "q_start");
  test::check_throws_naming([&] { Problem p(stack, VecX::Zero(3)); }, "q_start");
  AicoOptions o;
  o.steps = 0;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.steps");
  o = {};
  o.control_precision = 0.0;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.control_precision");
  o = {};
  o.control_precision = -1.0;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.control_precision");
  o = {};
  o.process_noise = 0.0;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.process_noise");
  o = {};
  o.duration = std::nan("");
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.duration");
  o = {};
  o.tolerance = -1e-3;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.tolerance");
  o = {};
  o.damping = -1.0;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.damping");
  // Finite but out of the documented ranges: INT_MAX steps overflowed steps + 1.
  o = {};
  o.steps = std::numeric_limits<int>::max();
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.steps");
  o.steps = k_max_aico_steps + 1;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.steps");
  {
    AicoWorkspace<arm, ArmReach> ws;
    test::check_throws_naming([&] { ws.resize(std::numeric_limits<int>::max()); }, "steps");
    test::check_throws_naming([&] { ws.resize(0); }, "steps");
  }
  o = {};
  o.duration = 1e300;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.duration");
  o = {};
  o.duration = 1e-300;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.duration");
  o = {};
  o.control_precision = 1e300;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.control_precision");
  o = {};
  o.process_noise = 1e300;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.process_noise");
  o = {};
  o.terminal_precision = 1e300;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.terminal_precision");
  o = {};
  o.damping_increase = 1e300;
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.damping_increase");
  o = {};
  o.local_iterations = std::numeric_limits<int>::max();
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.local_iterations");
  o = {};
  o.max_sweeps = std::numeric_limits<int>::max();
  test::check_throws_naming([&] { Problem p(stack, q0, o); }, "options.max_sweeps");
  // The bounds themselves are accepted (checked, not solved: k_max_aico_steps is large).
  o = {};
  o.steps = k_max_aico_steps;
  o.duration = 1e6;
  CHECK_NOTHROW(Problem(stack, q0, o));
  // A warm start of the wrong length or with a NaN.
  o = {};
  o.steps = 10;
  Problem p(stack, q0, o);
  AicoWorkspace ws(p);
  test::check_throws_naming([&] { (void)solve(p, ws, std::vector<Vec<arm.nq>>(5, q0)); },
                            "initial");
  std::vector<Vec<arm.nq>> bad(11, q0);
  bad[4] = nan_q;
  test::check_throws_naming([&] { (void)solve(p, ws, bad); }, "initial");
}

TEST_CASE("a task turning non-finite ends the solve with a status, not NaNs", "[aico][input]") {
  const Vec<arm.nq> q0 = Vec<arm.nq>::Zero();
  ArmReach stack;
  // The target asks joint 0 to turn; the task is NaN beyond 0.05 rad of it.
  Vec<arm.nq> q_goal = q0;
  q_goal[0] = 0.8;
  stack.target = frame_position<arm>(q_goal, arm.frame("flange"));
  stack.nan_above = 0.05;
  AicoOptions o;
  o.steps = 20;
  o.control_precision = 1e-2;
  AicoProblem<arm, ArmReach> problem(stack, q0, o);
  AicoWorkspace ws(problem);
  const auto r = solve(problem, ws);
  CHECK(r.status == Status::numerical_issue);
  CHECK(r.termination == AicoTermination::non_finite);
  CHECK(std::isfinite(r.cost));
  for (const auto& q : r.q) CHECK(q.allFinite());
  for (const auto& v : r.qdot) CHECK(v.allFinite());
  check_monotone(r);

  // Non-finite already at the start: nothing to improve, reported as such.
  ArmReach at_start = stack;
  at_start.nan_above = -1.0;
  AicoProblem<arm, ArmReach> p2(at_start, q0, o);
  const auto r2 = solve(p2, ws);
  CHECK(r2.status == Status::numerical_issue);
  CHECK(r2.sweeps == 0);
  for (const auto& q : r2.q) CHECK(q.allFinite());
}

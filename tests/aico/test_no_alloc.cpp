// SPDX-License-Identifier: BSD-3-Clause
// A sweep allocates nothing: Eigen's run-time malloc guard plus a global operator new counter
// (tests/support/allocation_counter.hpp).
#include <catch2/catch.hpp>

#include <topograsp/aico.hpp>
#include <topograsp/model/models.hpp>

#include "stacks.hpp"
#include "support/allocation_counter.hpp"
#include "wrap_scene.hpp"

namespace {

using namespace topograsp;

template <class Problem, class Workspace>
void check_sweeps_do_not_allocate(const Problem& problem, Workspace& ws) {
  (void)initialise(problem, ws);
  const long before = test::allocations();
  Eigen::internal::set_is_malloc_allowed(false);
  int task_evaluations = 0;
  for (int k = 0; k < 3; ++k) task_evaluations += sweep(problem, ws).task_evaluations;
  const bool passes_ok = detail::message_passes(problem, ws);
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(test::allocations() == before);
  CHECK(test::allocation_counter_counts());  // so the check above can fail
  CHECK(task_evaluations > 0);               // the sweeps re-evaluated the tasks
  CHECK(passes_ok);
}

}  // namespace

TEST_CASE("an AICO sweep allocates nothing", "[aico][alloc]") {
  constexpr const auto& robot = models::schunk_arm_sdh;
  using Reach = test::ReachStack<robot, robot.frame("grasp_centre")>;
  Reach stack;
  stack.target = Vec3(0.2, -0.3, 0.7);
  AicoOptions o;
  o.steps = 30;
  for (SweepMode sm : {SweepMode::symmetric, SweepMode::local_gauss_newton}) {
    o.sweep = sm;
    AicoProblem<robot, Reach> dynamic(stack, Vec<robot.nq>::Constant(0.1), o);
    AicoWorkspace ws_d(dynamic);
    check_sweeps_do_not_allocate(dynamic, ws_d);
    AicoProblem<robot, Reach, AicoMode::kinematic> kinematic(stack, Vec<robot.nq>::Constant(0.1),
                                                             o);
    AicoWorkspace ws_k(kinematic);
    check_sweeps_do_not_allocate(kinematic, ws_k);
  }
}

TEST_CASE("a sweep with winding and collision tasks allocates nothing", "[aico][alloc]") {
  const test::WrapScene scene;
  using Stack = TopologicalStack<test::WrapBase, WindingTask<test::wrap_robot, 2>>;
  AicoOptions o;
  o.steps = 20;
  Stack stack{scene.base(), scene.windings(), std::vector<Vec2>(21, scene.goal)};
  AicoProblem<test::wrap_robot, Stack> problem(stack, scene.home, o);
  AicoWorkspace ws(problem);
  check_sweeps_do_not_allocate(problem, ws);
}

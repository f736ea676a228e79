// SPDX-License-Identifier: BSD-3-Clause
// The topological layer on the wrap scene: the SDH on the arm wraps two curves around a cylinder.
#include <catch2/catch.hpp>

#include <topograsp/aico.hpp>

#include "wrap_scene.hpp"

namespace {

using namespace topograsp;

AicoOptions wrap_options() {
  AicoOptions o;
  o.steps = 40;
  o.control_precision = 1e-2;
  o.max_sweeps = 100;
  return o;
}

Vec2 windings_at(const test::WrapScene& scene, const Vec<test::wrap_nq>& q) {
  KinematicsData<test::wrap_robot> d;
  forward_kinematics(d, q);
  return scene.windings().value(d);
}

}  // namespace

TEST_CASE("direct winding targets are reached within 0.05 without collision",
          "[aico][topological]") {
  const test::WrapScene scene;
  TopologicalOptions topo;
  topo.mode = TopologicalMode::direct;
  const auto r = solve_topological<test::wrap_robot>(scene.base(), scene.windings(), scene.goal,
                                                     scene.home, wrap_options(), topo);
  INFO(to_string(r.aico.termination) << " after " << r.aico.sweeps << " sweeps");
  CHECK(r.aico.status != Status::numerical_issue);
  CHECK(r.rounds == 1);
  const Vec2 w = windings_at(scene, r.final_configuration());
  CHECK((w - r.final_value()).norm() < 1e-12);
  CHECK(std::abs(w[0] - scene.goal[0]) < 0.05);
  CHECK(std::abs(w[1] - scene.goal[1]) < 0.05);
  KinematicsData<test::wrap_robot> d;
  forward_kinematics(d, r.final_configuration());
  CHECK(scene.base().collision.min_distance(d) > -0.002);
  // The targets are the straight interpolation from the start's windings.
  REQUIRE(r.targets.size() == 41);
  CHECK((r.targets.back() - scene.goal).norm() < 1e-12);
  CHECK((r.targets.front() - r.values.front()).norm() < 1e-12);
  // Per-task costs: collision, limits, posture, windings.
  CHECK(r.aico.task_costs.size() == 4);
}

TEST_CASE("the coupled topological layer reaches the same goal", "[aico][topological]") {
  const test::WrapScene scene;
  TopologicalOptions topo;
  topo.mode = TopologicalMode::coupled;
  topo.max_rounds = 3;
  AicoOptions o = wrap_options();
  o.steps = 20;  // short, so that the suite stays fast under the sanitizers
  o.max_sweeps = 60;
  const auto r = solve_topological<test::wrap_robot>(scene.base(), scene.windings(), scene.goal,
                                                     scene.home, o, topo);
  INFO(to_string(r.aico.termination) << ", " << r.rounds << " rounds");
  CHECK(r.aico.status != Status::numerical_issue);
  CHECK(r.rounds > 1);
  const Vec2 w = windings_at(scene, r.final_configuration());
  CHECK(std::abs(w[0] - scene.goal[0]) < 0.05);
  CHECK(std::abs(w[1] - scene.goal[1]) < 0.05);
  // The y layer stays pinned at both ends and moves in between.
  CHECK((r.targets.back() - scene.goal).norm() < 1e-12);
  CHECK((r.targets.front() - r.values.front()).norm() < 1e-12);
  KinematicsData<test::wrap_robot> d;
  forward_kinematics(d, r.final_configuration());
  CHECK(scene.base().collision.min_distance(d) > -0.002);
}

TEST_CASE("the y smoother is the exact minimiser of its chain", "[aico][topological]") {
  // Two coordinates, T = 6: compare with the dense normal equations.
  const int T = 6;
  const double w = 3.0, rho = 2.0;
  std::vector<Vec2> y(T + 1, Vec2::Zero()), phi(T + 1);
  y.front() = Vec2(0.1, -0.2);
  y.back() = Vec2(1.0, 0.5);
  for (int t = 0; t <= T; ++t) phi[static_cast<std::size_t>(t)] = Vec2(0.3 * t, std::sin(t));
  detail::smooth_topological_targets(y, phi, w, rho);
  for (int j = 0; j < 2; ++j) {
    MatX H = MatX::Zero(T - 1, T - 1);
    VecX g = VecX::Zero(T - 1);
    for (int i = 0; i < T - 1; ++i) {
      H(i, i) = 2.0 * w + rho;
      if (i > 0) H(i, i - 1) = -w;
      if (i + 1 < T - 1) H(i, i + 1) = -w;
      g[i] = rho * phi[static_cast<std::size_t>(i + 1)][j];
    }
    g[0] += w * y.front()[j];
    g[T - 2] += w * y.back()[j];
    const VecX z = H.ldlt().solve(g);
    for (int i = 0; i < T - 1; ++i) CHECK(y[static_cast<std::size_t>(i + 1)][j] == Approx(z[i]));
  }
}

TEST_CASE("bad topological input throws invalid_argument naming it", "[aico][topological][input]") {
  const test::WrapScene scene;
  TopologicalOptions topo;
  topo.precision = 0.0;
  CHECK_THROWS_WITH(solve_topological<test::wrap_robot>(scene.base(), scene.windings(), scene.goal,
                                                        scene.home, wrap_options(), topo),
                    Catch::StartsWith("topology.precision"));
  CHECK_THROWS_WITH(
      solve_topological<test::wrap_robot>(scene.base(), scene.windings(), Vec2(std::nan(""), 0.0),
                                          scene.home, wrap_options()),
      Catch::StartsWith("goal"));
  AicoOptions o = wrap_options();
  o.steps = 0;
  CHECK_THROWS_AS(solve_topological<test::wrap_robot>(scene.base(), scene.windings(), scene.goal,
                                                      scene.home, o),
                  topograsp::invalid_argument);
}

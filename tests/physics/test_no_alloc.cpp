// SPDX-License-Identifier: BSD-3-Clause
// The stepper alone allocates nothing once its bodies are added: a box, a capsule and a sphere
// resting on the ground (both collider families, warm-started manifolds), counted with a replaced
// global operator new (tests/support/allocation_counter.hpp) and Eigen's run-time malloc guard.
#include "physics_test_support.hpp"

#include <array>

#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

using namespace topograsp;

TEST_CASE("stepping a world of resting bodies allocates nothing", "[physics][alloc]") {
  static const std::array<ShapeSpec, 1> ground{box("", at(0, 0, -0.5), {2.0, 2.0, 0.5})};
  static const std::array<ShapeSpec, 1> block{box("", Pose{}, {0.05, 0.04, 0.03})};
  static const std::array<ShapeSpec, 1> rod{capsule("", {-0.06, 0, 0}, {0.06, 0, 0}, 0.02)};
  static const std::array<ShapeSpec, 1> ball{sphere("", {0, 0, 0}, 0.03)};
  World<double> w;
  BodyDesc d;
  d.type = BodyType::fixed;
  d.shapes = ground;
  (void)w.add_body(d);
  d.type = BodyType::dynamic;
  d.mass = 0.3;
  d.shapes = block;
  d.pose = at(0, 0, 0.03);
  const int b_block = w.add_body(d);
  d.shapes = rod;
  d.pose = at(0.3, 0, 0.02);
  const int b_rod = w.add_body(d);
  d.shapes = ball;
  d.pose = at(-0.3, 0, 0.03);
  const int b_ball = w.add_body(d);
  REQUIRE(w.step() == Status::success);  // the first contacts
  const long before = test::allocations();
  Eigen::internal::set_is_malloc_allowed(false);
  Status s = Status::success;
  for (int i = 0; i < 100 && s == Status::success; ++i) s = w.step();
  Eigen::internal::set_is_malloc_allowed(true);
  const long after = test::allocations();
  CHECK(s == Status::success);
  CHECK(after == before);
  CHECK(test::allocation_counter_counts());  // so the check above can fail
  // The bodies rest on the ground: the contacts were solved, not skipped.
  CHECK(w.body(b_block).x.z() == Approx(0.03).margin(2e-3));
  CHECK(w.body(b_rod).x.z() == Approx(0.02).margin(2e-3));
  CHECK(w.body(b_ball).x.z() == Approx(0.03).margin(2e-3));
}

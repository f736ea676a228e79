// SPDX-License-Identifier: BSD-3-Clause
// Once a scene is built, stepping it allocates nothing: counted with a replaced global operator
// new (tests/support/allocation_counter.hpp) and checked by Eigen's run-time malloc guard. Also:
// the float instantiation compiles and runs.
#include "evaluation_test_support.hpp"

#include <catch2/catch.hpp>

#include "support/allocation_counter.hpp"

using namespace topograsp;

// Explicit instantiation: every member of the hand scene compiles for float (the stepper's own
// instantiations are in tests/physics/test_instantiation.cpp).
template class topograsp::HandScene<models::schunk_sdh, float>;

TEST_CASE("stepping a built scene allocates nothing", "[evaluation][alloc]") {
  auto scene = test::sdh_bottle_scene(1.0);
  REQUIRE(close_hand(scene).status == Status::success);
  const long before = test::allocations();
  Eigen::internal::set_is_malloc_allowed(false);
  Status s = Status::success;
  for (int i = 0; i < 50; ++i) s = scene.step();
  Eigen::internal::set_is_malloc_allowed(true);
  const long after = test::allocations();
  CHECK(s == Status::success);
  CHECK(after == before);
  // The counter does count (so the check above can fail).
  CHECK(test::allocation_counter_counts());
}

TEST_CASE("the stability suite allocates per test, never per step", "[evaluation][alloc]") {
  auto scene = test::sdh_bottle_scene(1.0);
  REQUIRE(close_hand(scene).status == Status::success);
  // The same number of allocations (the scene copies and one force buffer) for 8 times the steps.
  const auto count = [&](int scale) {
    StabilityOptions o;
    o.shake.steps = 20 * scale;
    o.direction_steps = 5 * scale;
    o.hard_shake.steps = 20 * scale;
    o.every_test = true;  // every test at both scales, whatever the verdicts
    const long before = test::allocations();
    const StabilityResult r = stability_suite(scene, o);
    const long n = test::allocations() - before;
    CHECK(r.shake().steps == 20 * scale);
    return n;
  };
  const long few = count(1), many = count(8);
  CHECK(few > 0);  // it does copy the scene
  CHECK(many == few);
  // One working scene for its eight tests, reset by assignment, which reuses the scene's
  // buffers: the suite allocates one copy of the scene and a few records, where one copy per
  // test (8 copies) made a MuJoCo run's heap grow (docs/transfer.md, "Memory").
  auto copy = scene;
  const long before = test::allocations();
  copy = scene;
  const long assigned = test::allocations() - before;
  {
    const auto another = scene;
  }
  const long one_copy = test::allocations() - before - assigned;
  CHECK(assigned == 0);
  REQUIRE(one_copy > 0);
  CHECK(few < 3 * one_copy);
}

TEST_CASE("the float stepper holds a box and a grasp", "[evaluation][float]") {
  World<float> w;
  static const std::array<ShapeSpec, 1> ground{box("", at(0, 0, -0.5), {20.0, 20.0, 0.5})};
  static const std::array<ShapeSpec, 1> cube{box("", Pose{}, {0.1, 0.1, 0.1})};
  BodyDesc g;
  g.type = BodyType::fixed;
  g.shapes = ground;
  w.add_body(g);
  BodyDesc b;
  b.pose = at(0, 0, 0.1);
  b.shapes = cube;
  b.mass = 1.0;
  const int box_id = w.add_body(b);
  for (int i = 0; i < 120; ++i) REQUIRE(w.step() == Status::success);
  CHECK(std::abs(w.body(box_id).x.z() - 0.1f) < 1e-3f);
  CHECK(w.kinetic_energy() < 1e-6f);

  const Eigen::Isometry3d hand = test::sdh_side_pose();
  Vec<7> q;
  q << 0.0, -0.6, 0.3, -0.6, 0.3, -0.6, 0.3;
  HandScene<models::schunk_sdh, float> scene(
      hand, q,
      test::cylinder_object(hand, Eigen::Vector3d(0, 0, 0.15), Eigen::Vector3d::UnitY(), 0.035, 0.1,
                            0.5));
  REQUIRE(close_hand(scene).status == Status::success);
  StabilityOptions o;
  o.hard_shake.steps = 0;
  const StabilityResult r = stability_suite(scene, o);
  CHECK(r.stable);
}

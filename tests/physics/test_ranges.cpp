// SPDX-License-Identifier: BSD-3-Clause
// What the stepper cannot represent is refused up front (sizes, masses, inertias, velocities,
// poses, a time step too long for the contacts), and a state that still goes wrong ends the run
// with Status::numerical_issue in the step where it happens, never with a NaN under success.
#include "physics_test_support.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

using namespace topograsp;

namespace {

ShapeSpec sphere_of(double r) {
  ShapeSpec s;
  s.type = ShapeType::sphere;
  s.size = {r, 0.0, 0.0};
  return s;
}

// A dynamic body of one shape; mass 0 takes the density.
template <class S>
int add(World<S>& w, const ShapeSpec& shape, double mass, double density = 1000.0) {
  const std::array<ShapeSpec, 1> shapes{shape};
  BodyDesc d;
  d.shapes = shapes;
  d.mass = mass;
  d.density = density;
  return w.add_body(d);
}

// Every number a body exposes, finite.
template <class S>
bool all_finite(const World<S>& w) {
  for (int i = 0; i < w.body_count(); ++i) {
    const RigidBody<S>& b = w.body(i);
    if (!b.x.allFinite() || !b.v.allFinite() || !b.w.allFinite() || !b.q.coeffs().allFinite() ||
        !b.inertia.allFinite() || !b.inv_inertia.allFinite() || !std::isfinite(b.mass) ||
        !std::isfinite(b.kinetic_energy()))
      return false;
  }
  return std::isfinite(w.kinetic_energy());
}

}  // namespace

TEST_CASE("the world refuses sizes whose derived quantities overflow", "[physics][input]") {
  // Radius 1e-120 with a density: the mass (r^3) and inertia (r^5) underflow to 0.
  test::check_throws_naming(
      [] {
        World<> w;
        (void)add(w, sphere_of(1e-120), 0.0);
      },
      "desc.density");
  // Radius 1e120: the mass from the density overflows.
  test::check_throws_naming(
      [] {
        World<> w;
        (void)add(w, sphere_of(1e120), 0.0);
      },
      "desc.density");
  // Radius 1e150 with a mass of 1e10 kg: the inertia 0.4 m r^2 overflows.
  test::check_throws_naming(
      [] {
        World<> w;
        (void)add(w, sphere_of(1e150), 1e10);
      },
      "desc.mass");
  // Radius 1e120 with a mass of 1 kg is representable (inertia 4e239 kg m^2, its kinetic energy
  // at max_speed 4e243 J): accepted, and it steps with finite numbers.
  {
    World<> w;
    (void)add(w, sphere_of(1e120), 1.0);
    CHECK(w.step() == Status::success);
    CHECK(all_finite(w));
  }
  // Beyond the length range of the scalar: squares of sizes overflow or underflow.
  test::check_throws_naming(
      [] {
        World<> w;
        (void)add(w, sphere_of(1e200), 1.0);
      },
      "desc.shapes[0].size[0]");
  test::check_throws_naming(
      [] {
        World<> w;
        (void)add(w, sphere_of(1e-200), 1.0);
      },
      "desc.shapes[0].size[0]");
  test::check_throws_naming(
      [] {
        World<float> w;
        (void)add(w, sphere_of(1e20), 1.0);
      },
      "desc.shapes[0].size[0]");
  // The refusal names the range, readably.
  try {
    World<> w;
    (void)add(w, sphere_of(1e200), 1.0);
  } catch (const invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("expected a size in [") && Catch::Contains("1e+200"));
  }
  // A pose beyond the length range.
  test::check_throws_naming(
      [] {
        World<> w;
        const std::array<ShapeSpec, 1> shapes{sphere_of(0.1)};
        BodyDesc d;
        d.shapes = shapes;
        d.pose.p = {0.0, 0.0, 1e300};
        (void)w.add_body(d);
      },
      "desc.pose");
  // Sizes at the edges of the documented range are accepted and stay finite.
  World<> w;
  (void)add(w, sphere_of(1e-3), 1e-3);
  (void)add(w, sphere_of(1e3), 1e3);
  CHECK(all_finite(w));
}

TEST_CASE("the world refuses masses the scalar type cannot represent", "[physics][input]") {
  // 1e300 kg is a double but not a float.
  test::check_throws_naming(
      [] {
        World<float> w;
        (void)add(w, sphere_of(0.1), 1e300);
      },
      "desc.mass");
  // 1e300 kg in double: its kinetic energy at max_speed (100 m/s) is 5e303 J, finite: accepted.
  // 1e306 kg is not (5e309 J).
  {
    World<> w;
    CHECK_NOTHROW(add(w, sphere_of(0.1), 1e300));
    CHECK(all_finite(w));
  }
  test::check_throws_naming(
      [] {
        World<> w;
        (void)add(w, sphere_of(0.1), 1e306);
      },
      "desc.mass");
  // A tiny mass whose inverse overflows.
  test::check_throws_naming(
      [] {
        World<> w;
        (void)add(w, sphere_of(0.1), 1e-320);
      },
      "desc.mass");
  test::check_throws_naming(
      [] {
        World<float> w;
        (void)add(w, sphere_of(0.1), 1e-40);
      },
      "desc.mass");
  // A float world with a sane body works.
  World<float> wf;
  (void)add(wf, sphere_of(0.05), 0.2);
  for (int k = 0; k < 5; ++k) CHECK(wf.step() == Status::success);
  CHECK(all_finite(wf));
}

TEST_CASE("the world refuses velocities above max_speed", "[physics][input]") {
  World<> w;
  const int b = add(w, sphere_of(0.1), 1.0);
  test::check_throws_naming([&] { w.set_velocity(b, Vec3(0, 0, 1e308), Vec3::Zero()); }, "v");
  test::check_throws_naming([&] { w.set_velocity(b, Vec3::Zero(), Vec3(1e308, 0, 0)); }, "w");
  test::check_throws_naming([&] { w.set_velocity(b, Vec3(0, 0, 100.5), Vec3::Zero()); }, "v");
  CHECK(all_finite(w));
  w.set_velocity(b, Vec3(0, 0, 99.0), Vec3(0, 50.0, 0));
  CHECK(std::isfinite(w.kinetic_energy()));
  // max_speed itself must have a finite square.
  test::check_throws_naming(
      [] {
        StepperOptions o;
        o.max_speed = 1e200;
        World<> world(o);
      },
      "options.max_speed");
  test::check_throws_naming(
      [] {
        StepperOptions o;
        o.max_speed = 1e20;
        World<float> world(o);
      },
      "options.max_speed");
}

TEST_CASE("a time step too long for the contacts to catch a fall is refused", "[physics][input]") {
  // With a 1 s step a box fell 9.8 m in its first step, through a 1 m thick ground, and the run
  // was reported a success for 11 steps.
  test::check_throws_naming(
      [] {
        StepperOptions o;
        o.time_step = 1.0;
        World<> w(o);
      },
      "options.time_step");
  try {
    StepperOptions o;
    o.time_step = 1.0;
    World<> w(o);
  } catch (const invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("speculative_distance") &&
                             Catch::Contains("use a shorter time step"));
  }
  // The bound: |g| dt^2 <= speculative_distance. Just within and just beyond it.
  StepperOptions o;
  o.time_step = std::sqrt(o.speculative_distance / standard_gravity) * 0.999;
  CHECK_NOTHROW(World<>(o));
  o.time_step = std::sqrt(o.speculative_distance / standard_gravity) * 1.001;
  CHECK_THROWS_AS(World<>(o), invalid_argument);
  // Without gravity any step is accepted; a larger speculative distance allows a longer step.
  o.gravity = {0.0, 0.0, 0.0};
  o.time_step = 1.0;
  CHECK_NOTHROW(World<>(o));
  // A step too short for the scalar: 1.6e-203 s is 0 in float, and the step divided by it left
  // NaN in the contacts (found by fuzz_stepper: fuzz/regressions/stepper).
  test::check_throws_naming(
      [] {
        StepperOptions so;
        so.time_step = 1.6e-203;
        World<float> w(so);
      },
      "options.time_step");
  o.time_step = 1e-6;
  CHECK_NOTHROW(World<float>(o));
  // Without gravity no fall bounds the step: 1e291 s is inf in float (a kinematic body's pose
  // became inf with status success).
  o.time_step = 1e291;
  test::check_throws_naming([&] { World<float> w(o); }, "options.time_step");
  CHECK_NOTHROW(World<double>(o));
  // Sub-steps: INT_MAX would be a hang of 2e9 sub-steps per step.
  test::check_throws_naming(
      [] {
        StepperOptions so;
        so.substeps = std::numeric_limits<int>::max();
        World<> world(so);
      },
      "options.substeps");
  // set_gravity keeps the bound.
  World<> w;
  test::check_throws_naming([&] { w.set_gravity(Vec3(0, 0, -1e3)); }, "g");
  CHECK_NOTHROW(w.set_gravity(Vec3(0, -9.81, 0)));
  // The defaults and the shake test's step satisfy it.
  CHECK_NOTHROW(World<>());
}

TEST_CASE("a box on the ground at the longest accepted step does not fall through",
          "[physics][input]") {
  StepperOptions o;
  o.time_step = std::sqrt(o.speculative_distance / standard_gravity);
  World<> w(o);
  const std::array<ShapeSpec, 1> ground_shape{box("", Pose{}, {2.0, 2.0, 0.5})};
  BodyDesc ground;
  ground.type = BodyType::fixed;
  ground.shapes = ground_shape;
  ground.pose.p = {0.0, 0.0, -0.5};
  (void)w.add_body(ground);
  const std::array<ShapeSpec, 1> cube{box("", Pose{}, {0.05, 0.05, 0.05})};
  BodyDesc d;
  d.shapes = cube;
  d.mass = 1.0;
  d.pose.p = {0.0, 0.0, 0.3};
  const int b = w.add_body(d);
  for (int k = 0; k < 200; ++k) REQUIRE(w.step() == Status::success);
  CHECK(w.body(b).x.z() == Approx(0.05).margin(0.01));
}

TEST_CASE("poses beyond the length range are refused by set_pose and set_target",
          "[physics][input]") {
  World<> w;
  const std::array<ShapeSpec, 1> shapes{sphere_of(0.02)};
  BodyDesc k;
  k.type = BodyType::kinematic;
  k.shapes = shapes;
  const int hand = w.add_body(k);
  const int ball = add(w, sphere_of(0.05), 0.1);
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Vec3(0, 0, 1.7e308);
  test::check_throws_naming([&] { w.set_target(hand, far); }, "pose");
  test::check_throws_naming([&] { w.set_pose(ball, far); }, "pose");
  CHECK_FALSE(World<>::target_in_range(far));
  far.translation() = Vec3(0, 0, 1.0);
  CHECK(World<>::target_in_range(far));
  CHECK(World<float>::max_length() < 1e17f);
  CHECK(World<double>::max_length() > 1e150);
}

TEST_CASE("a state that leaves the representable range ends the run in that step",
          "[physics][input]") {
  // A body at the edge of the position range moving outward: the first step that takes it past
  // max_length() is refused with numerical_issue, and every number stays finite.
  StepperOptions o;
  o.gravity = {0.0, 0.0, 0.0};
  o.time_step = 1e200;  // 50 m/s for 1e200 s: 5e201 m, beyond max_length() (1.3e151 m)
  World<> w(o);
  const int b = add(w, sphere_of(1.0), 1.0);
  w.set_velocity(b, Vec3(0, 0, 50.0), Vec3::Zero());
  CHECK(w.step() == Status::numerical_issue);
  CHECK(w.steps() == 0);
  CHECK(all_finite(w));
  CHECK(w.body(b).x.z() == 0.0);  // the step was undone
  CHECK(w.step() == Status::numerical_issue);
}

TEST_CASE("a ball deep inside a huge turning sphere keeps its contact point near it",
          "[physics][input]") {
  // Found by fuzz_stepper (fuzz/regressions/stepper/deep_overlap_far_contact_point): the point
  // midway between the surfaces of a 0.4 m ball and a kinematic sphere of radius 1e127 around it
  // lay 5e126 m away; the sphere's spin times that lever arm overflowed the solver (NaN impulse).
  // The point is kept within twice the smaller shape's bounding radius of its centre.
  World<> w;
  BodyDesc k;
  k.type = BodyType::kinematic;
  const std::array<ShapeSpec, 1> huge{sphere_of(1e127)};
  k.shapes = huge;
  const int shell = w.add_body(k);
  const int ball = add(w, sphere_of(0.4), 7.0);
  w.set_velocity(shell, Vec3(-5, -5, -5), Vec3(-10, -10, -10));
  w.set_velocity(ball, Vec3(-7, 0, 9), Vec3(0, 4.6, -2.5));
  for (int s = 0; s < 3; ++s) REQUIRE(w.step() == Status::success);
  CHECK(all_finite(w));
  // (Taken at the last step's start: the ball has moved on by less than 0.2 m since.)
  for (const Manifold<double>& m : w.manifolds())
    for (int i = 0; i < m.count; ++i)
      CHECK((m.points[static_cast<std::size_t>(i)].point - w.body(ball).x).norm() <
            2.0 * 0.4 + w.options().speculative_distance + 0.2);
}

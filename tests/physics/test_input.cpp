// SPDX-License-Identifier: BSD-3-Clause
// Bad input to the stepper itself (the World, without a hand scene) throws naming the argument.
#include "physics_test_support.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

using namespace topograsp;

TEST_CASE("bad input to the world throws naming the argument", "[physics][input]") {
  static const std::array<ShapeSpec, 1> cube{box("", Pose{}, {0.1, 0.1, 0.1})};
  BodyDesc good;
  good.shapes = cube;
  good.mass = 1.0;
  test::check_throws_naming(
      [] {
        StepperOptions o;
        o.time_step = 0.0;
        World<> w(o);
      },
      "options.time_step");
  test::check_throws_naming(
      [] {
        StepperOptions o;
        o.substeps = 0;
        World<> w(o);
      },
      "options.substeps");
  test::check_throws_naming(
      [] {
        StepperOptions o;
        o.gravity[2] = std::nan("");
        World<> w(o);
      },
      "options.gravity");
  test::check_throws_naming(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.shapes = {};
        w.add_body(d);
      },
      "desc.shapes");
  test::check_throws_naming(
      [&] {
        World<> w;
        std::array<ShapeSpec, 1> flat = cube;
        flat[0].size[2] = 0.0;
        BodyDesc d = good;
        d.shapes = flat;
        w.add_body(d);
      },
      "desc.shapes[0].size[2]");
  test::check_throws_naming(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.pose.p[0] = std::numeric_limits<double>::infinity();
        w.add_body(d);
      },
      "desc.pose");
  test::check_throws_naming(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.friction = -0.1;
        w.add_body(d);
      },
      "desc.friction");
  test::check_throws_naming(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.mass = -1.0;
        w.add_body(d);
      },
      "mass");
  test::check_throws_naming(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.mass = 0.0;
        d.density = 0.0;
        w.add_body(d);
      },
      "density");
  test::check_throws_naming(
      [&] {
        World<> w;
        const int b = w.add_body(good);  // dynamic
        w.set_target(b, Eigen::Isometry3d::Identity());
      },
      "body");
  test::check_throws_naming(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.type = BodyType::kinematic;
        const int b = w.add_body(d);
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.translation().y() = std::nan("");
        w.set_target(b, T);
      },
      "pose");
}

TEST_CASE("a held body stays put under gravity and contact, and is itself again once released",
          "[physics][held]") {
  static const std::array<ShapeSpec, 1> cube{box("", Pose{}, {0.05, 0.05, 0.05})};
  World<> w;
  BodyDesc ground;
  ground.type = BodyType::fixed;
  ground.shapes = cube;
  const int g = w.add_body(ground);
  BodyDesc d;
  d.shapes = cube;
  d.mass = 2.0;
  d.pose = at(0.0, 0.0, 0.5);
  const int b = w.add_body(d);
  w.set_velocity(b, {0.0, 0.0, -1.0}, {0.0, 0.0, 0.0});
  w.set_held(b, true);
  CHECK(w.held(b));
  for (int k = 0; k < 30; ++k) REQUIRE(w.step() == Status::success);
  CHECK(w.body(b).pose().translation().z() == 0.5);  // neither its velocity nor gravity moved it
  w.set_held(b, false);
  CHECK(w.body(b).inv_mass == 0.5);
  for (int k = 0; k < 30; ++k) REQUIRE(w.step() == Status::success);
  CHECK(w.body(b).pose().translation().z() < 0.5);  // released at rest, it falls
  test::check_throws_naming([&] { w.set_held(g, true); }, "body");
  test::check_throws_naming([&] { w.set_held(7, true); }, "body");
}

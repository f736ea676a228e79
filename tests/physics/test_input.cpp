// SPDX-License-Identifier: BSD-3-Clause
// Bad input to the stepper itself (the World, without a hand scene) throws naming the argument.
#include "physics_test_support.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

using namespace topograsp;

TEST_CASE("bad input to the world throws naming the argument", "[physics][input]") {
  const auto throws_with = [](auto&& f, const std::string& name) {
    try {
      f();
    } catch (const topograsp::invalid_argument& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).rfind(name, 0) == 0);
      return;
    }
    FAIL("no topograsp::invalid_argument for " << name);
  };
  static const std::array<ShapeSpec, 1> cube{box("", Pose{}, {0.1, 0.1, 0.1})};
  BodyDesc good;
  good.shapes = cube;
  good.mass = 1.0;
  throws_with(
      [] {
        StepperOptions o;
        o.time_step = 0.0;
        World<> w(o);
      },
      "options.time_step");
  throws_with(
      [] {
        StepperOptions o;
        o.substeps = 0;
        World<> w(o);
      },
      "options.substeps");
  throws_with(
      [] {
        StepperOptions o;
        o.gravity[2] = std::nan("");
        World<> w(o);
      },
      "options.gravity");
  throws_with(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.shapes = {};
        w.add_body(d);
      },
      "desc.shapes");
  throws_with(
      [&] {
        World<> w;
        std::array<ShapeSpec, 1> flat = cube;
        flat[0].size[2] = 0.0;
        BodyDesc d = good;
        d.shapes = flat;
        w.add_body(d);
      },
      "desc.shapes[0].size[2]");
  throws_with(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.pose.p[0] = std::numeric_limits<double>::infinity();
        w.add_body(d);
      },
      "desc.pose");
  throws_with(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.friction = -0.1;
        w.add_body(d);
      },
      "desc.friction");
  throws_with(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.mass = -1.0;
        w.add_body(d);
      },
      "mass");
  throws_with(
      [&] {
        World<> w;
        BodyDesc d = good;
        d.mass = 0.0;
        d.density = 0.0;
        w.add_body(d);
      },
      "density");
  throws_with(
      [&] {
        World<> w;
        const int b = w.add_body(good);  // dynamic
        w.set_target(b, Eigen::Isometry3d::Identity());
      },
      "body");
  throws_with(
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

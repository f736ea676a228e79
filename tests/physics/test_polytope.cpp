// SPDX-License-Identifier: BSD-3-Clause
// The polytopes of boxes and cylinders: degenerate sizes throw instead of overrunning the
// polytope's arrays (found by fuzz/narrow_phase and fuzz/stepper: a World<float> cylinder whose
// half height rounds to 0 in float wrote past Polytope::directions).
#include "physics_test_support.hpp"

#include <array>
#include <limits>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

using namespace topograsp;

TEST_CASE("box and cylinder polytopes have their edge directions", "[physics][polytope]") {
  const Polytope<double> box = box_polytope<double>(Eigen::Vector3d(0.1, 0.2, 0.3));
  CHECK(box.n_vertices == 8);
  CHECK(box.n_edges == 12);
  CHECK(box.n_directions == 3);
  const Polytope<double> cyl = cylinder_polytope<double>(0.05, 0.1);
  CHECK(cyl.n_vertices == 2 * cylinder_prism_sides);
  CHECK(cyl.n_directions == Polytope<double>::max_directions);  // the axis and 8 cap directions
  // Tiny but representable: the squared edge lengths underflow, the directions do not.
  const Polytope<double> tiny = cylinder_polytope<double>(1e-200, 1e-200);
  CHECK(tiny.n_directions == Polytope<double>::max_directions);
  for (int k = 0; k < tiny.n_directions; ++k)
    CHECK(tiny.directions[static_cast<std::size_t>(k)].norm() == Approx(1.0));
  const Polytope<float> flat = box_polytope<float>(Eigen::Vector3f(1.0f, 1.0f, 1e-30f));
  CHECK(flat.n_directions == 3);
  for (int k = 0; k < flat.n_directions; ++k)
    CHECK(flat.directions[static_cast<std::size_t>(k)].norm() == Approx(1.0));
}

TEST_CASE("degenerate polytope sizes throw naming the size", "[physics][polytope][input]") {
  test::check_throws_naming([] { (void)cylinder_polytope<double>(0.1, 0.0); }, "half_height");
  test::check_throws_naming([] { (void)cylinder_polytope<double>(0.0, 0.1); }, "radius");
  test::check_throws_naming([] { (void)cylinder_polytope<double>(-1.0, 0.1); }, "radius");
  test::check_throws_naming(
      [] { (void)cylinder_polytope<double>(std::numeric_limits<double>::infinity(), 0.1); },
      "radius");
  test::check_throws_naming([] { (void)box_polytope<double>(Eigen::Vector3d(0.1, 0.0, 0.1)); },
                            "h");
  // Positive, but the vertices coincide in the scalar type: too small (subnormal radius) or too
  // large (the edges overflow).
  const float tiny = std::numeric_limits<float>::denorm_min();
  test::check_throws_naming([&] { (void)cylinder_polytope<float>(tiny, 1.0f); }, "radius");
  test::check_throws_naming([] { (void)box_polytope<double>(Eigen::Vector3d(1.0, 1.0, 1e308)); },
                            "h");
  // Positive, but too thin to order the vertices of the prism's sides (in double, 1e-17 gave more
  // than the 48 edges a polytope holds; 1e-16 is still resolved).
  const Polytope<double> thin = cylinder_polytope<double>(1.0, 1e-16);
  CHECK(thin.n_edges == Polytope<double>::max_edges);
  CHECK(thin.n_vertices - thin.n_edges + thin.n_faces == 2);
  test::check_throws_naming([] { (void)cylinder_polytope<double>(1.0, 1e-17); }, "half_height");
  test::check_throws_naming([] { (void)cylinder_polytope<double>(1e-16, 1.0); }, "radius");
  test::check_throws_naming([] { (void)cylinder_polytope<float>(1.0f, 1e-30f); }, "half_height");
}

TEST_CASE("a World<float> refuses a cylinder whose size rounds to 0 in float",
          "[physics][polytope][input]") {
  World<float> world;
  const std::array<ShapeSpec, 1> shapes{cylinder("", Pose{}, 0.05, 1e-300)};
  BodyDesc desc;
  desc.shapes = shapes;
  desc.mass = 1.0;
  CHECK_THROWS_AS(world.add_body(desc), topograsp::invalid_argument);
}

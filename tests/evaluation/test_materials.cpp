// SPDX-License-Identifier: BSD-3-Clause
// An object of several materials in a hand scene: per-part densities and friction per pair.
#include "evaluation_test_support.hpp"

#include <limits>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

using namespace topograsp;
using test::cylinder_object;

namespace {

// A two-part object (two cylinders end to end along the cylinder axis) 0.16 m in front of the
// SDH's palm.
ObjectSpec two_part_object(const Eigen::Isometry3d& hand) {
  ObjectSpec o = cylinder_object(hand, {0, 0, 0.16}, Eigen::Vector3d::UnitY(), 0.03, 0.05, 0.5);
  o.shapes = {cylinder("", at(0, 0, -0.05), 0.03, 0.05), cylinder("", at(0, 0, 0.05), 0.03, 0.05)};
  return o;
}

}  // namespace

TEST_CASE(
    "part densities give the object's mass and centre; part friction is set on every hand "
    "pair of that part",
    "[evaluation][materials]") {
  const Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  const Vec<7> q = Vec<7>::Zero();
  ObjectSpec o = two_part_object(hand);
  o.mass = 0.0;
  o.part_density = {1000.0, 3000.0};
  o.part_friction = {0.3, 0.7};
  HandSceneOptions so;
  so.friction = 1.0;
  const HandScene<models::schunk_sdh> scene(hand, q, o, so);
  const World<double>& w = scene.world();
  const RigidBody<double>& ob = w.body(scene.object_body());
  const double v = pi * 0.03 * 0.03 * 0.1;  // each part's volume
  CHECK(ob.mass == Approx(4000.0 * v).epsilon(1e-12));
  CHECK(ob.local_com.z() == Approx(0.025).epsilon(1e-12));  // (-0.05 * 1 + 0.05 * 3) / 4
  int hand_pairs = 0;
  for (const Manifold<double>& m : w.manifolds()) {
    const int a = m.body_a == scene.object_body() ? m.collider_a : m.collider_b;
    REQUIRE((m.body_a == scene.object_body() || m.body_b == scene.object_body()));
    const int part = a - ob.first_collider;
    REQUIRE((part == 0 || part == 1));
    CHECK(m.friction == Approx(part == 0 ? 0.3 : 0.7));
    ++hand_pairs;
  }
  CHECK(hand_pairs == 2 * (w.collider_count() - ob.n_colliders));
  // Without part friction every pair has HandSceneOptions::friction.
  o.part_friction.clear();
  const HandScene<models::schunk_sdh> uniform(hand, q, o, so);
  for (const Manifold<double>& m : uniform.world().manifolds()) CHECK(m.friction == Approx(1.0));
}

TEST_CASE("bad part densities and friction throw naming the field", "[evaluation][materials]") {
  const Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  const Vec<7> q = Vec<7>::Zero();
  const ObjectSpec good = two_part_object(hand);
  const auto build = [&](const ObjectSpec& o) { HandScene<models::schunk_sdh> s(hand, q, o); };
  ObjectSpec o = good;
  o.part_density = {1000.0};
  test::check_throws_naming([&] { build(o); }, "object.part_density");
  o.part_density = {1000.0, 0.0};
  test::check_throws_naming([&] { build(o); }, "object.part_density[1]");
  o = good;
  o.part_friction = {0.5, 0.5, 0.5};
  test::check_throws_naming([&] { build(o); }, "object.part_friction");
  o.part_friction = {-0.5, 0.5};
  test::check_throws_naming([&] { build(o); }, "object.part_friction[0]");
  o.part_friction = {0.5, std::numeric_limits<double>::infinity()};
  test::check_throws_naming([&] { build(o); }, "object.part_friction[1]");
  o.part_friction = {0.5, 2e6};
  test::check_throws_naming([&] { build(o); }, "object.part_friction[1]");
  // Densities alone give the mass when the mass is 0.
  o = good;
  o.mass = 0.0;
  o.part_density = {500.0, 500.0};
  const HandScene<models::schunk_sdh> s(hand, q, o);
  CHECK(s.world().body(s.object_body()).mass == Approx(1000.0 * pi * 0.03 * 0.03 * 0.1));
}

// SPDX-License-Identifier: BSD-3-Clause
// Finite but out-of-range input to the hand scene and to close_hand: refused with a readable
// error naming the argument, or reported as a status, never std::terminate, a hang or UB.
#include "evaluation_test_support.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

using namespace topograsp;
using test::cylinder_object;

TEST_CASE("a finite hand pose beyond the documented range is refused with a readable error",
          "[evaluation][input]") {
  // z = 1.7e308 used to be accepted, and the noexcept step() then called a function that threw:
  // std::terminate.
  HandScene<models::schunk_sdh> scene = test::sdh_bottle_scene();
  Eigen::Isometry3d far = scene.hand_pose();
  far.translation().z() = 1.7e308;
  test::check_throws_naming([&] { scene.set_hand_pose(far); }, "pose");
  try {
    scene.set_hand_pose(far);
  } catch (const invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("at most 1e6 m") && Catch::Contains("1.7e+308"));
  }
  test::check_throws_naming([&] { scene.place_hand(far, scene.joint_targets()); }, "pose");
  test::check_throws_naming(
      [&] {
        HandScene<models::schunk_sdh> s(far, scene.joint_targets(),
                                        cylinder_object(Eigen::Isometry3d::Identity(), {0, 0, 0.16},
                                                        Eigen::Vector3d::UnitY(), 0.03, 0.05, 0.2));
      },
      "hand_pose");
  // A linear part that is not a rotation.
  Eigen::Isometry3d skew = scene.hand_pose();
  skew.linear() *= 2.0;
  test::check_throws_naming([&] { scene.set_hand_pose(skew); }, "pose");
  // The scene is untouched and still steps.
  CHECK(scene.step() == Status::success);
  // At the bound itself it is accepted.
  Eigen::Isometry3d edge = scene.hand_pose();
  edge.translation().z() = HandScene<models::schunk_sdh>::k_max_hand_coordinate;
  CHECK_NOTHROW(scene.set_hand_pose(edge));
}

TEST_CASE("a scene refuses a model whose joints have no motor, naming the joint",
          "[evaluation][input]") {
  // The free-base SDH: its base translations and rotations are not driven by motors (no
  // LinkSpec::effort), so it cannot be simulated with torque-limited joints.
  constexpr auto& f = models::schunk_sdh_free;
  const Vec<f.nq> q = Vec<f.nq>::Zero();
  const Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  try {
    HandScene<f> scene(
        hand, q, cylinder_object(hand, {0, 0, 0.4}, Eigen::Vector3d::UnitY(), 0.03, 0.05, 0.2));
    FAIL("expected topograsp::invalid_argument");
  } catch (const invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("model: joint 'base_x'") && Catch::Contains("no motor"));
  }
}

TEST_CASE("close_hand refuses a step that would take too many increments", "[evaluation][input]") {
  // step = 1e-8 rad ran for minutes (3e8 increments); 1e-10 overflowed the float-to-int cast.
  for (const double step : {1e-8, 1e-10, 1e-300, std::numeric_limits<double>::denorm_min()}) {
    CAPTURE(step);
    HandScene<models::schunk_sdh> scene = test::sdh_bottle_scene();
    CloseOptions o;
    o.step = step;
    test::check_throws_naming([&] { (void)close_hand(scene, o); }, "options.step");
  }
  try {
    HandScene<models::schunk_sdh> scene = test::sdh_bottle_scene();
    CloseOptions o;
    o.step = 1e-10;
    (void)close_hand(scene, o);
  } catch (const invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("expected at least") && Catch::Contains("1e-10"));
  }
  // The other counts are bounded too.
  HandScene<models::schunk_sdh> scene = test::sdh_bottle_scene();
  CloseOptions o;
  o.bisections = 1000000000;
  test::check_throws_naming([&] { (void)close_hand(scene, o); }, "options.bisections");
  o = {};
  o.closing_steps = std::numeric_limits<int>::max();
  test::check_throws_naming([&] { (void)close_hand(scene, o); }, "options.closing_steps");
  o.closing_steps = 0;
  test::check_throws_naming([&] { (void)close_hand(scene, o); }, "options.closing_steps");
  o = {};
  for (const double f : {0.0, -0.5, 1.5, std::nan("")}) {
    o.hold_fraction = f;
    test::check_throws_naming([&] { (void)close_hand(scene, o); }, "options.hold_fraction");
  }
  // A huge step is fine: one increment reaches the limit.
  o = {};
  o.step = 1e300;
  const auto r = close_hand(scene, o);
  CHECK(r.status == Status::success);
  CHECK(r.q_closed.allFinite());
}

TEST_CASE("an object the World cannot represent is refused naming the object",
          "[evaluation][input]") {
  const Eigen::Isometry3d hand = test::sdh_side_pose();
  Vec<7> q;
  q << 0.0, -0.6, 0.3, -0.6, 0.3, -0.6, 0.3;
  ObjectSpec o = cylinder_object(hand, {0, 0, 0.15}, Eigen::Vector3d::UnitY(), 0.035, 0.1, 0.5);
  o.mass = 1e306;  // its kinetic energy at max_speed overflows
  test::check_throws_naming([&] { HandScene<models::schunk_sdh> s(hand, q, o); }, "object.mass");
  try {
    HandScene<models::schunk_sdh> s(hand, q, o);
  } catch (const invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("not representable") && Catch::Contains("1e+306"));
  }
  o.mass = 0.5;
  o.shapes[0].size[0] = 1e200;  // a cylinder radius beyond the length range
  test::check_throws_naming([&] { HandScene<models::schunk_sdh> s(hand, q, o); },
                            "object.shapes[0].size[0]");
}

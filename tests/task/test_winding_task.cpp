// SPDX-License-Identifier: BSD-3-Clause
#include <random>

#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task/winding_descriptor.hpp>
#include <topograsp/task/winding_task.hpp>

#include "support/finite_diff.hpp"
#include "support/random.hpp"

using namespace topograsp;

namespace {

// The point the hand closes around: the centroid of all curve points at the given configuration,
// shifted a little so that no vertex sits on it.
template <const auto& M>
Vec3 grasp_point(const KinematicsData<M>& d) {
  Vec3 c = Vec3::Zero();
  int n = 0;
  std::array<Vec3, static_cast<std::size_t>(hand_curve_capacity<M>)> x;
  for (int i = 0; i < hand_curve_count<M>; ++i) {
    const int m = hand_curve_points(d, i, x);
    for (int k = 0; k < m; ++k) c += x[static_cast<std::size_t>(k)];
    n += m;
  }
  return c / n + Vec3(0.003, -0.002, 0.001);
}

template <const auto& M>
void check_winding_jacobian(std::uint32_t seed) {
  std::mt19937 rng(seed);
  KinematicsData<M> d;
  for (int trial = 0; trial < 10; ++trial) {
    const Vec<M.nq> q = test::random_configuration<M>(rng);
    forward_kinematics(d, q);
    const WindingTask<M> task(grasp_point(d));
    INFO(M.name.view() << " trial " << trial);
    CHECK(test::jacobian_error(task, q) < 1e-6);
    CHECK(test::numeric_jacobian(task, q).cwiseAbs().maxCoeff() > 1e-2);
  }
}

}  // namespace

TEST_CASE("hand curves run from the thumb tip through the palm to each finger tip",
          "[task][winding]") {
  SECTION("human hand") {
    constexpr auto& M = models::human_hand;
    static_assert(hand_curve_count<M> == 4);
    static_assert(hand_curve_capacity<M> == 9);
    constexpr auto curves = hand_curves<M>();
    const auto& thumb = M.fingers[static_cast<std::size_t>(M.thumb)];
    for (std::size_t i = 0; i < curves.size(); ++i) {
      const auto& c = curves[i];
      CHECK(c.finger == static_cast<int>(i));  // the thumb is the last finger
      REQUIRE(c.size == 9);
      CHECK(c.points[0] == thumb.points[3]);
      CHECK(c.points[3] == thumb.points[0]);
      CHECK(c.points[4] == M.palm);
      CHECK(c.points[8] == M.fingers[i].points[3]);
    }
    static_assert(hand_curve_index<M>("middle") == 1);
    static_assert(hand_curve_index<M>("thumb") == -1);
    static_assert(hand_curve_index<M>("nope") == -1);
  }
  SECTION("SDH on the arm: two curves, the arm joints do not move their shape") {
    constexpr auto& M = models::schunk_arm_sdh;
    static_assert(hand_curve_count<M> == 2);
    static_assert(hand_curve_index<M>("finger_1") == 0);
    static_assert(hand_curve_index<M>("finger_2") == 1);
    KinematicsData<M> d;
    Vec<M.nq> q = Vec<M.nq>::Zero();
    forward_kinematics(d, q);
    std::array<Vec3, 7> x;
    CHECK(hand_curve_points(d, 0, x) == 7);
    // Thumb tip first, finger tip last: their distance is the thumb-finger aperture.
    CHECK((x[0] - d.frame_p[static_cast<std::size_t>(M.frame("thumb_tip"))]).norm() < 1e-15);
    CHECK((x[6] - d.frame_p[static_cast<std::size_t>(M.frame("tip_1"))]).norm() < 1e-15);
    CHECK((x[3] - d.frame_p[static_cast<std::size_t>(M.frame("palm_centre"))]).norm() < 1e-15);
  }
}

TEST_CASE("closing the SDH around a point raises both windings", "[task][winding]") {
  constexpr auto& M = models::schunk_sdh;
  KinematicsData<M> d;
  const Vec3 p(0, 0, 0.15);  // between the fingers, above the palm
  const WindingTask<M> task(p);
  Vec<7> q = Vec<7>::Zero();
  forward_kinematics(d, q);
  const Vec2 open = task.value(d);
  q << 0.0, 0.6, 0.6, 0.6, 0.6, 0.6, 0.6;
  forward_kinematics(d, q);
  const Vec2 closed = task.value(d);
  CHECK(closed[0] > open[0]);
  CHECK(closed[1] > open[1]);
  // Fingers 1 and 2 are mirror images at knuckle 0: equal windings.
  CHECK(closed[0] == Approx(closed[1]).epsilon(1e-12));
}

TEST_CASE("the winding task Jacobian matches central differences on every hand",
          "[task][winding]") {
  check_winding_jacobian<models::schunk_sdh>(1);
  check_winding_jacobian<models::human_hand>(2);
  check_winding_jacobian<models::barrett_bh8>(3);
  check_winding_jacobian<models::schunk_arm_sdh>(4);
  check_winding_jacobian<models::schunk_sdh_free>(5);
  check_winding_jacobian<models::human_hand_free>(6);
  check_winding_jacobian<models::barrett_bh8_free>(7);
}

TEST_CASE("a winding task on chosen curves reports those curves", "[task][winding]") {
  constexpr auto& M = models::human_hand;
  std::mt19937 rng(3);
  KinematicsData<M> d;
  const Vec<M.nq> q = test::random_configuration<M>(rng);
  forward_kinematics(d, q);
  const Vec3 p = grasp_point(d);
  const WindingTask<M> all(p);
  const WindingTask<M, 2> two({3, 1}, p);
  const Vec<4> w = all.value(d);
  const Vec2 v = two.value(d);
  CHECK(v[0] == w[3]);
  CHECK(v[1] == w[1]);
  CHECK(test::jacobian_error(two, q) < 1e-6);
}

TEST_CASE("the descriptor picks the two largest windings", "[task][winding]") {
  constexpr auto& M = models::human_hand;
  std::mt19937 rng(5);
  KinematicsData<M> d;
  for (int trial = 0; trial < 20; ++trial) {
    forward_kinematics(d, test::random_configuration<M>(rng));
    const Vec3 p = grasp_point(d);
    const Vec<4> w = WindingTask<M>(p).value(d);
    const WindingDescriptor y = winding_descriptor(d, p);
    REQUIRE(y.curves[0] != y.curves[1]);
    CHECK(y.values[0] == w[y.curves[0]]);
    CHECK(y.values[1] == w[y.curves[1]]);
    CHECK(y.values[0] >= y.values[1]);
    for (int i = 0; i < 4; ++i)
      if (i != y.curves[0]) CHECK(w[i] <= y.values[1]);
  }
}

TEST_CASE("the winding task rejects bad input naming the argument", "[task][winding]") {
  constexpr auto& M = models::schunk_sdh;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(WindingTask<M>(Vec3(nan, 0, 0)), Catch::StartsWith("point"));
  CHECK_THROWS_WITH((WindingTask<M, 1>({2}, Vec3::Zero())), Catch::StartsWith("curves"));
  CHECK_THROWS_AS((WindingTask<M, 1>({-1}, Vec3::Zero())), invalid_argument);
  WindingTask<M> t(Vec3::Zero());
  CHECK_THROWS_WITH(t.set_point(Vec3(0, 0, nan)), Catch::StartsWith("point"));
}

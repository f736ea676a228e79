// SPDX-License-Identifier: BSD-3-Clause
#include <random>

#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task/collision_task.hpp>

#include "support/finite_diff.hpp"
#include "support/objects.hpp"
#include "support/random.hpp"

using namespace topograsp;

namespace {

// A pose that puts an object near link shape i, randomly turned, then slides it along the contact
// normal until its distance to that shape is between -1 cm and +1.5 cm: the working range of the
// potential (contact and shallow penetration).
template <const auto& M>
Eigen::Isometry3d near_shape(const KinematicsData<M>& d, std::size_t i, std::mt19937& rng,
                             Composite (*make)(const Eigen::Isometry3d&)) {
  std::uniform_real_distribution<double> a(-1.0, 1.0);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(a(rng), a(rng), a(rng), a(rng)).normalized().toRotationMatrix();
  T.translation() = world_shape(d, i).p + 0.03 * Vec3(a(rng), a(rng), a(rng));
  const Primitive s = world_shape(d, i);
  const Composite object = make(T);
  Contact nearest;
  nearest.distance = std::numeric_limits<double>::infinity();
  for (const Primitive& o : object.parts()) {
    const Contact c = signed_distance(s, o);
    if (c.distance < nearest.distance) nearest = c;
  }
  const double target = std::uniform_real_distribution<double>(-0.01, 0.015)(rng);
  T.pretranslate((target - nearest.distance) * nearest.normal);
  return T;
}

template <const auto& M>
void check_collision_jacobian(std::uint32_t seed) {
  std::mt19937 rng(seed);
  KinematicsData<M> d;
  int nonzero = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Vec<M.nq> q = test::random_configuration<M>(rng);
    forward_kinematics(d, q);
    const std::size_t shape =
        std::uniform_int_distribution<std::size_t>(0, M.shapes.size() - 1)(rng);
    INFO(M.name.view() << " trial " << trial << " near shape " << shape);
    // Spheres, capsules and boxes: exact against the human hand; the other hands have
    // cylinders, whose penetration EPA approaches iteratively (signed_distance()): it stops when
    // its bounds on the depth are 1e-10 (1 + depth) m apart, which the central differences over
    // 2e-6 rad turn into noise of about 1e-4 of the potential's slope (2.7e-4 measured on a
    // Barrett trial in the clang -O1 sanitizer build).
    const bool exact_hand = M.name.view() == "human_hand";
    const CollisionTask<M> blocks(test::blocks(near_shape(d, shape, rng, &test::blocks)), 0.02);
    CHECK(test::jacobian_error(blocks, q) < (exact_hand ? 1e-6 : 1e-3));
    // The bottle and the hammer bring cylinders of their own.
    const CollisionTask<M> bottle(test::bottle(near_shape(d, shape, rng, &test::bottle)), 0.02);
    const CollisionTask<M> hammer(test::hammer(near_shape(d, shape, rng, &test::hammer)), 0.02);
    // Deep inside a cylinder the penetration depth has kinks (the shortest way out switches
    // between the side and a cap): there the gradient is that of one side. EPA's witness points
    // on a curved rim are good to about 1e-5 m, which the factor 2/m of the potential amplifies.
    CHECK(test::piecewise_jacobian_error(bottle, q) < 1e-2);
    CHECK(test::piecewise_jacobian_error(hammer, q) < 1e-2);
    if (blocks.value(d)[0] > 0.0) ++nonzero;
  }
  CHECK(nonzero >= 6);
}

}  // namespace

TEST_CASE("the collision task Jacobian matches central differences on every model",
          "[task][collision]") {
  check_collision_jacobian<models::schunk_sdh>(11);
  check_collision_jacobian<models::human_hand>(12);
  check_collision_jacobian<models::barrett_bh8>(13);
  check_collision_jacobian<models::schunk_arm>(14);
  check_collision_jacobian<models::schunk_arm_sdh>(15);
  check_collision_jacobian<models::schunk_sdh_free>(16);
  check_collision_jacobian<models::human_hand_free>(17);
  check_collision_jacobian<models::barrett_bh8_free>(18);
}

TEST_CASE("the collision potential is zero beyond the margin, continuous at it, monotone inside",
          "[task][collision]") {
  constexpr auto& M = models::schunk_sdh;
  KinematicsData<M> d;
  forward_kinematics(d, Vec<7>::Zero());
  // The palm is a cylinder of radius 0.06 about z centred at (-0.0101, 0, 0.0357), half height
  // 0.0385; a ball approaches it from the side along -x.
  const double m = 0.01, r = 0.02;
  const auto phi_at = [&](double gap) {
    const Vec3 c(-0.0101 - 0.06 - r - gap, 0.0, 0.0357);
    return CollisionTask<M>(Composite({Primitive::sphere(c, r)}), m).value(d)[0];
  };
  CHECK(phi_at(0.5) == 0.0);
  CHECK(phi_at(m + 1e-9) == 0.0);
  CHECK(phi_at(m - 1e-6) == Approx(1e-8).epsilon(1e-3));  // (1e-6 / m)^2
  CHECK(phi_at(0.0) == Approx(1.0).epsilon(1e-12));
  CHECK(phi_at(-m) == Approx(4.0).epsilon(1e-12));
  double last = 0.0;
  for (double gap = 0.02; gap > -0.05; gap -= 0.001) {
    const double phi = phi_at(gap);
    CHECK(phi >= last);
    if (gap < m) CHECK(phi == Approx((1 - gap / m) * (1 - gap / m)).epsilon(1e-9).margin(1e-12));
    last = phi;
  }
  CHECK(last > 30.0);  // keeps growing without bound as the ball sinks in
}

TEST_CASE("the collision task sums over shapes and parts, and can leave shapes out",
          "[task][collision]") {
  constexpr auto& M = models::schunk_sdh;
  KinematicsData<M> d;
  forward_kinematics(d, Vec<7>::Zero());
  const Composite object(
      {Primitive::sphere(Vec3(0, 0, 0.0), 0.02), Primitive::sphere(Vec3(0, 0, 0.0), 0.02)});
  CollisionTask<M> task(object, 0.01);
  const CollisionTask<M> single(Composite({object.parts()[0]}), 0.01);
  REQUIRE(single.value(d)[0] > 0.0);
  CHECK(task.value(d)[0] == Approx(2.0 * single.value(d)[0]));
  std::array<bool, M.shapes.size()> none{};
  task.set_active(none);
  CHECK(task.value(d)[0] == 0.0);
  CHECK(task.min_distance(d) == std::numeric_limits<double>::infinity());
  Vec<1> phi;
  Mat<1, 7> J;
  task.evaluate(d, phi, J);
  CHECK(phi[0] == 0.0);
  CHECK(J.isZero());
}

TEST_CASE("the collision task rejects a bad margin naming it", "[task][collision]") {
  constexpr auto& M = models::schunk_sdh;
  CHECK_THROWS_WITH(CollisionTask<M>(test::bottle(), 0.0), Catch::StartsWith("margin"));
  CHECK_THROWS_AS(CollisionTask<M>(test::bottle(), std::nan("")), invalid_argument);
}

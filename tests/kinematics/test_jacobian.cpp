// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>

#include "support/finite_diff.hpp"
#include "support/random.hpp"

using namespace topograsp;

namespace {

// Every frame Jacobian (6 x nq), every link rotation Jacobian and every finger point Jacobian of
// model M against central differences at 100 random configurations; returns the largest error.
template <const auto& M>
double max_jacobian_error() {
  std::mt19937_64 rng(42);
  double worst = 0.0;
  KinematicsData<M> d;
  for (int trial = 0; trial < 100; ++trial) {
    const Vec<M.nq> q = test::random_configuration<M>(rng);
    forward_kinematics(d, q);
    for (int f = 0; f < static_cast<int>(M.n_frames); ++f) {
      const Mat<6, M.nq> J = frame_jacobian(d, f);
      const auto position = [&](const Vec<M.nq>& x) {
        KinematicsData<M> e;
        forward_kinematics(e, x);
        return Vec3(e.frame_p[static_cast<std::size_t>(f)]);
      };
      const auto rotation = [&](const Vec<M.nq>& x) {
        KinematicsData<M> e;
        forward_kinematics(e, x);
        return Mat3(e.frame_R[static_cast<std::size_t>(f)]);
      };
      const Mat<3, M.nq> Jp = test::central_difference<3, M.nq>(q, position);
      const Mat<3, M.nq> Jr = test::rotation_difference<M.nq>(q, rotation);
      worst = std::max(worst, (J.template topRows<3>() - Jp).cwiseAbs().maxCoeff());
      worst = std::max(worst, (J.template bottomRows<3>() - Jr).cwiseAbs().maxCoeff());
      worst = std::max(worst, (frame_position_jacobian(d, f) - Jp).cwiseAbs().maxCoeff());
      worst = std::max(worst, (frame_rotation_jacobian(d, f) - Jr).cwiseAbs().maxCoeff());
    }
    for (const Finger& finger : M.fingers) {
      for (int k = 0; k < finger.size; ++k) {
        const LinkPoint pt = finger.points[static_cast<std::size_t>(k)];
        const auto position = [&](const Vec<M.nq>& x) {
          KinematicsData<M> e;
          forward_kinematics(e, x);
          return world_point(e, pt);
        };
        const Mat<3, M.nq> J = point_jacobian(d, pt.link, world_point(d, pt));
        worst = std::max(
            worst, (J - test::central_difference<3, M.nq>(q, position)).cwiseAbs().maxCoeff());
      }
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("Jacobians of every shipped model match central differences", "[kinematics][jacobian]") {
  SECTION("Schunk SDH") { CHECK(max_jacobian_error<models::schunk_sdh>() <= 1e-6); }
  SECTION("Schunk arm") { CHECK(max_jacobian_error<models::schunk_arm>() <= 1e-6); }
  SECTION("SDH on the arm") { CHECK(max_jacobian_error<models::schunk_arm_sdh>() <= 1e-6); }
  SECTION("human hand") { CHECK(max_jacobian_error<models::human_hand>() <= 1e-6); }
  SECTION("Barrett BH8 (mimic joints)") {
    CHECK(max_jacobian_error<models::barrett_bh8>() <= 1e-6);
  }
  SECTION("SDH on a free base") { CHECK(max_jacobian_error<models::schunk_sdh_free>() <= 1e-6); }
  SECTION("human hand on a free base") {
    CHECK(max_jacobian_error<models::human_hand_free>() <= 1e-6);
  }
  SECTION("Barrett on a free base") {
    CHECK(max_jacobian_error<models::barrett_bh8_free>() <= 1e-6);
  }
}

TEST_CASE("a wrong analytic Jacobian would be caught", "[kinematics][jacobian]") {
  // The oracle itself must be able to fail: dropping the mimic joint's contribution to the SDH's
  // knuckle column changes finger 2's Jacobian by more than the tolerance.
  using models::schunk_sdh;
  KinematicsData<schunk_sdh> d;
  Vec<7> q;
  q << 0.5, 0.3, 0.4, 0.3, 0.4, 0.2, 0.1;
  forward_kinematics(d, q);
  const int f = schunk_sdh.frame("tip_2");
  Mat<3, 7> J = frame_position_jacobian(d, f);
  const auto position = [&](const Vec<7>& x) {
    KinematicsData<schunk_sdh> e;
    forward_kinematics(e, x);
    return Vec3(e.frame_p[static_cast<std::size_t>(f)]);
  };
  const Mat<3, 7> Jfd = test::central_difference<3, 7>(q, position);
  CHECK((J - Jfd).cwiseAbs().maxCoeff() <= 1e-6);
  J.col(0).setZero();
  CHECK((J - Jfd).cwiseAbs().maxCoeff() > 1e-3);
}

// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <random>

#include <topograsp/core/sincos.hpp>
#include <topograsp/model/models.hpp>

using namespace topograsp;

TEST_CASE("shipped models have the paper's degrees of freedom", "[model]") {
  STATIC_REQUIRE(models::schunk_sdh.nq == 7);
  STATIC_REQUIRE(models::schunk_sdh.n_links == 10);
  STATIC_REQUIRE(models::schunk_arm.nq == 7);
  STATIC_REQUIRE(models::schunk_arm_sdh.nq == 14);
  STATIC_REQUIRE(models::human_hand.nq == 20);
  STATIC_REQUIRE(models::human_hand.n_fingers == 5);
  STATIC_REQUIRE(models::barrett_bh8.nq == 4);
  STATIC_REQUIRE(models::schunk_sdh_free.nq == 13);
  STATIC_REQUIRE(models::human_hand_free.nq == 26);
}

TEST_CASE("the configuration follows the documented joint order", "[model]") {
  constexpr auto& sdh = models::schunk_sdh;
  const std::array<std::string_view, 7> sdh_order{
      "knuckle", "finger_12", "finger_13", "finger_22", "finger_23", "thumb_2", "thumb_3"};
  for (int i = 0; i < 7; ++i) CHECK(sdh.joint_name(i) == sdh_order[static_cast<std::size_t>(i)]);
  constexpr auto& whole = models::schunk_arm_sdh;
  CHECK(whole.joint_name(0) == "arm_1");
  CHECK(whole.joint_name(6) == "arm_7");
  CHECK(whole.joint_name(7) == "knuckle");
  CHECK(models::human_hand.joint_name(16) == "thumb_cmc1");
  CHECK(models::human_hand_free.joint_name(0) == "base_x");
  CHECK(models::human_hand_free.joint_name(6) == "index_abd");
  STATIC_REQUIRE(sdh.joint("thumb_3") == 6);
  CHECK(sdh.find_joint("knuckle_2") == -1);  // a mimic joint owns no entry
  CHECK(sdh.find_joint("no_such_joint") == -1);
}

TEST_CASE("mimic joints resolve to their source's entry", "[model][mimic]") {
  constexpr auto& sdh = models::schunk_sdh;
  constexpr Link k2 = sdh.links[static_cast<std::size_t>(sdh.link("knuckle_2"))];
  STATIC_REQUIRE(k2.q == 0);
  STATIC_REQUIRE(!k2.actuated);
  STATIC_REQUIRE(k2.axis[2] == -1.0);
  constexpr auto& bh = models::barrett_bh8;
  constexpr Link d1 = bh.links[static_cast<std::size_t>(bh.link("finger_1_dist"))];
  STATIC_REQUIRE(d1.q == bh.joint("finger_1_med"));
  STATIC_REQUIRE(d1.spec.multiplier == 0.3);
  STATIC_REQUIRE(d1.spec.offset == 0.75);
}

TEST_CASE("hands know their thumb, fingers and palm centre", "[model][hand]") {
  STATIC_REQUIRE(models::schunk_sdh.is_hand());
  STATIC_REQUIRE(!models::schunk_arm.is_hand());
  STATIC_REQUIRE(models::schunk_arm_sdh.is_hand());
  CHECK(models::schunk_sdh.fingers[static_cast<std::size_t>(models::schunk_sdh.thumb)]
            .spec.name.view() == "thumb");
  CHECK(models::human_hand.fingers[static_cast<std::size_t>(models::human_hand.thumb)]
            .spec.name.view() == "thumb");
  CHECK(models::barrett_bh8.fingers[static_cast<std::size_t>(models::barrett_bh8.thumb)].size == 3);
  CHECK(models::human_hand.fingers[0].size == 4);
  // The SDH on the arm keeps the hand's fingers, re-resolved to the shifted link indices.
  constexpr auto& whole = models::schunk_arm_sdh;
  CHECK(whole.fingers[0].points[0].link == whole.find_link("finger_12"));
  CHECK(whole.palm.link == whole.find_link("palm"));
  CHECK(whole.palm.offset[2] == Approx(0.0745));
}

TEST_CASE("joint closing directions come from the model", "[model]") {
  constexpr auto& sdh = models::schunk_sdh;
  CHECK(sdh.joint_spec(0).closing == 0.0);  // the knuckle chooses the pre-shape, it does not close
  for (int i = 1; i < 7; ++i) CHECK(sdh.joint_spec(i).closing == 1.0);
  CHECK(models::human_hand.joint_spec(models::human_hand.joint("index_abd")).closing == 0.0);
  CHECK(models::human_hand.joint_spec(models::human_hand.joint("thumb_cmc2")).closing == -1.0);
}

TEST_CASE("constexpr poses compose and invert exactly enough", "[model][pose]") {
  constexpr Pose a = at(0.1, -0.2, 0.3).rpy(0.3, -0.7, 1.1);
  constexpr Pose b = at(-0.4, 0.5, 0.0).quat(0.9, 0.1, -0.3, 0.2);
  const Eigen::Isometry3d ab = a.isometry() * b.isometry();
  CHECK(((a * b).isometry().matrix() - ab.matrix()).cwiseAbs().maxCoeff() < 1e-14);
  CHECK(((a * inverse(a)).isometry().matrix() - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff() <
        1e-14);
  // rpy is Rz(y) Ry(p) Rx(r), as in URDF.
  const Mat3 expected =
      (Eigen::AngleAxisd(1.1, Vec3::UnitZ()) * Eigen::AngleAxisd(-0.7, Vec3::UnitY()) *
       Eigen::AngleAxisd(0.3, Vec3::UnitX()))
          .toRotationMatrix();
  CHECK((a.rotation() - expected).cwiseAbs().maxCoeff() < 1e-14);
  SECTION("constexpr sin, cos and sqrt agree with the standard library") {
    for (double x = -10.0; x <= 10.0; x += 0.0137) {
      CHECK(cmath::sin(x) == Approx(std::sin(x)).margin(1e-15));
      CHECK(cmath::cos(x) == Approx(std::cos(x)).margin(1e-15));
    }
    for (const double x : {1e-8, 0.5, 2.0, 1e6}) CHECK(cmath::sqrt(x) == Approx(std::sqrt(x)));
  }
}

TEST_CASE("the fast sincos of the kinematics agrees with the standard library", "[core]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  for (int i = 0; i < 100000; ++i) {
    const double x = i < 1000 ? (i - 500) * (pi / 4.0) : u(rng);  // includes the octant edges
    const SinCos sc = sincos(x);
    CHECK(std::abs(sc.s - std::sin(x)) <= 1e-15);
    CHECK(std::abs(sc.c - std::cos(x)) <= 1e-15);
  }
  CHECK(sincos(0.0).s == 0.0);
  CHECK(sincos(0.0).c == 1.0);
  CHECK(sincos(2e5).s == std::sin(2e5));  // large arguments go to the standard library
  CHECK(std::isnan(sincos(std::numeric_limits<double>::quiet_NaN()).s));
}

// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>

using namespace topograsp;
using models::schunk_sdh;

namespace {

struct SdhPose {
  const char* name;
  std::array<double, 7> q;
  std::array<double, 3> finger_1;  // expected tip of finger 1 (m), models.md table 1.5
};

Vec3 tip(const KinematicsData<schunk_sdh>& d, const char* frame) {
  return d.frame_p[static_cast<std::size_t>(schunk_sdh.find_frame(frame))];
}

}  // namespace

TEST_CASE("SDH fingertips match the hand-computed pre-shapes", "[kinematics][sdh]") {
  // Values from the pre-shape table of docs/models.md (three decimals).
  const std::array<SdhPose, 6> poses{{
      {"home", {0, 0, 0, 0, 0, 0, 0}, {0.019, 0.033, 0.246}},
      {"cylopen", {0, -0.9854, 0.9472, -0.9854, 0.9472, -0.9854, 0.9472}, {0.094, 0.033, 0.207}},
      {"cylclosed", {0, 0, 1.0472, 0, 1.0472, 0, 1.0472}, {-0.040, 0.033, 0.212}},
      {"spheropen", {1.047, -0.785, 1.047, -0.785, 1.047, -0.785, 1.047}, {0.041, 0.071, 0.218}},
      {"spherclosed", {1.047, -0.262, 1.047, -0.262, 1.047, -0.262, 1.047}, {0.006, 0.011, 0.223}},
      {"fist", {0, 0, 1.57, 0, 1.57, 0, 1.57}, {-0.049, 0.033, 0.178}},
  }};
  KinematicsData<schunk_sdh> d;
  for (const SdhPose& pose : poses) {
    INFO(pose.name);
    forward_kinematics(d, Eigen::Map<const Vec<7>>(pose.q.data()));
    const Vec3 expected = Eigen::Map<const Vec3>(pose.finger_1.data());
    CHECK((tip(d, "tip_1") - expected).cwiseAbs().maxCoeff() < 1e-3);
  }
  SECTION("the thumb at home and at cylopen") {
    forward_kinematics(d, Vec<7>::Zero());
    CHECK((tip(d, "thumb_tip") - Vec3(-0.03811, 0.0, 0.246)).norm() < 1e-9);
    CHECK((tip(d, "tip_2") - Vec3(0.01905, -0.033, 0.246)).norm() < 1e-9);
    Vec<7> q;
    q << 0, -0.9854, 0.9472, -0.9854, 0.9472, -0.9854, 0.9472;
    forward_kinematics(d, q);
    CHECK((tip(d, "thumb_tip") - Vec3(-0.113, 0.0, 0.207)).cwiseAbs().maxCoeff() < 1e-3);
  }
}

TEST_CASE("the SDH knuckle drives fingers 1 and 2 mirror-symmetrically", "[kinematics][mimic]") {
  KinematicsData<schunk_sdh> d;
  for (const double knuckle : {0.0, 0.3, pi / 3.0, pi / 2.0}) {
    Vec<7> q;
    q << knuckle, 0.4, 0.7, 0.4, 0.7, 0.2, 0.1;
    forward_kinematics(d, q);
    const Vec3 a = tip(d, "tip_1"), b = tip(d, "tip_2");
    CHECK(a.x() == Approx(b.x()).margin(1e-12));
    CHECK(a.y() == Approx(-b.y()).margin(1e-12));
    CHECK(a.z() == Approx(b.z()).margin(1e-12));
  }
  SECTION("at pi/2 the two fingers face each other: their flexion moves them along y") {
    Vec<7> q0, q1;
    q0 << pi / 2, 0, 0, 0, 0, 0, 0;
    q1 << pi / 2, 0.5, 0, 0.5, 0, 0, 0;
    forward_kinematics(d, q0);
    const Vec3 a0 = tip(d, "tip_1");
    forward_kinematics(d, q1);
    const Vec3 a1 = tip(d, "tip_1");
    CHECK(a1.y() < a0.y() - 0.03);  // finger 1 (at +y) closes toward -y
    CHECK(std::abs(a1.x() - a0.x()) < 1e-9);
  }
}

TEST_CASE("Barrett distal joints follow 0.3 * medial + 0.75", "[kinematics][mimic]") {
  using models::barrett_bh8;
  KinematicsData<barrett_bh8> d;
  Vec<4> q;
  q << 0.4, 1.0, 0.5, 2.0;
  forward_kinematics(d, q);
  const auto angle_between = [&](const char* a, const char* b) {
    const Mat3 rel = d.R[static_cast<std::size_t>(barrett_bh8.find_link(a))].transpose() *
                     d.R[static_cast<std::size_t>(barrett_bh8.find_link(b))];
    return std::atan2(rel(1, 0), rel(0, 0));  // both joints turn about z
  };
  CHECK(angle_between("finger_1_med", "finger_1_dist") == Approx(0.3 * 1.0 + 0.75));
  CHECK(angle_between("finger_2_med", "finger_2_dist") == Approx(0.3 * 0.5 + 0.75));
  CHECK(angle_between("finger_3_med", "finger_3_dist") == Approx(0.3 * 2.0 + 0.75));
  // The spread of finger 2 mirrors finger 1's (same motor, opposite axis); both bases are turned
  // by -pi/2 at zero spread.
  CHECK(angle_between("finger_1_prox", "base") - pi / 2 == Approx(0.4));
  CHECK(angle_between("finger_2_prox", "base") - pi / 2 == Approx(-0.4));
}

TEST_CASE("the arm's joints sit where the ORS model puts them", "[kinematics][arm]") {
  using models::schunk_arm;
  // World joint positions and axes at q = 0 from docs/models.md (four decimals).
  const std::array<std::array<double, 6>, 7> expected{{
      {0.1061, 0.0225, 1.1869, -0.109, 0.235, -0.966},
      {-0.0525, -0.0515, 1.1869, 0.906, 0.423, 0},
      {-0.2111, -0.1254, 1.1869, 0.423, -0.906, 0},
      {-0.2111, -0.1254, 1.0354, 0, 0, 1},
      {-0.2111, -0.1254, 0.8839, -0.906, -0.423, 0},
      {-0.1580, -0.2394, 0.8839, -0.423, 0.906, 0},
      {-0.1048, -0.3534, 0.8839, 0, 0, -1},
  }};
  KinematicsData<schunk_arm> d;
  forward_kinematics(d, Vec<7>::Zero());
  for (std::size_t j = 0; j < 7; ++j) {
    INFO("joint " << j + 1);
    const auto l = static_cast<std::size_t>(schunk_arm.find_link("arm_" + std::to_string(j + 1)));
    const auto& e = expected[j];
    CHECK((d.p[l] - Vec3(e[0], e[1], e[2])).cwiseAbs().maxCoeff() < 1e-4);
    CHECK((d.axis[l] - Vec3(e[3], e[4], e[5])).cwiseAbs().maxCoeff() < 1e-3);
  }
}

TEST_CASE("the human hand is an average adult hand", "[kinematics][human]") {
  using models::human_hand;
  KinematicsData<human_hand> d;
  forward_kinematics(d, Vec<20>::Zero());
  const double length = d.frame_p[static_cast<std::size_t>(human_hand.frame("middle_tip"))].norm();
  CHECK(length == Approx(0.19).margin(0.005));
  SECTION("flexion moves the fingertips to the palm side (+x) and the thumb across the palm (-y)") {
    Vec<20> q = Vec<20>::Zero();
    for (int i = 0; i < 20; ++i)
      if (human_hand.joint_spec(i).closing > 0) q[i] = 0.5;
    KinematicsData<human_hand> c;
    forward_kinematics(c, q);
    for (const char* f : {"index_tip", "middle_tip", "ring_tip", "pinky_tip"}) {
      INFO(f);
      const auto i = static_cast<std::size_t>(human_hand.find_frame(f));
      CHECK(c.frame_p[i].x() > d.frame_p[i].x() + 0.01);
    }
    const auto t = static_cast<std::size_t>(human_hand.frame("thumb_tip"));
    CHECK(c.frame_p[t].y() < d.frame_p[t].y() - 0.01);
  }
}

TEST_CASE("composition: the SDH on the arm is the SDH at the flange", "[kinematics][compose]") {
  using models::schunk_arm;
  using models::schunk_arm_sdh;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Vec<14> q;
    for (int i = 0; i < 14; ++i) q[i] = u(rng);
    q[7] = std::abs(q[7]);  // knuckle in [0, pi/2]
    KinematicsData<schunk_arm_sdh> whole;
    KinematicsData<schunk_arm> arm;
    KinematicsData<schunk_sdh> sdh;
    forward_kinematics(whole, q);
    forward_kinematics(arm, q.head<7>());
    forward_kinematics(sdh, q.tail<7>());
    const Eigen::Isometry3d flange = frame_pose(arm, schunk_arm.frame("flange"));
    for (const char* f : {"tip_1", "tip_2", "thumb_tip", "palm_centre"}) {
      const Vec3 expected = flange * frame_pose(sdh, schunk_sdh.find_frame(f)).translation();
      const Vec3 got = whole.frame_p[static_cast<std::size_t>(schunk_arm_sdh.find_frame(f))];
      CHECK((got - expected).norm() < 1e-12);
    }
  }
  SECTION("a free base places the hand at x y z, then rotates it by Rz Ry Rx") {
    using models::schunk_sdh_free;
    Vec<13> q = Vec<13>::Zero();
    q.head<6>() << 0.1, -0.2, 0.3, 0.4, -0.5, 0.6;
    q.tail<7>() << 0.2, 0.3, 0.4, 0.3, 0.4, 0.5, 0.6;
    KinematicsData<schunk_sdh_free> fb;
    KinematicsData<schunk_sdh> sdh;
    forward_kinematics(fb, q);
    forward_kinematics(sdh, q.tail<7>());
    const Eigen::Isometry3d base =
        Eigen::Translation3d(0.1, -0.2, 0.3) * Eigen::AngleAxisd(0.4, Vec3::UnitZ()) *
        Eigen::AngleAxisd(-0.5, Vec3::UnitY()) * Eigen::AngleAxisd(0.6, Vec3::UnitX());
    for (const char* f : {"tip_1", "thumb_tip"}) {
      const Vec3 expected = base * frame_pose(sdh, schunk_sdh.find_frame(f)).translation();
      CHECK(
          (fb.frame_p[static_cast<std::size_t>(schunk_sdh_free.find_frame(f))] - expected).norm() <
          1e-12);
    }
  }
}

TEST_CASE("bad configurations are rejected with the argument's name", "[kinematics][bad-input]") {
  Vec<7> q = Vec<7>::Zero();
  CHECK_NOTHROW(require_configuration<schunk_sdh>(q));
  q[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(require_configuration<schunk_sdh>(q), topograsp::invalid_argument);
  CHECK_THROWS_WITH(require_configuration<schunk_sdh>(q, "q_start"), Catch::Contains("q_start"));
  q[3] = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(require_configuration<schunk_sdh>(q), std::invalid_argument);
  const Eigen::VectorXd wrong = Eigen::VectorXd::Zero(5);
  CHECK_THROWS_WITH(require_configuration<schunk_sdh>(wrong), Catch::Contains("size 7"));
  SECTION("the clamp puts every entry inside its limits") {
    Vec<7> big = Vec<7>::Constant(5.0);
    const Vec<7> c = clamp_to_limits<schunk_sdh>(big);
    CHECK(c[0] == Approx(pi / 2));
    CHECK((c.array() <= upper_limits<schunk_sdh>().array()).all());
    CHECK((clamp_to_limits<schunk_sdh>(-big).array() >= lower_limits<schunk_sdh>().array()).all());
  }
}

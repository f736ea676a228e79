// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <topograsp/grasp/object.hpp>
#include <topograsp/grasp/placement.hpp>
#include <topograsp/model/models.hpp>

using namespace topograsp;

TEST_CASE("zyx angles rebuild the rotation", "[grasp][placement]") {
  for (const Vec3& a : {Vec3(0.3, -0.4, 1.2), Vec3(-2.5, 1.0, 0.1), Vec3(0.0, pi / 2, 0.0)}) {
    const Mat3 R = (Eigen::AngleAxisd(a[0], Vec3::UnitZ()) *
                    Eigen::AngleAxisd(a[1], Vec3::UnitY()) * Eigen::AngleAxisd(a[2], Vec3::UnitX()))
                       .toRotationMatrix();
    const Vec3 b = zyx_angles(R);
    const Mat3 R2 =
        (Eigen::AngleAxisd(b[0], Vec3::UnitZ()) * Eigen::AngleAxisd(b[1], Vec3::UnitY()) *
         Eigen::AngleAxisd(b[2], Vec3::UnitX()))
            .toRotationMatrix();
    CHECK((R - R2).cwiseAbs().maxCoeff() < 1e-12);
  }
}

TEST_CASE("a frame of a free-base hand is put at the asked pose", "[grasp][placement]") {
  using models::human_hand_free;
  const Eigen::Isometry3d T =
      Eigen::Translation3d(0.2, -0.1, 0.5) * Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized());
  Vec<20> hand = Vec<20>::Constant(0.2);
  const int f = human_hand_free.frame("index_tip");  // on a moving link: the hand's q matters
  const Vec<26> q = place_frame<human_hand_free>(T, f, hand);
  KinematicsData<human_hand_free> d;
  forward_kinematics(d, q);
  CHECK((frame_pose(d, f).matrix() - T.matrix()).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((q.tail<20>() - hand).norm() == 0.0);
}

TEST_CASE("approach until contact stops at the gap, and reports a miss", "[grasp][placement]") {
  using models::schunk_sdh_free;
  const GraspObject can = objects::can();
  const Composite object = can.composite();
  // The SDH pointing down (its fingers along -z) above the can.
  const Eigen::Isometry3d T =
      Eigen::Translation3d(0.0, 0.0, 0.5) * Eigen::AngleAxisd(pi, Vec3::UnitX());
  const int palm = schunk_sdh_free.frame("palm_centre");
  const Vec<13> start = place_frame<schunk_sdh_free>(T, palm, Vec<7>::Zero());
  const auto touched =
      approach_until_contact<schunk_sdh_free>(start, -Vec3::UnitZ(), object, 0.002);
  REQUIRE(touched.has_value());
  KinematicsData<schunk_sdh_free> d;
  forward_kinematics(d, *touched);
  CHECK(hand_object_distance(d, object) == Approx(0.002).margin(1e-4));
  CHECK((*touched - start).tail<10>().norm() == Approx(0.0).margin(1e-12));  // only z moved
  // Moving sideways, the hand passes the can: a miss.
  CHECK_FALSE(approach_until_contact<schunk_sdh_free>(start, Vec3::UnitX(), object).has_value());
}

// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include <topograsp/grasp/hand_axes.hpp>
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

TEST_CASE("the palm-first approach brings the palm to the object, fingers opening, hand sliding",
          "[grasp][placement]") {
  using models::human_hand_free;
  const GraspObject bottle = objects::bottle();
  const Composite object = bottle.composite();
  // The human hand 12 cm out on -x, its palm facing the bottle, fingers up, in the demonstrations'
  // pre-shape (the thumb opposed, standing out of the palm) with the index bent.
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = palm_rotation(human_hand_axes, Vec3::UnitX(), Vec3::UnitZ());
  T.translation() = Vec3(-0.152, 0.0, 0.085);
  Vec<20> pre = Vec<20>::Zero();
  pre[human_hand_free.joint("thumb_cmc2") - 6] = -deg(50.0);
  pre[human_hand_free.joint("index_pip") - 6] = 0.6;
  const int palm = human_hand_free.link("palm");
  const Vec<26> start = place_frame<human_hand_free>(T, human_hand_free.frame("grasp_centre"), pre);
  // The distance of the palm and of the nearest other link to the bottle at q.
  const auto distances = [&](const Vec<26>& q) {
    KinematicsData<human_hand_free> d;
    forward_kinematics(d, q);
    double to_palm = std::numeric_limits<double>::infinity(), nearest = to_palm;
    for (std::size_t i = 0; i < human_hand_free.n_shapes; ++i)
      for (const Primitive& p : object.parts()) {
        const double dist = signed_distance(world_shape(d, i), p).distance;
        if (human_hand_free.shapes[i].link == palm)
          to_palm = std::min(to_palm, dist);
        else
          nearest = std::min(nearest, dist);
      }
    return std::pair{to_palm, nearest};
  };
  const auto first = approach_until_contact<human_hand_free>(start, Vec3::UnitX(), object, 0.002);
  PalmApproachOptions no_slide;
  no_slide.max_slide = 0.0;
  const auto blocked =
      approach_palm_first<human_hand_free>(start, Vec3::UnitX(), object, palm, no_slide);
  const auto placed = approach_palm_first<human_hand_free>(start, Vec3::UnitX(), object, palm);
  REQUIRE(first);
  REQUIRE(blocked);
  REQUIRE(placed);
  const auto [palm_first, nearest_first] = distances(*first);
  const auto [palm_blocked, nearest_blocked] = distances(*blocked);
  const auto [palm_placed, nearest_placed] = distances(*placed);
  INFO("palm " << palm_first << " m from the bottle at the first contact, " << palm_blocked
               << " m palm first without sliding, " << palm_placed << " m with");
  // The first contact stands the thumb out: the palm is more than 2 cm away.
  CHECK(std::min(palm_first, nearest_first) == Approx(0.002).margin(1e-4));
  CHECK(palm_first > 0.02);
  // Without sliding, a link that cannot open (the thumb's base) stops the palm short, at the gap.
  CHECK(palm_blocked > 0.001);
  CHECK(nearest_blocked == Approx(0.002).margin(1e-4));
  CHECK((*blocked - start).segment<2>(1).norm() == Approx(0.0).margin(1e-15));  // no sideways move
  // Sliding sideways (square to the approach, within max_slide), the palm touches the bottle,
  // the fingers still at least the gap away.
  CHECK(palm_placed == Approx(0.0).margin(2e-5));
  CHECK(nearest_placed >= 0.002 - 1e-9);
  const Vec3 slide = (*placed).head<3>() - (*blocked).head<3>();
  CHECK(std::abs(slide.y()) > 0.001);
  CHECK(std::abs(slide.y()) <= 0.04 + 1e-12);
  CHECK(slide.z() == Approx(0.0).margin(1e-15));
  // Only the closing joints moved, and only toward open.
  const Vec<26> dir = closing_directions<human_hand_free>();
  for (int i = 6; i < 26; ++i) {
    if (dir[i] == 0.0) CHECK((*placed)[i] == start[i]);
    CHECK(dir[i] * ((*placed)[i] - start[i]) <= 1e-12);
  }
  // Missing the object is reported.
  CHECK_FALSE(approach_palm_first<human_hand_free>(start, Vec3::UnitY(), object, palm).has_value());
}

TEST_CASE("the palm-first approach names the option it refuses", "[grasp][placement]") {
  using models::human_hand_free;
  const Composite object = objects::bottle().composite();
  const Vec<26> start = Vec<26>::Zero();
  const int palm = human_hand_free.link("palm");
  const auto refused = [&](void (*set)(PalmApproachOptions&), const char* name) {
    PalmApproachOptions o;
    set(o);
    CHECK_THROWS_WITH(approach_palm_first<human_hand_free>(start, Vec3::UnitX(), object, palm, o),
                      Catch::Contains(name));
  };
  refused([](PalmApproachOptions& o) { o.gap = -0.001; }, "options.gap");
  refused([](PalmApproachOptions& o) { o.palm_gap = std::nan(""); }, "options.palm_gap");
  refused([](PalmApproachOptions& o) { o.max_slide = -1.0; }, "options.max_slide");
  refused([](PalmApproachOptions& o) { o.max_travel = 0.0; }, "options.max_travel");
  refused([](PalmApproachOptions& o) { o.open_step = 0.0; }, "options.open_step");
  refused([](PalmApproachOptions& o) { o.slide_step = HUGE_VAL; }, "options.slide_step");
  CHECK_THROWS_WITH(approach_palm_first<human_hand_free>(start, Vec3::UnitX(), object, -1),
                    Catch::StartsWith("palm"));
  CHECK_THROWS_AS(approach_palm_first<human_hand_free>(start, Vec3::UnitX(), object,
                                                       static_cast<int>(human_hand_free.n_links)),
                  invalid_argument);
}

// SPDX-License-Identifier: BSD-3-Clause
// MujocoScene, the second judge: the exported grasp loads, opens as the built-in scene has it,
// holds a box by the SDH's motors and drops it when their torque limit is too small; gravity per
// scene; copies are independent. Only with MuJoCo (TOPOGRASP_HAVE_MUJOCO).
#ifdef TOPOGRASP_HAVE_MUJOCO
#include "evaluation_test_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include <catch2/catch.hpp>
#include <topograsp/mujoco/mujoco_scene.hpp>

#include "support/throws.hpp"

using namespace topograsp;

namespace {

// The SDH's side grasp (test::sdh_side_pose) of a 0.3 kg box, 6 x 6 x 10 cm, closed by
// close_hand; \p open: the hand open and the box 10 cm beyond its fingers, touching nothing;
// \p friction: the hand-object friction coefficient.
HandScene<models::schunk_sdh> sdh_box_scene(bool open = false,
                                            double friction = HandSceneOptions{}.friction) {
  const Eigen::Isometry3d hand = test::sdh_side_pose();
  ObjectSpec o;
  o.shapes = {box("", Pose{}, {0.03, 0.03, 0.05})};
  o.pose = to_pose(
      hand * test::z_along(Eigen::Vector3d::UnitY(), Eigen::Vector3d(0, 0, open ? 0.35 : 0.15)));
  o.mass = 0.3;
  Vec<7> q;
  q << 0.0, -0.6, 0.3, -0.6, 0.3, -0.6, 0.3;
  HandSceneOptions so;
  so.friction = friction;
  HandScene<models::schunk_sdh> scene(hand, q, o, so);
  if (!open) REQUIRE(close_hand(scene).status == Status::success);
  return scene;
}

// Motors of \p effort (N m) on every SDH joint.
MjcfOptions sdh_motors(double effort) {
  MjcfOptions o;
  o.effort.assign(7, effort);
  return o;
}

double moved(const MujocoScene& s, const Eigen::Isometry3d& start) {
  return (s.object_in_hand().translation() - start.translation()).norm();
}

}  // namespace

TEST_CASE("the exported grasp opens in MuJoCo as the built-in scene has it",
          "[evaluation][mujoco]") {
  const auto scene = sdh_box_scene();
  const MujocoScene ms(scene, sdh_motors(1.0));
  CHECK(ms.substeps() == 9);
  CHECK(ms.time_step() == Approx(scene.time_step()));
  CHECK(ms.object_mass() == Approx(0.3));
  CHECK(ms.gravity().isApprox(scene.gravity()));
  CHECK(ms.hand_pose().isApprox(scene.hand_pose()));
  // The keyframe: the joints at the built-in's values (the mirror knuckle through its coupling).
  for (int i = 0; i < 7; ++i)
    CHECK(ms.joint_value(models::schunk_sdh.joint_name(i)) ==
          Approx(scene.joint_positions()[i]).margin(1e-12));
  CHECK(ms.joint_value("knuckle_2") == Approx(scene.joint_positions()[0]).margin(1e-12));
  CHECK(ms.object_in_hand().isApprox(scene.object_in_hand(), 1e-12));
  CHECK((ms.object_com() - scene.object_com()).norm() < 1e-12);
  CHECK((ms.palm_centre() - scene.palm_centre()).norm() < 1e-12);
  CHECK(ms.hand_contacts(0.001) > 0);
  CHECK(ms.deepest_penetration() > 0.0);
  CHECK(ms.collider_error() < 1e-9);  // a box and capsules: MuJoCo's own colliders, exact
}

TEST_CASE("a box held by the SDH's motors stays in MuJoCo; motors too weak drop it",
          "[evaluation][mujoco]") {
  const auto scene = sdh_box_scene();
  const double weight = 0.3 * 9.81;
  SECTION("1 N m per joint holds the box for 2 s with gravity on") {
    MujocoScene ms(scene, sdh_motors(1.0));
    const Eigen::Isometry3d start = ms.object_in_hand();
    for (int i = 0; i < 120; ++i) REQUIRE(ms.step() == Status::success);
    CHECK(moved(ms, start) < 0.01);
    CHECK(ms.hand_contacts(0.001) >= 3);
    // The grip comes from the motors: more than the weight, bounded by what they can give.
    CHECK(ms.hand_force() > weight);
    CHECK(ms.deepest_penetration() < 0.005);
  }
  SECTION("0.01 N m per joint (0.1 N at a 10 cm finger) cannot hold 2.9 N: the box falls") {
    MujocoScene ms(scene, sdh_motors(0.01));
    const Eigen::Isometry3d start = ms.object_in_hand();
    for (int i = 0; i < 120; ++i) REQUIRE(ms.step() == Status::success);
    CHECK(moved(ms, start) > 0.5);
    CHECK(ms.hand_contacts(0.001) == 0);
    CHECK(ms.hand_force() == 0.0);
  }
}

TEST_CASE("MuJoCo's convex collider gives several points a pair with multi_point_contacts",
          "[evaluation][mujoco]") {
  // The SDH's pads on a bottle (a cylinder: MuJoCo 2.2's general convex collider): one point per
  // pad without the flag, more with it, as the built-in stepper's manifolds have.
  auto scene = test::sdh_bottle_scene(0.9);
  REQUIRE(close_hand(scene).status == Status::success);
  MjcfOptions one = sdh_motors(1.0), several = sdh_motors(1.0);
  one.multi_point_contacts = false;
  MujocoScene a(scene, one), b(scene, several);
  REQUIRE(a.step() == Status::success);
  REQUIRE(b.step() == Status::success);
  const int pairs_touching = a.hand_contacts(0.001);
  INFO(pairs_touching << " contacts with one point a pair, " << b.hand_contacts(0.001)
                      << " with several");
  CHECK(pairs_touching >= 2);
  CHECK(b.hand_contacts(0.001) > pairs_touching);
  CHECK(to_mjcf(scene, one).find("multiccd") == std::string::npos);
}

TEST_CASE("MuJoCo's noslip solver keeps a grip below its friction limit from creeping",
          "[evaluation][mujoco]") {
  // The box held by the SDH's motors at a small fraction of their limits, gravity pulling it
  // along the fingers, 4 s: MuJoCo's soft friction constraints let it creep through the grip; its
  // noslip solver (the default, MjcfOptions::noslip_iterations) stops that, as the built-in
  // stepper's friction sticks below its cone.
  const auto run = [](double friction, double fraction) {
    auto held = sdh_box_scene(false, friction);
    held.set_effort_fraction(fraction);
    MjcfOptions soft;
    soft.noslip_iterations = 0;
    MujocoScene a(held, soft), b(held, MjcfOptions{});
    auto built_in = held;
    const Eigen::Isometry3d start = held.object_in_hand();
    std::array<double, 3> one_s{}, four_s{};  // soft, noslip, built-in
    for (int i = 1; i <= 240; ++i) {
      REQUIRE(a.step() == Status::success);
      REQUIRE(b.step() == Status::success);
      REQUIRE(built_in.step() == Status::success);
      if (i != 60 && i != 240) continue;
      const std::array<double, 3> now{
          moved(a, start), moved(b, start),
          (built_in.object_in_hand().translation() - start.translation()).norm()};
      (i == 60 ? one_s : four_s) = now;
    }
    CHECK(b.hand_contacts(0.001) >= 3);
    return std::pair{one_s, four_s};
  };
  SECTION("near the limit MuJoCo without noslip loses the box; with it, it holds as built-in") {
    const auto [one_s, four_s] = run(0.5, 0.07);  // each: without noslip, with, built-in (m)
    CAPTURE(one_s, four_s);
    CHECK(four_s[0] > 0.02);  // the stability suite's limit
    CHECK(four_s[1] < 0.01);
    CHECK(four_s[2] < 0.01);
  }
  SECTION("further from it the box creeps without noslip and stays put with it") {
    const auto [one_s, four_s] = run(0.7, 0.05);
    CAPTURE(one_s, four_s);
    CHECK(four_s[0] - one_s[0] > 2e-4);
    CHECK(std::abs(four_s[1] - one_s[1]) < 5e-5);
    CHECK(std::abs(four_s[2] - one_s[2]) < 5e-5);
  }
  MjcfOptions soft;
  soft.noslip_iterations = 0;
  CHECK(to_mjcf(sdh_box_scene(), MjcfOptions{}).find("noslip_iterations=\"10\"") !=
        std::string::npos);
  CHECK(to_mjcf(sdh_box_scene(), soft).find("noslip_iterations") == std::string::npos);
}

TEST_CASE("MuJoCo scene gravity moves a free object along it; copies are independent",
          "[evaluation][mujoco]") {
  const auto built_in = sdh_box_scene(true);
  MujocoScene ms(built_in, sdh_motors(1.0));
  REQUIRE(ms.hand_contacts(0.001) == 0);
  const double g = built_in.gravity().norm();
  REQUIRE(built_in.gravity().isApprox(Vec3(0.0, 0.0, -g)));
  const Vec3 c0 = ms.object_com();
  MujocoScene copy = ms;
  copy.set_gravity(Vec3(9.81, 0.0, 0.0));
  CHECK(ms.gravity() == built_in.gravity());
  for (int i = 0; i < 30; ++i) REQUIRE(copy.step() == Status::success);
  // 0.5 s of free fall along +x: 1.23 m (MuJoCo's implicit Euler, to 2 %).
  const Vec3 d = copy.object_com() - c0;
  CHECK(d.x() == Approx(0.5 * 9.81 * 0.25).epsilon(0.02));
  CHECK(std::abs(d.y()) < 1e-9);
  CHECK(std::abs(d.z()) < 1e-9);
  // The original did not move while its copy fell, and falls down when stepped.
  CHECK((ms.object_com() - c0).norm() == 0.0);
  for (int i = 0; i < 30; ++i) REQUIRE(ms.step() == Status::success);
  CHECK((ms.object_com() - c0).z() == Approx(-0.5 * g * 0.25).epsilon(0.02));
  // A copy continues exactly as its original (mj_copyData copies the whole state).
  MujocoScene twin = copy;
  copy.set_hand_pose(copy.hand_pose() * Eigen::Translation3d(0.0, 0.01, 0.0));
  twin.set_hand_pose(copy.hand_pose());
  for (int i = 0; i < 5; ++i) {
    REQUIRE(copy.step() == Status::success);
    REQUIRE(twin.step() == Status::success);
  }
  CHECK(twin.object_com() == copy.object_com());
  // Assignment copies too (reusing the target's mjData: the same model), and the assigned
  // scene goes on exactly as its source, as stability_suite() relies on.
  twin = ms;
  CHECK(twin.object_com() == ms.object_com());
  CHECK(twin.gravity() == ms.gravity());
  for (int i = 0; i < 5; ++i) {
    REQUIRE(twin.step() == Status::success);
    REQUIRE(ms.step() == Status::success);
  }
  CHECK(twin.object_com() == ms.object_com());
  CHECK(twin.object_in_hand().isApprox(ms.object_in_hand(), 0.0));
}

TEST_CASE("the hand moves to the pose set; its welded base follows", "[evaluation][mujoco]") {
  MujocoScene ms(sdh_box_scene(true), sdh_motors(1.0));
  ms.set_gravity(Vec3::Zero());
  Eigen::Isometry3d target = ms.hand_pose();
  target.translation() += Vec3(0.0, 0.0, 0.05);
  target.linear() = Eigen::AngleAxisd(0.3, Vec3::UnitZ()).toRotationMatrix() * target.linear();
  ms.set_hand_pose(target);
  REQUIRE(ms.step() == Status::success);
  const mjData& d = ms.data();
  const mjModel& m = ms.model();
  CHECK((Vec3(d.mocap_pos[0], d.mocap_pos[1], d.mocap_pos[2]) - target.translation()).norm() <
        1e-12);
  const int hand = mj_name2id(&m, mjOBJ_BODY, "hand");
  CHECK((Vec3(d.xpos[3 * hand], d.xpos[3 * hand + 1], d.xpos[3 * hand + 2]) - target.translation())
            .norm() < 1e-12);
  // The base is a free body: it has the velocity of its motion, and reaches the target within a
  // few of the weld's 4 ms time constants.
  const int base = mj_name2id(&m, mjOBJ_BODY, "hand_base");
  REQUIRE(base >= 0);
  const int dof = m.jnt_dofadr[m.body_jntadr[base]];
  CHECK(Vec3(d.qvel[dof], d.qvel[dof + 1], d.qvel[dof + 2]).norm() > 0.5);  // 5 cm in 1/60 s
  for (int i = 0; i < 6; ++i) REQUIRE(ms.step() == Status::success);
  const Eigen::Isometry3d T_base =
      Eigen::Translation3d(d.xpos[3 * base], d.xpos[3 * base + 1], d.xpos[3 * base + 2]) *
      Eigen::Quaterniond(d.xquat[4 * base], d.xquat[4 * base + 1], d.xquat[4 * base + 2],
                         d.xquat[4 * base + 3]);
  CHECK((T_base.translation() - target.translation()).norm() < 1e-4);
  CHECK(Eigen::AngleAxisd(T_base.linear().transpose() * target.linear()).angle() < 1e-3);
}

TEST_CASE("a held box goes with a hand that moves fast: its contacts drag it",
          "[evaluation][mujoco]") {
  // The hand is carried with a velocity (the weld), so friction at the fingers carries the box:
  // 30 cm sideways and a 45 degree turn in 0.25 s, then 0.25 s at rest.
  MujocoScene ms(sdh_box_scene(), sdh_motors(1.0));
  ms.set_gravity(Vec3::Zero());
  const Eigen::Isometry3d start = ms.object_in_hand();
  const Eigen::Isometry3d from = ms.hand_pose();
  for (int i = 1; i <= 30; ++i) {
    const double a = std::min(1.0, i / 15.0);
    ms.set_hand_pose(Eigen::Translation3d(0.3 * a, 0.0, 0.0) * from *
                     Eigen::AngleAxisd(a * 0.785, Vec3::UnitX()));
    REQUIRE(ms.step() == Status::success);
  }
  CHECK(moved(ms, start) < 0.005);
  CHECK(Eigen::AngleAxisd(start.linear().transpose() * ms.object_in_hand().linear()).angle() <
        0.05);
}

TEST_CASE("collider_error measures how much deeper MuJoCo takes an overlap than it is",
          "[evaluation][mujoco]") {
  // A finger capsule across a hammer handle (a cylinder along z) near its end, overlapping it by
  // 1.5 mm (the pair of a grasp of the default run). MuJoCo 2.2's convex collider (MPR) measures
  // it exactly without a margin, and 23 mm deep with a 5 mm margin (the shapes grown by it).
  const auto scene_with_margin = [](const char* margin) {
    return std::string(
               "<mujoco><worldbody><body name=\"hand\" mocap=\"true\" "
               "pos=\"-0.0152 -0.0217 0.1155\"><geom name=\"cap\" type=\"capsule\" "
               "size=\"0.014 0.04325\" zaxis=\"-0.846 0.531 0.034\" margin=\"") +
           margin + "\" gap=\"" + margin +
           "\"/></body><body name=\"object\"><joint type=\"free\"/><geom type=\"cylinder\" "
           "size=\"0.014 0.14\"/></body></worldbody></mujoco>";
  };
  const MujocoScene exact(scene_with_margin("0"));
  REQUIRE(exact.hand_contacts() == 1);
  CHECK(exact.deepest_penetration() == Approx(0.0015).margin(1e-4));
  CHECK(exact.collider_error() < 1e-6);
  const MujocoScene grown(scene_with_margin("0.005"));
  REQUIRE(grown.hand_contacts() == 1);
  CHECK(grown.deepest_penetration() > 0.02);
  CHECK(grown.collider_error() > 0.02);
  CHECK(grown.collider_error() == Approx(grown.deepest_penetration() - 0.0015).margin(1e-4));
}

TEST_CASE("MujocoScene refuses bad input with readable errors", "[evaluation][mujoco]") {
  // MuJoCo's own error text comes through.
  try {
    MujocoScene bad("<mujoco><worldbody><geom type=\"nonsense\"/></worldbody></mujoco>");
    FAIL("loaded a bad model");
  } catch (const invalid_argument& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.rfind("mjcf: MuJoCo did not load it: ", 0) == 0);
    CHECK(what.find("nonsense") != std::string::npos);
  }
  test::check_throws_naming([] { MujocoScene s("not xml at all"); }, "mjcf");
  const std::string no_hand =
      "<mujoco><worldbody><body name=\"object\"><freejoint/><geom size=\"0.1\"/></body>"
      "</worldbody></mujoco>";
  test::check_throws_naming([&] { MujocoScene s(no_hand); }, "mjcf");
  const std::string no_object =
      "<mujoco><worldbody><body name=\"hand\" mocap=\"true\"><geom size=\"0.1\"/></body>"
      "</worldbody></mujoco>";
  test::check_throws_naming([&] { MujocoScene s(no_object); }, "mjcf");
  const std::string minimal =
      "<mujoco><worldbody><body name=\"hand\" mocap=\"true\"><geom size=\"0.1\"/></body>"
      "<body name=\"object\" pos=\"1 0 0\"><freejoint/><geom size=\"0.1\"/></body>"
      "</worldbody></mujoco>";
  test::check_throws_naming([&] { MujocoScene s(minimal, 0); }, "substeps");
  MujocoScene s(minimal);  // the contract alone is enough: no keyframe, no palm site
  CHECK(s.palm_centre() == Vec3::Zero());
  test::check_throws_naming([&] { s.set_gravity(Vec3(0.0, std::nan(""), 0.0)); }, "g");
  Eigen::Isometry3d skew = Eigen::Isometry3d::Identity();
  skew.linear()(0, 1) = 0.5;
  test::check_throws_naming([&] { s.set_hand_pose(skew); }, "pose");
  Eigen::Isometry3d nan = Eigen::Isometry3d::Identity();
  nan.translation().x() = std::nan("");
  test::check_throws_naming([&] { s.set_hand_pose(nan); }, "pose");
  test::check_throws_naming([&] { (void)s.joint_value("no_such_joint"); }, "name");
  // A hand whose model gives no effort limits cannot be judged without options.effort.
  if (models::schunk_sdh.joint_spec(1).effort == 0.0)
    test::check_throws_naming([] { MujocoScene j(sdh_box_scene(true)); }, "scene");
  test::check_throws_naming([] { MujocoScene j(sdh_box_scene(true), sdh_motors(-1.0)); },
                            "options.effort[0]");
}

#endif  // TOPOGRASP_HAVE_MUJOCO

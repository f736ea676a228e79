// SPDX-License-Identifier: BSD-3-Clause
// MJCF export: the articulated scene names the mocap hand, the links with their joints and
// motors, the couplings, the free object with its inertia and the contact pairs with their
// friction; with MuJoCo found, the file loads back and matches the scene (the MuJoCo adapter's
// own tests are in test_mujoco_scene.cpp).
#include "evaluation_test_support.hpp"

#include <algorithm>
#include <array>
#include <string>

#include <catch2/catch.hpp>
#include <topograsp/io/mjcf.hpp>

#include "support/throws.hpp"

#ifdef TOPOGRASP_HAVE_MUJOCO
#include <topograsp/mujoco/mujoco_scene.hpp>
#endif

using namespace topograsp;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("a hand scene exports as articulated MJCF: mocap hand, joints, motors, object, pairs",
          "[evaluation][mjcf]") {
  auto scene = test::sdh_bottle_scene(0.9);
  REQUIRE(close_hand(scene).status == Status::success);
  MjcfOptions options;
  options.effort.assign(7, 0.5);
  const std::string xml = to_mjcf(scene, options);
  CHECK(xml.find("<mujoco model=\"schunk_sdh\">") != std::string::npos);
  CHECK(xml.find("<body name=\"hand\" mocap=\"true\"") != std::string::npos);
  CHECK(xml.find("<body name=\"hand_base\"") != std::string::npos);
  CHECK(xml.find("<weld name=\"hand_base\" body1=\"hand_base\" body2=\"hand\"") !=
        std::string::npos);
  CHECK(xml.find("<body name=\"finger_13\"") != std::string::npos);
  CHECK(xml.find("<body name=\"object\"") != std::string::npos);
  CHECK(xml.find("type=\"free\"") != std::string::npos);
  CHECK(xml.find("mass=\"0.5\"") != std::string::npos);
  CHECK(xml.find("cone=\"elliptic\"") != std::string::npos);
  CHECK(xml.find("impratio=\"10\"") != std::string::npos);
  CHECK(xml.find("integrator=\"implicit\"") != std::string::npos);
  CHECK(xml.find("<flag multiccd=\"enable\"/>") != std::string::npos);
  CHECK(xml.find("noslip_iterations=\"10\"") != std::string::npos);
  CHECK(xml.find("<key name=\"grasp\"") != std::string::npos);
  CHECK(xml.find("nan") == std::string::npos);
  // 8 joints (the knuckle's mirror coupled by one equality), 7 motors of 0.5 N m.
  CHECK(count(xml, "type=\"hinge\"") == 8);
  CHECK(count(xml, "<position ") == 7);
  CHECK(count(xml, "forcerange=\"-0.5 0.5\"") == 7);
  CHECK(xml.find("<joint joint1=\"knuckle_2\" joint2=\"knuckle\" polycoef=\"0 1 0 0 0\"/>") !=
        std::string::npos);
  // One pair per (hand shape, object shape), each with the World's pair friction.
  const auto& world = scene.world();
  const int hand_shapes = world.collider_count() - 1;
  CHECK(static_cast<int>(count(xml, "<pair ")) == hand_shapes);
  CHECK(static_cast<int>(count(xml, "friction=\"0.9")) == hand_shapes);
  // The scene's 1/60 s in 9 steps of 1.85 ms (<= 2 ms).
  CHECK(mjcf_substeps(1.0 / 60.0, 0.002) == 9);
  CHECK(mjcf_substeps(0.002, 0.002) == 1);
  CHECK(mjcf_substeps(0.001, 0.002) == 1);

#ifdef TOPOGRASP_HAVE_MUJOCO
  const MujocoScene ms(xml, 9);
  const mjModel& m = ms.model();
  CHECK(m.nmocap == 1);
  CHECK(m.nu == 7);
  CHECK(m.neq == 2);  // the base's weld and the knuckle's coupling
  CHECK(m.eq_type[0] == mjEQ_WELD);
  CHECK(m.eq_solref[0] == Approx(0.004));
  CHECK(m.njnt == 10);  // the base's free joint, 8 hinges and the object's free joint
  CHECK(m.npair == hand_shapes);
  for (int p = 0; p < m.npair; ++p) {
    CHECK(m.pair_friction[5 * p] == Approx(0.9).epsilon(1e-15));
    CHECK(m.pair_friction[5 * p + 1] == Approx(0.9).epsilon(1e-15));
    CHECK(m.pair_dim[p] == 4);
    CHECK(m.pair_solref[mjNREF * p] == Approx(0.01));  // near the built-in pads' stiffness
  }
  CHECK(m.ngeom == world.collider_count());
  CHECK(m.opt.timestep == Approx(1.0 / 60.0 / 9.0));
  CHECK(m.opt.cone == mjCONE_ELLIPTIC);
  CHECK(m.opt.integrator == mjINT_IMPLICIT);
  CHECK(m.opt.impratio == Approx(10.0));
  CHECK((m.opt.enableflags & mjENBL_MULTICCD) != 0);
  CHECK(m.opt.noslip_iterations == 10);
  const int object = mj_name2id(&m, mjOBJ_BODY, "object");
  REQUIRE(object >= 0);
  CHECK(m.body_mass[object] == Approx(0.5));
  // Principal moments of the bottle (a cylinder): m r^2 / 2 and m (3 r^2 + (2h)^2) / 12.
  std::array<double, 3> I{m.body_inertia[3 * object], m.body_inertia[3 * object + 1],
                          m.body_inertia[3 * object + 2]};
  std::sort(I.begin(), I.end());
  const double r = 0.035, h = 0.1;
  CHECK(I[0] == Approx(0.5 * r * r / 2).epsilon(1e-6));
  CHECK(I[2] == Approx(0.5 * (3 * r * r + 4 * h * h) / 12).epsilon(1e-6));
  // The motors: force range, kp the built-in servo's stiffness, control range = joint limits.
  const int a = mj_name2id(&m, mjOBJ_ACTUATOR, "finger_12");
  REQUIRE(a >= 0);
  CHECK(m.actuator_forcelimited[a] == 1);
  CHECK(m.actuator_forcerange[2 * a + 1] == Approx(0.5));
  CHECK(m.actuator_gainprm[mjNGAIN * a] ==
        Approx(m.actuator_forcerange[2 * a + 1] / scene.effort_fraction() / scene.servo_reach(1)));
  CHECK(m.actuator_ctrlrange[2 * a] == Approx(models::schunk_sdh.joint_spec(1).lower));
  CHECK(m.actuator_ctrlrange[2 * a + 1] == Approx(models::schunk_sdh.joint_spec(1).upper));
  // The keyframe puts every hand shape where the scene has it.
  const mjData& d = ms.data();
  for (int c = 0; c < world.collider_count(); ++c) {
    const auto& col = world.collider(c);
    if (world.body(col.body).type != BodyType::kinematic) continue;
    const int gid = mj_name2id(&m, mjOBJ_GEOM, ("hand_" + std::to_string(c)).c_str());
    REQUIRE(gid >= 0);
    for (int k = 0; k < 3; ++k) CHECK(d.geom_xpos[3 * gid + k] == Approx(col.p[k]).margin(1e-9));
  }
  // The object starts where the scene has it, and MuJoCo finds the hand touching it.
  const Eigen::Vector3d com = world.body(scene.object_body()).x;
  for (int k = 0; k < 3; ++k) CHECK(d.xipos[3 * object + k] == Approx(com[k]).margin(1e-9));
  CHECK(ms.hand_contacts() > 0);
#endif
}

TEST_CASE("the human hand exports with every link where the built-in scene has it",
          "[evaluation][mjcf]") {
  // The hammer's handle across the palm (as bench_physics): a tree of five fingers, so the MJCF
  // bodies (depth first) are not in the model's link order, and the keyframe must follow them.
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  hand.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  hand.translation() = Vec3(0, 0, 0.3);
  ObjectSpec hammer;
  hammer.shapes = {cylinder("", Pose{}, 0.016, 0.14),
                   box("", at(0, 0, 0.1525), {0.06, 0.0125, 0.0125})};
  Eigen::Isometry3d in_hand = Eigen::Isometry3d::Identity();
  in_hand.linear() = Eigen::AngleAxisd(-pi / 2, Vec3::UnitX()).toRotationMatrix();
  in_hand.translation() = Vec3(0.032, -0.06, 0.10);
  hammer.pose = to_pose(hand * in_hand);
  hammer.mass = 0.6;
  Vec<models::human_hand.nq> q = Vec<models::human_hand.nq>::Zero();
  q[17] = 0.3;
  HandScene<models::human_hand> scene(hand, q, hammer);
  REQUIRE(close_hand(scene).status == Status::success);
  const std::string xml = to_mjcf(scene);
  CHECK(static_cast<int>(count(xml, "<position ")) == models::human_hand.nq);
  const auto& world = scene.world();
  CHECK(static_cast<int>(count(xml, "<pair ")) == 2 * (world.collider_count() - 2));
#ifdef TOPOGRASP_HAVE_MUJOCO
  const MujocoScene ms(xml, 9);
  const mjModel& m = ms.model();
  CHECK(m.nu == models::human_hand.nq);
  CHECK(m.ngeom == world.collider_count());
  const mjData& d = ms.data();
  int checked = 0;
  for (int c = 0; c < world.collider_count(); ++c) {
    const auto& col = world.collider(c);
    if (world.body(col.body).type != BodyType::kinematic) continue;
    const int gid = mj_name2id(&m, mjOBJ_GEOM, ("hand_" + std::to_string(c)).c_str());
    REQUIRE(gid >= 0);
    for (int k = 0; k < 3; ++k) CHECK(d.geom_xpos[3 * gid + k] == Approx(col.p[k]).margin(1e-9));
    ++checked;
  }
  CHECK(checked == world.collider_count() - 2);
  for (int i = 0; i < models::human_hand.nq; ++i)
    CHECK(ms.joint_value(models::human_hand.joint_name(i)) ==
          Approx(scene.joint_positions()[i]).margin(1e-12));
  CHECK(ms.object_in_hand().isApprox(scene.object_in_hand(), 1e-12));
#endif
}

TEST_CASE("the articulated export writes a model without effort data and refuses bad options",
          "[evaluation][mjcf]") {
  auto scene = test::sdh_bottle_scene();
  // The SDH has no effort data on this branch's model: the motors have no force range and say so.
  if (models::schunk_sdh.joint_spec(1).effort == 0.0) {
    const std::string xml = to_mjcf(scene);
    CHECK(count(xml, "<position ") == 7);
    CHECK(xml.find("forcerange") == std::string::npos);
    CHECK(xml.find("no effort limit for finger_12") != std::string::npos);
  }
  const auto bad = [&](auto set, const char* name) {
    MjcfOptions o;
    set(o);
    test::check_throws_naming([&] { (void)to_mjcf(scene, o); }, name);
  };
  bad([](MjcfOptions& o) { o.max_time_step = 0.0; }, "options.max_time_step");
  bad([](MjcfOptions& o) { o.impratio = -1.0; }, "options.impratio");
  bad([](MjcfOptions& o) { o.default_armature = -1.0; }, "options.default_armature");
  bad([](MjcfOptions& o) { o.contact_timeconst = 0.001; }, "options.contact_timeconst");
  bad([](MjcfOptions& o) { o.hand_timeconst = 0.003; }, "options.hand_timeconst");
  bad([](MjcfOptions& o) { o.report_distance = -1.0; }, "options.report_distance");
  bad([](MjcfOptions& o) { o.noslip_iterations = -1; }, "options.noslip_iterations");
  bad([](MjcfOptions& o) { o.noslip_iterations = 1001; }, "options.noslip_iterations");
  bad([](MjcfOptions& o) { o.effort.assign(3, 1.0); }, "options.effort");
  bad([](MjcfOptions& o) { o.effort = {1, 1, 1, 0, 1, 1, 1}; }, "options.effort[3]");
  test::check_throws_naming([] { (void)mjcf_substeps(0.0, 0.002); }, "time_step");
  test::check_throws_naming([] { (void)mjcf_substeps(0.01, -1.0); }, "max_time_step");
  test::check_throws_naming([] { (void)mjcf_substeps(1.0, 1e-9); }, "max_time_step");
}

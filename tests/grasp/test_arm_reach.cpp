// SPDX-License-Identifier: BSD-3-Clause
// The arm setting: arm_reach() finds the arm's joints for hand poses the arm can reach, refuses
// the ones it cannot and the ones where the arm would enter the object, with a reason; and every
// transfer method in the arm setting is reached by the arm or not planned, saying why.
#include <cmath>
#include <limits>
#include <random>

#include <catch2/catch.hpp>

#include <topograsp/grasp/transfer.hpp>

using namespace topograsp;

namespace {
constexpr auto& arm_sdh = OnArm<models::schunk_sdh>::model;

// The SDH's palm pose (world) with the arm at q_arm and the hand at the SDH's pre-shape.
Eigen::Isometry3d palm_at(const Vec<7>& q_arm, KinematicsData<arm_sdh>& d) {
  Vec<14> q;
  q << q_arm, TransferOptions{}.sdh_preshape;
  forward_kinematics(d, q);
  return link_pose(d, arm_sdh.find_link("palm"));
}
}  // namespace

TEST_CASE("arm_reach finds the arm's joints for poses the arm can reach", "[grasp][arm]") {
  // Poses made by the arm itself (uniform joints within its limits), the object far away: the
  // inverse kinematics finds nearly all of them, and its joints put the palm where asked.
  const GraspObject bottle = objects::bottle();
  Eigen::Isometry3d away = Eigen::Isometry3d::Identity();
  away.translation() = Vec3(5.0, 5.0, 5.0);
  const TransferOptions options;
  const Vec<7> lo = lower_limits<arm_sdh>().head<7>(), hi = upper_limits<arm_sdh>().head<7>();
  std::mt19937 rng(7);
  int reached = 0;
  KinematicsData<arm_sdh> d;
  for (int k = 0; k < 100; ++k) {
    Vec<7> q;
    for (int i = 0; i < 7; ++i) q[i] = std::uniform_real_distribution<double>(lo[i], hi[i])(rng);
    const Eigen::Isometry3d palm = palm_at(q, d);
    const ArmReach r = arm_reach(bottle, away, away.inverse() * palm, options.arm_ready);
    if (!r.reached) continue;
    ++reached;
    CHECK(r.reason.empty());
    CHECK(r.position_error <= 1e-3);
    CHECK(r.rotation_error <= 1e-2);
    CHECK(((r.q_arm.array() >= lo.array()) && (r.q_arm.array() <= hi.array())).all());
    const Eigen::Isometry3d found = palm_at(r.q_arm, d);
    CHECK((found.translation() - palm.translation()).norm() <= 1e-3 + 1e-12);
  }
  CHECK(reached >= 95);
}

TEST_CASE("arm_reach refuses what the arm cannot reach, and an arm inside the object",
          "[grasp][arm]") {
  const GraspObject bottle = objects::bottle();
  const TransferOptions options;
  KinematicsData<arm_sdh> d;
  const Eigen::Isometry3d palm = palm_at(options.arm_ready, d);
  // 2 m beyond the arm's reach.
  Eigen::Isometry3d far = palm;
  far.pretranslate(Vec3(2.0, 0.0, 0.0));
  Eigen::Isometry3d away = Eigen::Isometry3d::Identity();
  away.translation() = Vec3(5.0, 5.0, 5.0);
  const ArmReach out = arm_reach(bottle, away, away.inverse() * far, options.arm_ready);
  CHECK_FALSE(out.reached);
  CHECK_THAT(out.reason, Catch::StartsWith("the arm cannot reach the hand pose ("));
  CHECK(out.position_error > 0.5);  // the arm stretches toward it, a metre short
  // The ready pose's palm, with the bottle's centre of mass on the arm's last module (just behind
  // the flange): every solution puts that module there, so the arm strikes the object.
  const int last = arm_sdh.find_link("arm_7");
  const Vec3 module = link_pose(d, last) * Vec3(0.0, 0.0, 0.0);
  const Vec3 flange = link_pose(d, arm_sdh.find_link("palm")).translation();
  Eigen::Isometry3d on_arm = Eigen::Isometry3d::Identity();
  on_arm.translation() = 0.5 * (module + flange) - bottle.centre_of_mass();
  const ArmReach struck = arm_reach(bottle, on_arm, on_arm.inverse() * palm, options.arm_ready);
  CHECK_FALSE(struck.reached);
  CHECK_THAT(struck.reason, Catch::StartsWith("the arm strikes the object ("));
  CHECK(struck.clearance < 0.0);
  CHECK(struck.position_error <= 1e-3);
  // Not finite: not reached.
  Eigen::Isometry3d nan = palm;
  nan.translation().x() = std::numeric_limits<double>::quiet_NaN();
  const ArmReach bad = arm_reach(bottle, away, nan, options.arm_ready);
  CHECK_FALSE(bad.reached);
  CHECK(bad.reason == "the arm cannot reach the hand pose (not finite)");
}

TEST_CASE("in the arm setting every method is reached by the arm or not planned, saying why",
          "[grasp][arm][transfer]") {
  const GraspObject bottle = objects::bottle();
  const auto hypotheses = box_hypotheses(bottle);
  HumanGrasp g;
  for (std::size_t i = 0; i < hypotheses.size() && !g.stable(); ++i)
    g = demonstrate(bottle, hypotheses[i], static_cast<int>(i));
  REQUIRE(g.stable());
  // The object fixed in front of the arm: each method's hand is reached (its arm joints put the
  // palm at its pose) or the method fails with the arm's reason; never judged unreached.
  TransferOptions options;
  options.arm_object = arm_setting_object_pose(bottle);
  CHECK((options.arm_object->translation() + bottle.centre_of_mass() - arm_setting_object_point)
            .norm() < 1e-12);
  KinematicsData<arm_sdh> d;
  for (const TransferMethod m : {TransferMethod::topological, TransferMethod::autoclose,
                                 TransferMethod::transplant, TransferMethod::virtual_finger}) {
    CAPTURE(to_string(m));
    const SdhTransfer t = transfer(m, bottle, g, options);
    INFO(t.reason);
    REQUIRE(t.arm_joints.has_value());
    if (t.planned) {
      const Eigen::Isometry3d palm = palm_at(*t.arm_joints, d);
      CHECK((palm.translation() - *options.arm_object * t.hand_pose.translation()).norm() <=
            1e-3 + 1e-12);
    } else {
      CHECK_THAT(t.reason,
                 Catch::StartsWith("the arm cannot reach") || Catch::StartsWith("the arm strikes"));
      CHECK_FALSE(t.stable());
    }
  }
  // The topological plan and the no_plan control need the arm at the plan's start too.
  for (const TransferMethod m : {TransferMethod::topological, TransferMethod::no_plan}) {
    CAPTURE(to_string(m));
    const SdhTransfer t = transfer(m, bottle, g, options);
    INFO(t.reason);
    REQUIRE(t.arm_joints.has_value());
    if (!t.planned)
      CHECK_THAT(t.reason,
                 Catch::StartsWith("the arm cannot reach") || Catch::StartsWith("the arm strikes"));
  }
  // Far out of reach: every method fails with the arm's reason.
  options.arm_object->translation() += Vec3(3.0, 0.0, 0.0);
  for (const TransferMethod m : {TransferMethod::autoclose, TransferMethod::transplant}) {
    const SdhTransfer t = transfer(m, bottle, g, options);
    CHECK_FALSE(t.planned);
    CHECK_THAT(t.reason, Catch::StartsWith("the arm cannot reach the hand pose"));
  }
  // Without the arm setting nothing is reached by the arm.
  CHECK_FALSE(transfer(TransferMethod::transplant, bottle, g, TransferOptions{}).arm_joints);
}

TEST_CASE("in the arm setting the topological plan starts where the hand setting starts",
          "[grasp][arm][transfer]") {
  // The arm moves from its ready pose, by its inverse kinematics, to the hand setting's start
  // (the SDH's grasp frame 3 cm short of the human's, the pre-shape) and the plan runs from there
  // over all 14 joints: the same start relative to the object as the hand setting's, so the same
  // windings at the plan's first step; the no_plan control is judged where that start puts the
  // hand, as in the hand setting. Where the arm cannot be at the start, both fail saying so.
  const GraspObject bottle = objects::bottle();
  const auto hypotheses = box_hypotheses(bottle);
  TransferOptions arm;
  arm.arm_object = arm_setting_object_pose(bottle);
  const TransferOptions hand;
  int compared = 0, refused = 0;
  for (std::size_t i = 0; i < hypotheses.size() && compared < 3; ++i) {
    const HumanGrasp g = demonstrate(bottle, hypotheses[i], static_cast<int>(i));
    if (!g.stable()) continue;
    CAPTURE(i);
    const SdhTransfer fixed = transfer(TransferMethod::topological, bottle, g, arm);
    INFO(fixed.reason);
    if (!fixed.planned && fixed.sweeps == 0) {
      CHECK_THAT(fixed.reason, Catch::EndsWith(" at the plan's start"));
      CHECK_THAT(transfer(TransferMethod::no_plan, bottle, g, arm).reason,
                 Catch::EndsWith(" at the plan's start"));
      ++refused;
      continue;
    }
    const SdhTransfer turned = transfer(TransferMethod::topological, bottle, g, hand);
    REQUIRE_FALSE(fixed.winding_plan.empty());
    REQUIRE_FALSE(turned.winding_plan.empty());
    CHECK((fixed.winding_plan.front() - turned.winding_plan.front()).norm() < 0.02);
    CHECK(fixed.sweeps > 0);
    const SdhTransfer still = transfer(TransferMethod::no_plan, bottle, g, arm);
    const SdhTransfer still_hand = transfer(TransferMethod::no_plan, bottle, g, hand);
    INFO(still.reason);
    REQUIRE(still.planned);
    CHECK((still.hand_pose.translation() - still_hand.hand_pose.translation()).norm() < 5e-3);
    CHECK(still.sweeps == 0);
    ++compared;
  }
  CHECK(compared == 3);
  CHECK(refused > 0);
}

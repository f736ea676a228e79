// SPDX-License-Identifier: BSD-3-Clause
// Hand scenes: closing each shipped hand on a cylinder, the stability suite on an SDH grasp, bad
// input. (The suite on scenes of known outcome: test_stability_suite.cpp.)
#include "evaluation_test_support.hpp"

#include <cstring>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

using namespace topograsp;
using test::cylinder_object;

namespace {

// Closes the hand of model M at configuration q on a cylinder and checks the outcome.
template <const auto& M>
void check_closing(const Vec<M.nq>& q, const Eigen::Vector3d& centre, const Eigen::Vector3d& axis,
                   double r, int min_touching, bool holds = true) {
  const Eigen::Isometry3d hand =
      test::z_along(Eigen::Vector3d(1, 1, 0).normalized(), Eigen::Vector3d(0.1, -0.2, 0.5));
  HandScene<M> scene(hand, q, cylinder_object(hand, centre, axis, r, 0.08, 0.3));
  const CloseOptions co;
  const auto result = close_hand(scene, co);
  REQUIRE(result.status == Status::success);
  CHECK(result.touching_joints >= min_touching);
  if (holds) CHECK(result.contacts >= 2);
  const Vec<M.nq> lo = lower_limits<M>(), hi = upper_limits<M>(), dir = closing_directions<M>();
  for (int i = 0; i < M.nq; ++i) {
    INFO("joint " << M.joint_name(i));
    if (dir[i] == 0.0) {
      CHECK(result.q_contact[i] == q[i]);  // joints that do not close stay where they were
      continue;
    }
    // Each closing joint moved toward closed, and stopped at contact or at its limit.
    CHECK(dir[i] * (result.q_contact[i] - q[i]) >= 0.0);
    const bool at_limit = result.q_contact[i] == lo[i] || result.q_contact[i] == hi[i];
    CHECK((result.touched[static_cast<std::size_t>(i)] || at_limit));
    // Then the motors, commanded closed, stopped each such joint where it stalls (its motor at
    // its hold torque: pressing on the object, or pushed back by it) or at its limit; no motor
    // gave more than its hold torque.
    const double closed_limit = dir[i] > 0.0 ? hi[i] : lo[i];
    const double torque = std::abs(scene.motor_torque(i));
    const double hold = co.hold_fraction * M.joint_spec(i).effort;
    CHECK((std::abs(result.q_closed[i] - closed_limit) < 0.05 || torque > 0.9 * hold));
    CHECK(torque <= hold * 1.0001);
  }
  CHECK(scene.effort_fraction() == 1.0);  // holding: the full limit against loads
  if (!holds) return;
  // Closed, the hand presses on the object without a deep overlap (well under a finger radius).
  CHECK(scene.hand_force() > 1.0);
  for (const auto& m : scene.world().manifolds())
    for (int k = 0; k < m.count; ++k)
      CHECK(m.points[static_cast<std::size_t>(k)].separation > -0.01);
}

// The human hand (thumb CMC2 opened, every other joint at 0) and a 0.3 kg cylinder of radius
// 2 cm, 16 cm long, across its fingers at \p centre (hand frame).
HandScene<models::human_hand> human_cylinder_scene(const Eigen::Vector3d& centre) {
  const Eigen::Isometry3d hand =
      test::z_along(Eigen::Vector3d(1, 1, 0).normalized(), Eigen::Vector3d(0.1, -0.2, 0.5));
  Vec<20> q = Vec<20>::Zero();
  q[17] = 0.3;  // thumb CMC2 opened (it closes toward negative values)
  return HandScene<models::human_hand>(
      hand, q, cylinder_object(hand, centre, Eigen::Vector3d::UnitY(), 0.02, 0.08, 0.3));
}

// The SDH closed on the bottle held still (uniform hold, then released): its three fingers'
// contact forces can balance.
HandScene<models::schunk_sdh> closed_sdh_bottle() {
  auto scene = test::sdh_bottle_scene();
  CloseOptions o;
  o.hold_object = true;
  REQUIRE(close_hand(scene, o).status == Status::success);
  return scene;
}

}  // namespace

TEST_CASE("closing each shipped hand on a cylinder stops every finger at contact",
          "[evaluation][close]") {
  SECTION("Schunk SDH") {
    Vec<7> q;
    q << 0.0, -0.6, 0.2, -0.6, 0.2, -0.6, 0.2;
    check_closing<models::schunk_sdh>(q, {0.0, 0.0, 0.16}, Eigen::Vector3d::UnitY(), 0.035, 3);
  }
  SECTION("human hand") {
    Vec<20> q = Vec<20>::Zero();
    q[17] = 0.3;  // thumb CMC2 opened (it closes toward negative values)
    // The first contacts are found, but this thin cylinder in front of the proximal phalanges,
    // with the thumb not opposing it at this pose, is swept out towards the wrist by the curling
    // fingers once their motors close them (as a real hand would lose it): no hold is checked.
    check_closing<models::human_hand>(q, {0.045, 0.0, 0.11}, Eigen::Vector3d::UnitY(), 0.02, 5,
                                      false);
  }
  SECTION("Barrett BH8") {
    const Vec<4> q = Vec<4>::Zero();
    check_closing<models::barrett_bh8>(q, {0.0, -0.02, 0.14}, Eigen::Vector3d::UnitX(), 0.03, 3);
  }
}

TEST_CASE("held closing: the object stays still while the fingers close, free it is swept",
          "[evaluation][close]") {
  // The human hand and the thin cylinder of the test above: the curling fingers sweep it out
  // when it is free; held, it does not move until it is released, and the record says so.
  const auto close = [&](bool held, int release_steps) {
    auto scene = human_cylinder_scene({0.045, 0.0, 0.11});
    CloseOptions o;
    o.hold_object = held;
    o.release_steps = release_steps;
    const auto r = close_hand(scene, o);
    REQUIRE(r.status == Status::success);
    CHECK_FALSE(scene.world().held(scene.object_body()));  // released in every case
    return r;
  };
  const auto free = close(false, 0);
  INFO("free: the object moved " << free.object_shift << " m");
  CHECK(free.object_shift > 0.01);
  const auto held = close(true, 0);
  CHECK(held.object_shift == 0.0);
  CHECK(held.object_turn == 0.0);
  CHECK(held.contacts >= 2);  // the fingers closed on it
  // Each contact point when closing ended: on a finger link (the palm is not near the cylinder),
  // a unit normal, pressing.
  REQUIRE(static_cast<int>(held.contact_points.size()) == held.contacts);
  double force = 0.0;
  for (const HandContact& c : held.contact_points) {
    INFO(c.link << " at " << c.point.transpose() << ", normal " << c.normal.transpose());
    CHECK(models::human_hand.find_link(c.link) >= 0);
    CHECK(c.link != "palm");
    CHECK(c.normal.norm() == Approx(1.0));
    CHECK(c.force >= 0.0);
    force += c.force;
  }
  CHECK(force > 1.0);
  CHECK(closing_record(held).contact_points.size() == held.contact_points.size());
  // Released for 0.25 s, the unbalanced fingers move it: the record measures that motion.
  const auto released = close(true, 15);
  CHECK(released.object_shift > 0.0);
}

TEST_CASE("a balanced hold keeps the released object where the fingers closed on it",
          "[evaluation][close]") {
  // A cylinder held while the human fingers close, released for 0.25 s: with every closing
  // joint pressing with its limit the unbalanced forces push it; with the torques of
  // balance_hold() it moves less, as far as the contacts let the forces balance.
  const auto close = [&](const Eigen::Vector3d& centre, bool balanced) {
    auto scene = human_cylinder_scene(centre);
    CloseOptions o;
    o.hold_object = true;
    o.release_steps = 15;
    o.balanced_hold = balanced;
    const auto r = close_hand(scene, o);
    REQUIRE(r.status == Status::success);
    return r;
  };
  SECTION("against the palm: the palm opposes the fingers, the forces balance") {
    const Eigen::Vector3d centre(0.03, 0.0, 0.07);
    const auto uniform = close(centre, false), balanced = close(centre, true);
    INFO("uniform: moved " << uniform.object_shift << " m, balanced: " << balanced.object_shift);
    CHECK_FALSE(uniform.balanced);
    for (int j = 0; j < 20; ++j)
      CHECK(uniform.hold_torque[j] == Approx(uniform_hold_loads<models::human_hand>(0.5)[j] *
                                             models::human_hand.joint_spec(j).effort));
    REQUIRE(balanced.balanced);
    CHECK(balanced.hold_imbalance < 0.01);
    // Less than half as far (measured 9 mm against 27): the stepper's contact forces for these
    // torques are not exactly the balanced ones, so the object still settles a little.
    CHECK(balanced.object_shift < 0.5 * uniform.object_shift);
    // The most loaded joint holds with hold_fraction of its limit, none with more.
    double most = 0.0;
    for (int j = 0; j < 20; ++j)
      most = std::max(most,
                      std::abs(balanced.hold_torque[j]) / models::human_hand.joint_spec(j).effort);
    CHECK(most == Approx(0.5));
    const ClosingRecord record = closing_record(balanced);
    CHECK(record.balanced);
    CHECK(record.hold_imbalance == balanced.hold_imbalance);
    REQUIRE(record.hold_torque.size() == 20);
    CHECK(record.hold_torque[1] == balanced.hold_torque[1]);
  }
  SECTION("across the fingers, no thumb opposing: the least imbalance, and it says so") {
    const Eigen::Vector3d centre(0.045, 0.0, 0.11);
    const auto uniform = close(centre, false), balanced = close(centre, true);
    INFO("uniform: moved " << uniform.object_shift << " m, balanced: " << balanced.object_shift);
    REQUIRE(balanced.balanced);
    CHECK(balanced.hold_imbalance > 0.1);
    CHECK(balanced.object_shift < 0.5 * uniform.object_shift);
  }
}

TEST_CASE("balance_hold: forces that balance on the object, scaled to the hold fraction",
          "[evaluation][close]") {
  // balance_hold() finds torques whose forces balance, at the asked fraction.
  auto scene = closed_sdh_bottle();
  REQUIRE(scene.hand_contacts() >= 3);
  for (const double fraction : {0.25, 1.0}) {
    const HoldBalance<7> b = balance_hold(scene, fraction);
    REQUIRE(b.found);
    CHECK(b.contacts == scene.hand_contacts());
    CHECK(b.imbalance < 0.01);
    CHECK(b.squeeze > 1.0);
    double most = 0.0;
    for (int j = 0; j < 7; ++j)
      most = std::max(most, std::abs(b.torque[j]) / models::schunk_sdh.joint_spec(j).effort);
    CHECK(most == Approx(fraction));
  }
  // Twice the fraction, twice the torques and the squeeze.
  const HoldBalance<7> half = balance_hold(scene, 0.5), full = balance_hold(scene, 1.0);
  CHECK(full.torque.isApprox(2.0 * half.torque));
  CHECK(full.squeeze == Approx(2.0 * half.squeeze));
  CHECK_THROWS_WITH(balance_hold(scene, 0.0), Catch::StartsWith("hold_fraction: "));
  CHECK_THROWS_WITH(balance_hold(scene, 1.5), Catch::StartsWith("hold_fraction: "));
  // A hand that touches nothing has nothing to balance.
  auto apart = test::sdh_bottle_scene();
  CHECK_FALSE(balance_hold(apart, 0.5).found);
}

TEST_CASE("load_squeeze: the squeeze a weight asks of two opposed contacts is weight / mu",
          "[evaluation][close]") {
  // Two contacts on either side of the centre of mass along x, friction mu, each a cone of 8
  // edges as balance_hold() builds it: a weight along y or z is held by friction alone, so the
  // two normal forces sum to weight / mu; along x one contact carries it, weight. The largest is
  // weight / mu.
  for (const double mu : {0.5, 1.0}) {
    Eigen::MatrixXd wrench(6, 2 * k_hold_cone_edges);
    const double r = 0.02, length = r;
    for (int i = 0; i < 2; ++i) {
      const Vec3 n = i == 0 ? Vec3::UnitX() : Vec3(-Vec3::UnitX());
      const Vec3 p = -r * n, t1 = n.unitOrthogonal(), t2 = n.cross(t1);
      for (int e = 0; e < k_hold_cone_edges; ++e) {
        const double a = 2.0 * std::numbers::pi * e / k_hold_cone_edges;
        const Vec3 f = n + mu * (std::cos(a) * t1 + std::sin(a) * t2);
        wrench.block<3, 1>(0, i * k_hold_cone_edges + e) = f;
        wrench.block<3, 1>(3, i * k_hold_cone_edges + e) = p.cross(f) / length;
      }
    }
    INFO("mu " << mu);
    CHECK(detail::load_squeeze(wrench, Mat3::Identity(), 3.0) == Approx(3.0 / mu).epsilon(1e-3));
    // The frame turned about x: the weight now pulls between two edges of each cone (the cone
    // of 8 edges reaches mu cos(22.5 degrees) there, not mu), so it asks a little more.
    const Mat3 turned = Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix();
    const double between = detail::load_squeeze(wrench, turned, 3.0);
    CHECK(between > 3.0 / mu * 1.001);
    CHECK(between <= 3.0 / (mu * std::cos(std::numbers::pi / 8.0)) * 1.001);
  }
  // One contact cannot hold a weight pulling it off: only the direction into it counts.
  Eigen::MatrixXd one(6, 1);
  one << 1, 0, 0, 0, 0, 0;
  CHECK(detail::load_squeeze(one, Mat3::Identity(), 2.0) == Approx(2.0));
}

TEST_CASE("a grip that follows the load: harder where the weight asks, up to max_grip",
          "[evaluation][close]") {
  auto scene = closed_sdh_bottle();
  const double fraction = 0.25;
  const HoldBalance<7> fixed = balance_hold(scene, fraction);
  REQUIRE(fixed.found);
  CHECK(fixed.grip == 1.0);
  CHECK(fixed.load_squeeze == 0.0);
  // max_grip 1 or no weight: the fixed grip, whatever the weight.
  for (const GripLoad g : {GripLoad{50.0, 0.4, 1.0}, GripLoad{0.0, 0.4, 5.0}}) {
    const HoldBalance<7> b = balance_hold(scene, fraction, g);
    CHECK(b.grip == 1.0);
    CHECK(b.torque.isApprox(fixed.torque));
  }
  // The squeeze a weight asks grows with it; the grip follows it from the fixed grip up to
  // max_grip, the torques scaled with it.
  const double light = balance_hold(scene, fraction, {1.0, 0.4, 5.0}).load_squeeze;
  REQUIRE(light > 0.0);
  for (const double weight : {1.0, 10.0, 40.0, 1000.0}) {
    const HoldBalance<7> b = balance_hold(scene, fraction, {weight, 0.4, 5.0});
    INFO("weight " << weight << " N: load squeeze " << b.load_squeeze << ", grip " << b.grip);
    CHECK(b.load_squeeze == Approx(weight * light).epsilon(1e-6));
    const double expected = std::clamp(1.4 * b.load_squeeze / fixed.squeeze, 1.0, 5.0);
    CHECK(b.grip == Approx(expected));
    CHECK(b.torque.isApprox(b.grip * fixed.torque));
    CHECK(b.squeeze == Approx(b.grip * fixed.squeeze));
  }
  CHECK(balance_hold(scene, fraction, {1000.0, 0.4, 5.0}).grip == 5.0);
  CHECK(balance_hold(scene, fraction, {1000.0, 0.4, 2.0}).grip == 2.0);
  CHECK_THROWS_WITH(balance_hold(scene, fraction, {-1.0, 0.4, 5.0}),
                    Catch::StartsWith("grip.weight: "));
  CHECK_THROWS_WITH(balance_hold(scene, fraction, {std::nan(""), 0.4, 5.0}),
                    Catch::StartsWith("grip.weight: "));
  CHECK_THROWS_WITH(balance_hold(scene, fraction, {1.0, -0.1, 5.0}),
                    Catch::StartsWith("grip.margin: "));
  CHECK_THROWS_WITH(balance_hold(scene, fraction, {1.0, 0.4, 0.5}),
                    Catch::StartsWith("grip.max_grip: "));
  CHECK_THROWS_WITH(balance_hold(scene, fraction, {1.0, 0.4, 11.0}),
                    Catch::StartsWith("grip.max_grip: "));
}

TEST_CASE("closing with a grip that follows the load: stronger, stiffer servos, recorded",
          "[evaluation][close]") {
  // The SDH on the 0.5 kg bottle, held at a twentieth of its limits: the bottle's weight asks
  // for more than that grip, and close_hand() grips up to max_grip times harder, its servos
  // given the torque and as much stiffer.
  const auto close = [](double max_grip) {
    auto scene = test::sdh_bottle_scene();
    CloseOptions o;
    o.hold_object = true;
    o.release_steps = 15;
    o.balanced_hold = true;
    o.hold_fraction = 0.05;
    o.max_grip = max_grip;
    const auto r = close_hand(scene, o);
    REQUIRE(r.status == Status::success);
    return std::pair{r, scene.effort_fraction()};
  };
  const auto [fixed, fixed_fraction] = close(1.0);
  REQUIRE(fixed.balanced);
  CHECK(fixed.grip == 1.0);
  CHECK(fixed.load_squeeze == 0.0);
  CHECK(fixed.hold_squeeze > 0.0);
  CHECK(fixed_fraction == 1.0);
  const auto [strong, strong_fraction] = close(8.0);
  REQUIRE(strong.balanced);
  INFO("load squeeze " << strong.load_squeeze << " N, grip " << strong.grip);
  CHECK(strong.load_squeeze > 0.0);
  CHECK(strong.grip > 1.0);
  CHECK(strong.grip <= 8.0);
  CHECK(strong.grip ==
        Approx(
            std::clamp(1.4 * strong.load_squeeze / (strong.hold_squeeze / strong.grip), 1.0, 8.0)));
  double most = 0.0;
  for (int j = 0; j < 7; ++j)
    most =
        std::max(most, std::abs(strong.hold_torque[j]) / models::schunk_sdh.joint_spec(j).effort);
  CHECK(most == Approx(0.05 * strong.grip));
  CHECK(strong_fraction == std::max(1.0, most));
  const ClosingRecord record = closing_record(strong);
  CHECK(record.grip == strong.grip);
  CHECK(record.load_squeeze == strong.load_squeeze);
  CHECK(record.hold_squeeze == strong.hold_squeeze);
  CloseOptions bad;
  bad.max_grip = 0.5;
  auto scene = test::sdh_bottle_scene();
  CHECK_THROWS_WITH(close_hand(scene, bad), Catch::Contains("max_grip"));
  bad.max_grip = 2.0;
  bad.grip_margin = -1.0;
  CHECK_THROWS_WITH(close_hand(scene, bad), Catch::Contains("grip_margin"));
}

TEST_CASE("an effort fraction above 1 gives the servos that much more torque and stiffness",
          "[evaluation][close]") {
  auto scene = test::sdh_bottle_scene();
  const double k = scene.servo_stiffness(1);
  CHECK(k == Approx(models::schunk_sdh.joint_spec(1).effort / scene.servo_reach(1)));
  scene.set_effort_fraction(0.5);  // a weaker motor, as stiff
  CHECK(scene.servo_stiffness(1) == k);
  CHECK(scene.effort_limit(1) == Approx(0.5 * models::schunk_sdh.joint_spec(1).effort));
  scene.set_effort_fraction(3.0);  // a stronger grip, three times as stiff
  CHECK(scene.servo_stiffness(1) == Approx(3.0 * k));
  CHECK(scene.effort_limit(1) == Approx(3.0 * models::schunk_sdh.joint_spec(1).effort));
  // hold_targets() puts each target where the stiffer servo gives the asked torque.
  Vec<7> load = Vec<7>::Zero();
  load[1] = 2.0;
  const Vec<7> q = scene.joint_positions();
  CHECK((hold_targets(scene, q, load)[1] - q[1]) * scene.servo_stiffness(1) ==
        Approx(2.0 * models::schunk_sdh.joint_spec(1).effort));
  CHECK_THROWS_WITH(scene.set_effort_fraction(10.5), Catch::StartsWith("fraction: "));
  CHECK_THROWS_WITH(scene.set_effort_fraction(0.0), Catch::StartsWith("fraction: "));
}

TEST_CASE("closing proximal first wraps the fingers: the knuckle, then the middle joint",
          "[evaluation][close]") {
  // A thin cylinder held against the palm: closing every joint at once, each finger meets it
  // with its tip alone; knuckle first, the knuckles close over it and the middle phalanges
  // come down on it as well.
  const auto close = [&](bool proximal_first) {
    auto scene = human_cylinder_scene({0.03, 0.0, 0.07});
    CloseOptions o;
    o.hold_object = true;
    o.proximal_first = proximal_first;
    const auto r = close_hand(scene, o);
    REQUIRE(r.status == Status::success);
    return r;
  };
  const auto all_at_once = close(false), wrapped = close(true);
  const auto touches = [](const CloseResult<20>& r, const std::string& link) {
    for (const HandContact& c : r.contact_points)
      if (c.link == link) return true;
    return false;
  };
  int middle_all_at_once = 0, middle_wrapped = 0;
  for (const char* finger : {"index", "middle", "ring", "pinky"}) {
    const std::string f = finger;
    INFO(f);
    middle_all_at_once += touches(all_at_once, f + "_pip") ? 1 : 0;
    middle_wrapped += touches(wrapped, f + "_pip") ? 1 : 0;
    CHECK(touches(all_at_once, f + "_dip"));
    CHECK(touches(wrapped, f + "_dip"));
    // The knuckle closed before the joints after it moved, and so further.
    const int mcp = models::human_hand.find_joint(f + "_mcp");
    CHECK(wrapped.q_contact[mcp] > all_at_once.q_contact[mcp] + 0.3);
  }
  CHECK(middle_all_at_once == 0);
  CHECK(middle_wrapped >= 3);
}

TEST_CASE("the grip comes from the motors, not from the pads' stiffness", "[evaluation][close]") {
  // The SDH holding a bottle: the normal force scales with the motors' torque limit and hardly
  // depends on the finger pads' contact stiffness (which only sets how far they give).
  const auto grip = [](double hold_fraction, double stiffness) {
    auto scene = test::sdh_bottle_scene(1.0, stiffness);
    CloseOptions o;
    o.hold_fraction = hold_fraction;
    REQUIRE(close_hand(scene, o).status == Status::success);
    return scene.hand_force();
  };
  const double base = grip(0.5, 8000.0);
  INFO("normal force at half the torque limit, 8000 N/m pads: " << base << " N");
  // (Not exactly half: the fingers settle at other angles.)
  CHECK(grip(0.25, 8000.0) == Approx(0.5 * base).epsilon(0.3));
  CHECK(grip(0.5, 32000.0) == Approx(base).epsilon(0.15));
  // (Soft 2000 N/m pads sink about 1 cm under these forces, which moves the contacts: the force
  // then differs by a third, not because the pads set it.)
}

TEST_CASE("a firm SDH grasp passes the stability suite and a slippery one fails it",
          "[evaluation][stability]") {
  StabilityOptions o;
  o.hard_shake.steps = 0;  // a stress, not part of the verdict; the cage tests run it
  SECTION("mu = 1 holds") {
    auto scene = test::sdh_bottle_scene(1.0);
    REQUIRE(close_hand(scene).status == Status::success);
    const Eigen::Isometry3d before = scene.object_pose();
    const StabilityResult r = stability_suite(scene, o);
    CHECK(r.stable);
    CHECK(r.reason.empty());
    for (std::size_t i = 0; i + 1 < k_stability_tests; ++i) {
      const StabilityRecord& t = r.tests[i];
      INFO(t.name << ": " << t.reason);
      CHECK(t.passed);
      CHECK(t.status == Status::success);
      CHECK(t.contacts > 0);
      CHECK(t.translation < 0.02);
      CHECK(t.rotation < deg(15));
      CHECK(t.force_median > 0.0);
      CHECK(t.force_ratio == Approx(t.force_median / r.weight));
    }
    CHECK(r.shake().steps == 100);
    CHECK(scene.object_pose().isApprox(before, 0.0));  // the suite works on copies
  }
  SECTION("mu = 0.05 drops the bottle") {
    auto scene = test::sdh_bottle_scene(0.05);
    REQUIRE(close_hand(scene).status == Status::success);
    const StabilityResult r = stability_suite(scene, o);
    CHECK_FALSE(r.stable);
    CHECK_FALSE(r.reason.empty());
    CHECK_FALSE(r.shake().passed);
    CHECK(r.shake().translation > 0.02);
  }
}

TEST_CASE("bad input to the scene and the tests throws naming the argument",
          "[evaluation][input]") {
  const Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  const Vec<7> q = Vec<7>::Zero();
  ObjectSpec good = cylinder_object(hand, {0, 0, 0.16}, Eigen::Vector3d::UnitY(), 0.03, 0.05, 0.2);
  test::check_throws_naming(
      [&] {
        ObjectSpec o = good;
        o.mass = -1.0;
        HandScene<models::schunk_sdh> s(hand, q, o);
      },
      "object.mass");
  test::check_throws_naming(
      [&] {
        ObjectSpec o = good;
        o.mass = 0.0;
        HandScene<models::schunk_sdh> s(hand, q, o);
      },
      "object.density");
  test::check_throws_naming(
      [&] {
        ObjectSpec o = good;
        o.shapes[0].size[0] = 0.0;
        HandScene<models::schunk_sdh> s(hand, q, o);
      },
      "object.shapes[0].size[0]");
  test::check_throws_naming(
      [&] {
        ObjectSpec o = good;
        o.shapes.clear();
        HandScene<models::schunk_sdh> s(hand, q, o);
      },
      "object.shapes");
  test::check_throws_naming(
      [&] {
        ObjectSpec o = good;
        o.pose.p[1] = std::nan("");
        HandScene<models::schunk_sdh> s(hand, q, o);
      },
      "object.pose");
  test::check_throws_naming(
      [&] {
        Vec<7> bad = q;
        bad[3] = std::nan("");
        HandScene<models::schunk_sdh> s(hand, bad, good);
      },
      "q");
  test::check_throws_naming(
      [&] {
        Eigen::Isometry3d h = hand;
        h.translation().x() = std::numeric_limits<double>::infinity();
        HandScene<models::schunk_sdh> s(h, q, good);
      },
      "hand_pose");
  test::check_throws_naming(
      [&] {
        HandScene<models::schunk_sdh> s(hand, q, good);
        StabilityOptions o;
        o.shake.rotations = 0;
        (void)stability_suite(s, o);
      },
      "options.shake.rotations");
  test::check_throws_naming(
      [&] {
        HandSceneOptions so;
        so.stepper.time_step = 0.0;
        HandScene<models::schunk_sdh> s(hand, q, good, so);
      },
      "options.time_step");
}

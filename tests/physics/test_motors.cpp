// SPDX-License-Identifier: BSD-3-Clause
// Motor oracles: joint-space actuators with torque-limited servos. A finger cannot hold a weight
// whose torque exceeds its limit and holds one below it; a motor commanded past an object stalls
// on it, pressing with its limit; limits and speed limits hold; bad input is refused.
#include "physics_test_support.hpp"

#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "support/throws.hpp"

using namespace topograsp;

namespace {

using test::g;
constexpr double length = 0.1;      // the finger link's length (m)
constexpr double thick = 0.005;     // the link's half thickness (m)
constexpr double box_half = 0.015;  // the held box's half extent (m)
constexpr double box_mass = 0.2;    // kg
constexpr double lever = 0.07;      // where the box rests on the link, from the joint axis (m)

// A horizontal finger: a box link along +x from a revolute joint about y at the origin, driven
// by actuator 0, and body 0 the link. Positive rotation about y turns +x down (towards -z).
struct Finger {
  World<double> w;
  int link = -1, actuator = -1;
  explicit Finger(double max_effort, const StepperOptions& options = {}) : w(options) {
    static const std::array<ShapeSpec, 1> shape{
        box("", at(0.5 * length, 0.0, 0.0), {0.5 * length, 0.02, thick})};
    BodyDesc d;
    d.type = BodyType::kinematic;
    d.shapes = shape;
    d.friction = 1.0;
    link = w.add_body(d);
    ActuatorDesc a;
    a.lower = -1.0;
    a.upper = 1.0;
    a.inertia = 1e-4;
    a.max_effort = max_effort;
    a.max_velocity = 2.0;
    actuator = w.add_actuator(a);
  }
  [[nodiscard]] double q() const { return w.actuator(actuator).q; }
  // One step: the link carried by the joint at its position; placed where it went.
  Status step() {
    const double q0 = q();
    const BodyJoint j{actuator, Eigen::Vector3d::UnitY(), Eigen::Vector3d::Zero(), 1.0, false};
    w.set_target(link, pose(q0));
    w.set_body_joints(link, std::span<const BodyJoint>(&j, 1));
    const Status s = w.step();
    w.move_kinematic(link, pose(q()));
    return s;
  }
  static Eigen::Isometry3d pose(double angle) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
    return T;
  }
};

// A box of `box_mass` resting on the finger at `lever` from the axis.
int add_box(World<double>& w, double x) {
  static const std::array<ShapeSpec, 1> shape{box("", Pose{}, {box_half, box_half, box_half})};
  BodyDesc d;
  d.pose = at(x, 0.0, thick + box_half);
  d.shapes = shape;
  d.mass = box_mass;
  d.friction = 1.0;
  return w.add_body(d);
}

}  // namespace

TEST_CASE("A finger holds a weight below its torque limit and drops one above it", "[motors]") {
  const double load = box_mass * g * lever;  // the weight's torque about the joint (N m)
  for (const double ratio : {0.7, 1.4}) {
    Finger f(ratio * load);
    const int b = add_box(f.w, lever);
    double lowest = 0.0;  // the finger's largest downward turn (rad)
    for (int k = 0; k < 120; ++k) {
      REQUIRE(f.step() == Status::success);
      lowest = std::max(lowest, f.q());
    }
    INFO("effort / load torque " << ratio << ", finger at " << f.q() << " rad, at most " << lowest);
    if (ratio < 1.0) {
      // The finger gives way: it turns down to its limit and the box falls off (then the
      // servo brings the empty finger back).
      CHECK(lowest > 0.9);
      CHECK(f.w.body(b).x.z() < -0.03);
    } else {
      // It holds level, the motor giving the weight's torque (not its limit).
      CHECK(std::abs(f.q()) < 0.01);
      CHECK(lowest < 0.03);  // the load arriving dips it by under 2 degrees
      CHECK(f.w.body(b).x.z() > thick);
      CHECK(f.w.actuator_torque(f.actuator) == Approx(-load).epsilon(0.1));
    }
  }
}

TEST_CASE("A motor commanded past an object stalls on it, pressing with its limit", "[motors]") {
  // Gravity off; the finger turns up (negative angle) into a heavy box above it.
  StepperOptions o;
  o.gravity = {0.0, 0.0, 0.0};
  const double effort = 0.5;
  Finger h(effort, o);
  static const std::array<ShapeSpec, 1> block{box("", Pose{}, {0.1, 0.1, 0.05})};
  BodyDesc d;
  d.pose = at(0.05, 0.0, thick + 0.05 + 0.002);
  d.shapes = block;
  d.mass = 1e5;  // it does not move under the finger's 5 N
  const int b = h.w.add_body(d);
  h.w.set_actuator_target(h.actuator, -1.0);
  for (int k = 0; k < 60; ++k) REQUIRE(h.step() == Status::success);
  INFO("finger at " << h.q() << " rad");
  // Stalled short of its target, at the contact.
  CHECK(h.q() > -0.1);
  CHECK(std::abs(h.w.actuator(h.actuator).qd) < 0.05);
  // The motor gives its limit, and the contact force balances it: sum of F r = effort.
  CHECK(h.w.actuator_torque(h.actuator) == Approx(-effort).epsilon(0.02));
  double moment = 0.0;
  for (const Manifold<double>& m : h.w.manifolds())
    for (int k = 0; k < m.count; ++k)
      moment += m.points[static_cast<std::size_t>(k)].step_impulse *
                m.points[static_cast<std::size_t>(k)].point.x();
  CHECK(moment / o.time_step == Approx(effort).epsilon(0.07));  // points as levers: approximate
  CHECK(h.w.body(b).x.z() > 0.05);
}

TEST_CASE("A free joint moves at its speed limit and stops at its joint limit", "[motors]") {
  StepperOptions o;
  o.gravity = {0.0, 0.0, 0.0};
  World<double> w(o);
  ActuatorDesc a;
  a.lower = -0.5;
  a.upper = 0.6;
  a.inertia = 1e-4;
  a.max_effort = 1.0;
  a.max_velocity = 1.5;
  const int i = w.add_actuator(a);
  w.set_actuator_target(i, 3.0);  // beyond the upper limit
  for (int k = 0; k < 12; ++k) REQUIRE(w.step() == Status::success);
  // 0.2 s at 1.5 rad/s (after a short acceleration at 1 N m / 1e-4 kg m^2).
  CHECK(w.actuator(i).q == Approx(0.3).margin(0.01));
  for (int k = 0; k < 60; ++k) REQUIRE(w.step() == Status::success);
  CHECK(w.actuator(i).q == Approx(0.6).margin(1e-3));
  // A reachable target inside the range is reached.
  w.set_actuator_target(i, -0.2);
  for (int k = 0; k < 60; ++k) REQUIRE(w.step() == Status::success);
  CHECK(w.actuator(i).q == Approx(-0.2).margin(1e-3));
}

TEST_CASE("Actuators refuse bad input, naming it", "[motors][input]") {
  World<double> w;
  ActuatorDesc good;
  good.lower = -1.0;
  good.upper = 1.0;
  const auto with = [&](auto change) {
    ActuatorDesc d = good;
    change(d);
    return d;
  };
  test::check_throws_naming([&] { w.add_actuator(with([](ActuatorDesc& d) { d.lower = 2.0; })); },
                            "desc.lower");
  test::check_throws_naming(
      [&] { w.add_actuator(with([](ActuatorDesc& d) { d.position = 1.5; })); }, "desc.position");
  test::check_throws_naming([&] { w.add_actuator(with([](ActuatorDesc& d) { d.inertia = 0.0; })); },
                            "desc.inertia");
  test::check_throws_naming(
      [&] { w.add_actuator(with([](ActuatorDesc& d) { d.max_effort = -1.0; })); },
      "desc.max_effort");
  test::check_throws_naming(
      [&] { w.add_actuator(with([](ActuatorDesc& d) { d.max_velocity = std::nan(""); })); },
      "desc.max_velocity");
  test::check_throws_naming(
      [&] { w.add_actuator(with([](ActuatorDesc& d) { d.max_velocity = 1e9; })); },
      "desc.max_velocity");
  test::check_throws_naming(
      [&] { w.add_actuator(with([](ActuatorDesc& d) { d.stiffness = 0.0; })); }, "desc.stiffness");
  test::check_throws_naming(
      [&] { w.add_actuator(with([](ActuatorDesc& d) { d.damping_time = -1.0; })); },
      "desc.damping_time");
  const int a = w.add_actuator(good);
  test::check_throws_naming([&] { w.set_actuator_target(a + 1, 0.0); }, "a");
  test::check_throws_naming(
      [&] { w.set_actuator_target(a, std::numeric_limits<double>::infinity()); }, "target");
  test::check_throws_naming([&] { w.set_actuator_max_effort(a, 0.0); }, "max_effort");
  test::check_throws_naming([&] { w.set_actuator_inertia(a, -1.0); }, "inertia");
  test::check_throws_naming([&] { w.set_actuator_gains(a, 0.0, 0.01); }, "stiffness");
  test::check_throws_naming([&] { w.set_actuator_gains(a, std::nan(""), 0.01); }, "stiffness");
  test::check_throws_naming([&] { w.set_actuator_gains(a, 10.0, -0.01); }, "damping_time");
  test::check_throws_naming([&] { w.set_actuator_gains(a + 1, 10.0, 0.01); }, "a");
  test::check_throws_naming([&] { w.set_actuator_force(a, std::nan("")); }, "force");
  test::check_throws_naming([&] { w.set_actuator_position(a, 1.5); }, "position");
  static const std::array<ShapeSpec, 1> shape{sphere("", {0, 0, 0}, 0.01)};
  BodyDesc dynamic;
  dynamic.shapes = shape;
  dynamic.mass = 1.0;
  const int body = w.add_body(dynamic);
  const BodyJoint j{a, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero(), 1.0, false};
  test::check_throws_naming([&] { w.set_body_joints(body, std::span<const BodyJoint>(&j, 1)); },
                            "body");
  BodyDesc kin = dynamic;
  kin.type = BodyType::kinematic;
  const int k = w.add_body(kin);
  BodyJoint bad = j;
  bad.axis = Eigen::Vector3d(1.0, 1.0, 0.0);
  test::check_throws_naming([&] { w.set_body_joints(k, std::span<const BodyJoint>(&bad, 1)); },
                            "joints[0].axis");
  bad = j;
  bad.actuator = 7;
  test::check_throws_naming([&] { w.set_body_joints(k, std::span<const BodyJoint>(&bad, 1)); },
                            "joints[0].actuator");
  std::array<BodyJoint, k_max_body_joints + 1> many;
  many.fill(j);
  test::check_throws_naming([&] { w.set_body_joints(k, many); }, "joints");
  test::check_throws_naming([&] { w.move_kinematic(body, Eigen::Isometry3d::Identity()); }, "body");
}

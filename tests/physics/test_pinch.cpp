// SPDX-License-Identifier: BSD-3-Clause
// Pinch oracles: two kinematic plates hold a box iff friction covers its load, at rest and when
// rotated; torsional friction; determinism; a failing run ends with a status.
#include "physics_test_support.hpp"

#include <cmath>
#include <cstring>

#include <catch2/catch.hpp>

using namespace topograsp;

namespace {

using test::g;
constexpr double held_half = 0.03;  // the held box's half extent (m)
constexpr double held_mass = 0.2;   // kg
constexpr double overlap = 0.002;   // each plate's overlap with the box (m)

// A pinch: plates at x = -+(held_half + 0.01 - overlap) around a box (or sphere) at the origin of
// `frame`; bodies 0 and 1 are the plates, 2 the held body.
struct Pinch {
  World<double> w;
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  explicit Pinch(double mu, const StepperOptions& o = {}, bool sphere_body = false,
                 const Eigen::Isometry3d& at_frame = Eigen::Isometry3d::Identity())
      : w(o), frame(at_frame) {
    static const std::array<ShapeSpec, 1> plate{box("", Pose{}, {0.01, 0.05, 0.05})};
    for (int side = 0; side < 2; ++side) {
      BodyDesc d;
      d.type = BodyType::kinematic;
      d.pose = to_pose(plate_pose(side, frame));
      d.shapes = plate;
      d.friction = mu;
      w.add_body(d);
    }
    static std::array<ShapeSpec, 1> held;
    held[0] = sphere_body ? sphere("", {0, 0, 0}, held_half)
                          : box("", Pose{}, {held_half, held_half, held_half});
    BodyDesc d;
    d.pose = to_pose(frame);
    d.shapes = held;
    d.mass = held_mass;
    d.friction = mu;
    w.add_body(d);
  }
  static Eigen::Isometry3d plate_pose(int side, const Eigen::Isometry3d& f) {
    const double x = (held_half + 0.01 - overlap) * (side == 0 ? -1.0 : 1.0);
    return f * Eigen::Translation3d(x, 0.0, 0.0);
  }
  // Moves the pinch frame (the plates follow in one step).
  Status step(const Eigen::Isometry3d& f) {
    frame = f;
    for (int side = 0; side < 2; ++side) w.set_target(side, plate_pose(side, f));
    return w.step();
  }
  Status step() { return step(frame); }
  // The squeeze force of one plate (N) over the last step.
  double force() const { return w.normal_impulse(0, 2) / w.options().time_step; }
  // The held body's position in the pinch frame.
  Eigen::Vector3d held_in_frame() const { return frame.inverse() * w.body(2).x; }
};

// The squeeze force, measured with ample friction.
double measured_force() {
  Pinch p(2.0);
  for (int i = 0; i < 60; ++i) REQUIRE(p.step() == Status::success);
  return p.force();
}

}  // namespace

TEST_CASE("the squeeze force is the hand stiffness times the overlap", "[physics][oracle][pinch]") {
  const double F = measured_force();
  CHECK(F == Approx(StepperOptions{}.kinematic_stiffness * overlap).epsilon(0.02));
}

TEST_CASE("a pinch holds a box iff 2 mu F >= m g", "[physics][oracle][pinch]") {
  const double F = measured_force();
  const double mu_edge = held_mass * g / (2.0 * F);
  const auto drop = [&](double mu) {
    Pinch p(mu);
    for (int i = 0; i < 60; ++i) REQUIRE(p.step() == Status::success);
    const double z0 = p.w.body(2).x.z();
    for (int i = 0; i < 30; ++i) REQUIRE(p.step() == Status::success);
    return z0 - p.w.body(2).x.z();
  };
  CHECK(drop(1.1 * mu_edge) < 2e-4);
  // Below the boundary it slides at a = g - 2 mu F / m = 0.1 g: 0.12 m in 0.5 s.
  CHECK(drop(0.9 * mu_edge) > 0.05);
}

TEST_CASE("a rotated pinch holds iff friction covers gravity plus the centripetal load",
          "[physics][oracle][pinch]") {
  const double F = measured_force();
  // The pinch turns about the world z axis at radius r; at omega^2 r = g the friction must carry
  // m sqrt(g^2 + (omega^2 r)^2) = m g sqrt(2) in the plates' plane.
  const double r = 0.2, omega = std::sqrt(g / r), ramp = 0.5;
  const double mu_edge = held_mass * g * std::sqrt(2.0) / (2.0 * F);
  const auto slip = [&](double mu) {
    const Eigen::Isometry3d start(Eigen::Translation3d(0.0, r, 0.0));
    Pinch p(mu, StepperOptions{}, false, start);
    for (int i = 0; i < 30; ++i) REQUIRE(p.step() == Status::success);
    const Eigen::Vector3d x0 = p.held_in_frame();
    const double dt = p.w.options().time_step;
    for (int i = 1; i <= 120; ++i) {
      // omega(t) = omega (1 - cos(pi t / ramp)) / 2 up to ramp, then omega; theta its integral.
      const double t = i * dt;
      const double theta = t < ramp ? 0.5 * omega * (t - ramp / pi * std::sin(pi * t / ramp))
                                    : 0.5 * omega * ramp + omega * (t - ramp);
      REQUIRE(p.step(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()) * start) ==
              Status::success);
    }
    return (p.held_in_frame() - x0).norm();
  };
  CHECK(slip(1.1 * mu_edge) < 3e-3);
  CHECK(slip(0.9 * mu_edge) > 2e-2);
}

TEST_CASE("torsional friction slows a pinched spinning sphere at mu r F", "[physics][oracle]") {
  StepperOptions o;
  o.gravity = {0.0, 0.0, 0.0};
  const double mu = 0.2;
  Pinch p(mu, o, true);
  for (int i = 0; i < 30; ++i) REQUIRE(p.step() == Status::success);
  p.w.set_velocity(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(20.0, 0.0, 0.0));
  REQUIRE(p.step() == Status::success);
  const double w0 = p.w.body(2).w.x();
  const double F = p.force();
  const int n = 5;
  for (int i = 0; i < n; ++i) REQUIRE(p.step() == Status::success);
  const double inertia = 0.4 * held_mass * held_half * held_half;
  const double alpha = 2.0 * mu * o.torsional_friction_radius * F / inertia;
  CHECK((w0 - p.w.body(2).w.x()) / (n * o.time_step) == Approx(alpha).epsilon(0.05));
  SECTION("without it, nothing stops the spin about the contact normal") {
    o.torsional_friction_radius = 0.0;
    Pinch q(mu, o, true);
    for (int i = 0; i < 30; ++i) REQUIRE(q.step() == Status::success);
    q.w.set_velocity(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(20.0, 0.0, 0.0));
    for (int i = 0; i < 30; ++i) REQUIRE(q.step() == Status::success);
    CHECK(q.w.body(2).w.x() == Approx(20.0).epsilon(1e-3));
  }
}

TEST_CASE("two runs give bitwise identical states", "[physics][determinism]") {
  const auto run = [] {
    Pinch p(0.8);
    std::array<double, 13> state{};
    for (int i = 1; i <= 90; ++i)
      REQUIRE(p.step(Eigen::Isometry3d(Eigen::AngleAxisd(0.01 * i, Eigen::Vector3d::UnitX()))) ==
              Status::success);
    const auto& b = p.w.body(2);
    std::memcpy(state.data(), b.x.data(), 3 * sizeof(double));
    std::memcpy(state.data() + 3, b.v.data(), 3 * sizeof(double));
    std::memcpy(state.data() + 6, b.w.data(), 3 * sizeof(double));
    std::memcpy(state.data() + 9, b.q.coeffs().data(), 4 * sizeof(double));
    return state;
  };
  const auto a = run(), b = run();
  CHECK(std::memcmp(a.data(), b.data(), sizeof(a)) == 0);
}

TEST_CASE("an exploding state ends the run with a status and finite numbers", "[physics][input]") {
  // Gravity of 1e300 is refused up front now (the step could not catch the fall); a max_speed
  // below what gravity reaches in a few steps makes the state "explode" instead.
  StepperOptions huge;
  huge.gravity = {0.0, 0.0, -1e300};
  CHECK_THROWS_AS(Pinch(1.0, huge), invalid_argument);
  StepperOptions o;
  o.max_speed = 0.2;
  Pinch p(0.0, o);  // frictionless: the body slips out and falls
  Status s = Status::success;
  for (int i = 0; i < 5 && s == Status::success; ++i) s = p.step();
  CHECK(s == Status::numerical_issue);
  CHECK(p.w.status() == Status::numerical_issue);
  CHECK(p.w.body(2).x.allFinite());
  CHECK(p.w.body(2).v.allFinite());
  // The undone step's contacts are discarded (their impulses may be what went non-finite: fuzz
  // regression stepper/float_nan_impulse_after_undone_step).
  for (const Manifold<double>& m : p.w.manifolds()) CHECK(m.count == 0);
  CHECK(p.step() == Status::numerical_issue);  // and it stays ended
}

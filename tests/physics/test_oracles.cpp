// SPDX-License-Identifier: BSD-3-Clause
// The analytic oracles of docs/stepper.md: free fall, a resting box, sliding and spinning friction,
// an incline, a stack, energy on a frictionless incline.
#include "physics_test_support.hpp"

#include <array>
#include <cmath>
#include <cstring>

#include <catch2/catch.hpp>

using namespace topograsp;

namespace {

using test::g;

// A large fixed box whose top face is the plane z = 0 (rotated by pitch about y through the
// origin).
int add_ground(World<double>& w, double pitch = 0.0, double friction = 0.5) {
  static const std::array<ShapeSpec, 1> ground{box("", at(0, 0, -0.5), {20.0, 20.0, 0.5})};
  BodyDesc d;
  d.type = BodyType::fixed;
  d.pose = rotation_rpy(0.0, pitch, 0.0);
  d.shapes = ground;
  d.friction = friction;
  return w.add_body(d);
}

// A dynamic box with half extents h resting on the plane z = 0 of a frame rotated by pitch.
int add_box(World<double>& w, std::array<double, 3> h, double mass, double friction,
            double pitch = 0.0, double z = 0.0) {
  static std::array<ShapeSpec, 1> shape;
  shape[0] = box("", Pose{}, h);
  BodyDesc d;
  d.pose = rotation_rpy(0.0, pitch, 0.0) * at(0.0, 0.0, h[2] + z);
  d.shapes = shape;
  d.mass = mass;
  d.friction = friction;
  return w.add_body(d);
}

}  // namespace

TEST_CASE("free fall follows semi-implicit Euler exactly", "[physics][oracle]") {
  StepperOptions o;
  o.substeps = GENERATE(1, 4);
  World<double> w(o);
  static const std::array<ShapeSpec, 1> ball{sphere("", {0, 0, 0}, 0.05)};
  BodyDesc d;
  d.pose = at(0.1, -0.2, 3.0);
  d.shapes = ball;
  d.mass = 0.3;
  const int b = w.add_body(d);
  w.set_velocity(b, Eigen::Vector3d(0.5, 0.0, 2.0), Eigen::Vector3d::Zero());
  const double h = o.time_step / o.substeps;
  Eigen::Vector3d x(0.1, -0.2, 3.0), v(0.5, 0.0, 2.0);
  const Eigen::Vector3d gv(0.0, 0.0, -g);
  for (int step = 1; step <= 60; ++step) {
    REQUIRE(w.step() == Status::success);
    for (int s = 0; s < o.substeps; ++s) {
      v = v + h * gv;
      x += h * v;
    }
    REQUIRE(w.body(b).x == x);  // bitwise: the same operations in the same order
    REQUIRE(w.body(b).v == v);
    // Closed form after k sub-steps: v = v0 + k h g, x = x0 + k h v0 + h^2 g k (k + 1) / 2.
    const double k = step * o.substeps;
    CHECK(w.body(b).v.z() == Approx(2.0 - k * h * g).epsilon(1e-12));
    CHECK(w.body(b).x.z() ==
          Approx(3.0 + k * h * 2.0 - h * h * g * k * (k + 1) / 2).epsilon(1e-12));
  }
}

TEST_CASE("a box resting on the ground stays put and carries its weight", "[physics][oracle]") {
  World<double> w;
  add_ground(w);
  const double m = 2.0;
  const int b = add_box(w, {0.1, 0.15, 0.05}, m, 0.5);
  const Eigen::Vector3d x0 = w.body(b).x;
  const double dt = w.options().time_step;
  // The soft contact settles into an overlap of about g / (2 pi f)^2 (0.3 mm at 30 Hz) in 1 s...
  for (int i = 0; i < 60; ++i) REQUIRE(w.step() == Status::success);
  CHECK((w.body(b).x - x0).norm() < 1e-3);
  CHECK(std::abs(w.body(b).x.x() - x0.x()) + std::abs(w.body(b).x.y() - x0.y()) < 1e-5);
  // ... and then stays put for 10 s, carrying m g dt per step.
  const Eigen::Vector3d x1 = w.body(b).x;
  for (int i = 0; i < 600; ++i) {
    REQUIRE(w.step() == Status::success);
    CHECK(w.normal_impulse(0, b) == Approx(m * g * dt).epsilon(1e-6));
  }
  CHECK(w.kinetic_energy() < 1e-8);
  CHECK((w.body(b).x - x1).norm() < 1e-5);
  CHECK(w.contact_count(0, b) == 4);
}

TEST_CASE("a sliding box decelerates at mu g in 12 headings without spinning",
          "[physics][oracle]") {
  const double mu = 0.4, v0 = 2.0;
  for (int k = 0; k < 12; ++k) {
    const double heading = k * two_pi / 12.0;
    World<double> w;
    add_ground(w, 0.0, mu);
    const int b = add_box(w, {0.1, 0.1, 0.05}, 1.0, mu);
    // Settle first, then launch.
    for (int i = 0; i < 10; ++i) REQUIRE(w.step() == Status::success);
    const Eigen::Vector3d dir(std::cos(heading), std::sin(heading), 0.0);
    w.set_velocity(b, v0 * dir, Eigen::Vector3d::Zero());
    const int n = 20;  // 1/3 s: v drops by mu g t = 1.31 m/s
    for (int i = 0; i < n; ++i) REQUIRE(w.step() == Status::success);
    const double t = n * w.options().time_step;
    const double a = (v0 - w.body(b).v.dot(dir)) / t;
    INFO("heading " << k);
    CHECK(a == Approx(mu * g).epsilon(0.02));
    CHECK(std::abs(w.body(b).v.dot(Eigen::Vector3d(-dir.y(), dir.x(), 0.0))) < 1e-3);
    CHECK(w.body(b).w.norm() < 1e-2);
  }
}

TEST_CASE("a box on a 30 degree incline holds above mu = tan(theta) and slides below it",
          "[physics][oracle]") {
  const double theta = deg(30.0);
  SECTION("mu = 1.1 tan(theta) holds") {
    const double mu = 1.1 * std::tan(theta);
    World<double> w;
    add_ground(w, theta, mu);
    const int b = add_box(w, {0.1, 0.1, 0.05}, 1.0, mu, theta);
    for (int i = 0; i < 30; ++i) REQUIRE(w.step() == Status::success);
    const Eigen::Vector3d x0 = w.body(b).x;
    for (int i = 0; i < 120; ++i) REQUIRE(w.step() == Status::success);
    CHECK((w.body(b).x - x0).norm() < 1e-4);
  }
  SECTION("mu = 0.9 tan(theta) slides at g (sin - mu cos)") {
    const double mu = 0.9 * std::tan(theta);
    World<double> w;
    add_ground(w, theta, mu);
    const int b = add_box(w, {0.1, 0.1, 0.05}, 1.0, mu, theta);
    const Eigen::Vector3d down(std::cos(theta), 0.0, -std::sin(theta));
    for (int i = 0; i < 15; ++i) REQUIRE(w.step() == Status::success);
    const double v0 = w.body(b).v.dot(down);
    const int n = 60;
    for (int i = 0; i < n; ++i) REQUIRE(w.step() == Status::success);
    const double a = (w.body(b).v.dot(down) - v0) / (n * w.options().time_step);
    CHECK(a == Approx(g * (std::sin(theta) - mu * std::cos(theta))).epsilon(0.03));
  }
}

TEST_CASE("a spinning box slows down with the torque friction predicts", "[physics][oracle]") {
  const double mu = 0.1, a = 0.2, m = 1.0;
  World<double> w;
  add_ground(w, 0.0, mu);
  const int b = add_box(w, {a, a, 0.05}, m, mu);
  for (int i = 0; i < 10; ++i) REQUIRE(w.step() == Status::success);
  w.set_velocity(b, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 5.0));
  REQUIRE(w.step() == Status::success);
  const double w0 = w.body(b).w.z();
  const int n = 20;
  for (int i = 0; i < n; ++i) REQUIRE(w.step() == Status::success);
  // Four corner contacts carry m g / 4 each at a sqrt(2) from the axis: torque mu m g a sqrt(2);
  // I_z = m (2a)^2 2 / 12 = 2 m a^2 / 3.
  const double alpha = mu * m * g * a * std::sqrt(2.0) / (2.0 * m * a * a / 3.0);
  CHECK((w0 - w.body(b).w.z()) / (n * w.options().time_step) == Approx(alpha).epsilon(0.05));
  CHECK(w.body(b).v.norm() < 1e-3);
}

TEST_CASE("a stack of five boxes stands for 10 s", "[physics][oracle]") {
  World<double> w;
  add_ground(w, 0.0, 0.6);
  std::array<int, 5> ids{};
  for (int i = 0; i < 5; ++i)
    ids[static_cast<std::size_t>(i)] = add_box(w, {0.1, 0.1, 0.1}, 1.0, 0.6, 0.0, 0.2 * i);
  const Eigen::Vector3d top0 = w.body(ids[4]).x;
  // The soft contacts settle in about 2 s (each sinks by its load over its stiffness: some 7 mm
  // in all for the five), the Gauss-Seidel order shifting the top box by a few millimetres...
  for (int i = 0; i < 120; ++i) REQUIRE(w.step() == Status::success);
  const auto& top = w.body(ids[4]);
  CHECK(std::hypot(top.x.x() - top0.x(), top.x.y() - top0.y()) < 5e-3);
  CHECK(std::abs(top.x.z() - top0.z()) < 1e-2);
  // ... then nothing moves for 8 s.
  const Eigen::Vector3d top1 = top.x;
  for (int i = 0; i < 480; ++i) REQUIRE(w.step() == Status::success);
  CHECK((top.x - top1).norm() < 1e-5);
  for (int id : ids) CHECK(detail::rotation_angle<double>(w.body(id).R) < deg(0.5));
  CHECK(w.kinetic_energy() < 1e-10);
}

TEST_CASE("energy never grows on a frictionless incline", "[physics][oracle]") {
  const double theta = deg(30.0);
  World<double> w;
  add_ground(w, theta, 0.0);
  const int b = add_box(w, {0.1, 0.1, 0.05}, 1.0, 0.0, theta);
  const auto energy = [&] { return w.kinetic_energy() + w.body(b).mass * g * w.body(b).x.z(); };
  double e = energy();
  const double e0 = e;
  for (int i = 0; i < 120; ++i) {
    REQUIRE(w.step() == Status::success);
    const double next = energy();
    CHECK(next <= e + 1e-9);
    e = next;
  }
  // ... and it is not simply lost: the box slides at g sin(theta) (2 %).
  CHECK(w.body(b).v.norm() == Approx(g * std::sin(theta) * 2.0).epsilon(0.02));
  CHECK(e < e0);
}

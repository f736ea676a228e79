// SPDX-License-Identifier: BSD-3-Clause
// Bodies of several materials: per-shape densities (mass properties against a hand computation)
// and friction per pair of shapes (World::set_pair_friction).
#include "physics_test_support.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

using namespace topograsp;

namespace {

using test::g;

// Two cubes of side 0.1 m at x = -0.1 and x = +0.1.
const std::array<ShapeSpec, 2> two_cubes{box("", at(-0.1, 0, 0), {0.05, 0.05, 0.05}),
                                         box("", at(0.1, 0, 0), {0.05, 0.05, 0.05})};

}  // namespace

TEST_CASE("a body of two densities has the mass, centre and inertia a hand computation gives",
          "[physics][materials]") {
  // Cube volumes 1e-3 m^3: 1 kg of density 1000 at x = -0.1 and 3 kg of density 3000 at x = 0.1.
  // Total 4 kg, centre x = (-0.1 * 1 + 0.1 * 3) / 4 = 0.05. Own inertia of a cube: m s^2 / 6
  // (s = 0.1), about every axis; the offsets from the centre are -0.15 and +0.05 along x, so
  // Iyy = Izz = 4 * 0.01 / 6 + 1 * 0.15^2 + 3 * 0.05^2 = 0.0066667 + 0.03.
  const std::array<double, 2> rho{1000.0, 3000.0};
  const MassProperties<double> mp = body_mass_properties<double>(two_cubes, 0.0, 0.0, rho);
  CHECK(mp.mass == Approx(4.0).epsilon(1e-12));
  CHECK(mp.com.x() == Approx(0.05).epsilon(1e-12));
  CHECK(mp.com.y() == Approx(0.0).margin(1e-15));
  CHECK(mp.inertia(0, 0) == Approx(4.0 * 0.01 / 6.0).epsilon(1e-12));
  CHECK(mp.inertia(1, 1) == Approx(4.0 * 0.01 / 6.0 + 0.0225 + 0.0075).epsilon(1e-12));
  CHECK(mp.inertia(2, 2) == Approx(mp.inertia(1, 1)).epsilon(1e-12));
  CHECK(mp.inertia(0, 1) == Approx(0.0).margin(1e-15));
  // With a given total mass the densities share it out: the same centre, the inertia scaled.
  const MassProperties<double> m8 = body_mass_properties<double>(two_cubes, 8.0, 1.0, rho);
  CHECK(m8.mass == 8.0);
  CHECK(m8.com.x() == Approx(0.05).epsilon(1e-12));
  CHECK(m8.inertia(1, 1) == Approx(2.0 * mp.inertia(1, 1)).epsilon(1e-12));
  // Equal densities are the uniform body.
  const std::array<double, 2> same{700.0, 700.0};
  const MassProperties<double> u = body_mass_properties<double>(two_cubes, 0.0, 700.0);
  const MassProperties<double> s = body_mass_properties<double>(two_cubes, 0.0, 0.0, same);
  CHECK(s.mass == Approx(u.mass).epsilon(1e-12));
  CHECK(s.inertia.isApprox(u.inertia, 1e-12));
  // The World builds the same body from BodyDesc::shape_density.
  World<double> w;
  BodyDesc d;
  d.shapes = two_cubes;
  d.mass = 0.0;
  d.shape_density = rho;
  const int b = w.add_body(d);
  CHECK(w.body(b).mass == Approx(4.0).epsilon(1e-12));
  CHECK(w.body(b).local_com.x() == Approx(0.05).epsilon(1e-12));
}

TEST_CASE("a given inertial replaces the shapes' mass properties; one no body can have is refused",
          "[physics][materials][input]") {
  // A mesh object's boxes stand in for its surface; its mesh gives the mass properties.
  MassProperties<double> given;
  given.mass = 0.3;
  given.com = Vec3(0.02, -0.01, 0.05);
  given.inertia = Vec3(4e-4, 5e-4, 3e-4).asDiagonal();
  given.inertia(0, 1) = given.inertia(1, 0) = 1e-5;
  World<double> w;
  BodyDesc d;
  d.shapes = two_cubes;
  d.mass = 5.0;  // not used
  d.inertial = given;
  d.pose = at(1.0, 2.0, 3.0);
  const int b = w.add_body(d);
  CHECK(w.body(b).mass == 0.3);
  CHECK(w.body(b).local_com == given.com);
  CHECK(w.body(b).inertia == given.inertia);
  CHECK(w.body(b).x.isApprox(Vec3(1.02, 1.99, 3.05), 1e-15));
  CHECK(w.body(b).inv_inertia_local.isApprox(given.inertia.inverse(), 1e-12));
  const auto refused = [&](MassProperties<double> m, const char* name) {
    World<double> v;
    BodyDesc e = d;
    e.inertial = m;
    CHECK_THROWS_WITH(v.add_body(e), Catch::StartsWith(name));
  };
  MassProperties<double> bad = given;
  bad.mass = 0.0;
  refused(bad, "desc.inertial.mass: ");
  bad = given;
  bad.com.x() = std::numeric_limits<double>::quiet_NaN();
  refused(bad, "desc.inertial.com: ");
  bad = given;
  bad.inertia(0, 2) = 1e-4;  // not symmetric
  refused(bad, "desc.inertial.inertia: ");
  bad = given;
  bad.inertia = Vec3(1e-4, 1e-4, 3e-4).asDiagonal();  // A + B < C: no mass distribution has it
  refused(bad, "desc.inertial.inertia: ");
  bad = given;
  bad.inertia = Vec3(-1e-4, 5e-4, 3e-4).asDiagonal();
  refused(bad, "desc.inertial.inertia: ");
}

TEST_CASE("bad per-shape densities throw naming the argument", "[physics][materials][input]") {
  const std::array<double, 1> one{1000.0};
  const std::array<double, 2> negative{1000.0, -1.0};
  const std::array<double, 2> nan{std::numeric_limits<double>::quiet_NaN(), 1000.0};
  test::check_throws_naming([&] { (void)body_mass_properties<double>(two_cubes, 0, 0, one); },
                            "shape_density");
  test::check_throws_naming(
      [&] { (void)body_mass_properties<double>(two_cubes, 1.0, 0, negative); }, "shape_density[1]");
  test::check_throws_naming([&] { (void)body_mass_properties<double>(two_cubes, 0, 0, nan); },
                            "shape_density[0]");
  World<double> w;
  BodyDesc d;
  d.shapes = two_cubes;
  d.shape_density = one;
  test::check_throws_naming([&] { w.add_body(d); }, "desc.shape_density");
  d.shape_density = negative;
  test::check_throws_naming([&] { w.add_body(d); }, "desc.shape_density[1]");
  CHECK(w.body_count() == 0);
}

namespace {

// The ground (collider 0) and a flat body of two boxes side by side along x (colliders 1 and 2),
// 0.4 x 0.2 x 0.04 m, resting on it; body frictions mu_body give every pair sqrt(mu mu) = mu_body.
struct TwoPartSlider {
  World<double> w;
  int body = -1;
  explicit TwoPartSlider(double mu_body) {
    static const std::array<ShapeSpec, 1> ground{box("", at(0, 0, -0.5), {20.0, 20.0, 0.5})};
    static const std::array<ShapeSpec, 2> parts{box("", at(-0.1, 0, 0), {0.1, 0.1, 0.02}),
                                                box("", at(0.1, 0, 0), {0.1, 0.1, 0.02})};
    BodyDesc gd;
    gd.type = BodyType::fixed;
    gd.shapes = ground;
    gd.friction = mu_body;
    w.add_body(gd);
    BodyDesc d;
    d.pose = at(0, 0, 0.02);
    d.shapes = parts;
    d.mass = 2.0;
    d.friction = mu_body;
    body = w.add_body(d);
  }
  // The deceleration (m/s^2) of a slide launched at 2 m/s along +x, over 1/6 s.
  double deceleration() {
    for (int i = 0; i < 10; ++i) REQUIRE(w.step() == Status::success);
    w.set_velocity(body, Eigen::Vector3d(2.0, 0.0, 0.0), Eigen::Vector3d::Zero());
    const int n = 10;
    for (int i = 0; i < n; ++i) REQUIRE(w.step() == Status::success);
    return (2.0 - w.body(body).v.x()) / (n * w.options().time_step);
  }
};

}  // namespace

TEST_CASE("friction set per pair of shapes acts on that pair only", "[physics][materials]") {
  SECTION("the body's own friction without an override") {
    TwoPartSlider s(0.3);
    CHECK(s.deceleration() == Approx(0.3 * g).epsilon(0.03));
  }
  SECTION("both pairs overridden") {
    TwoPartSlider s(0.3);
    s.w.set_pair_friction(0, 1, 0.6);
    s.w.set_pair_friction(2, 0, 0.6);  // either order
    CHECK(s.deceleration() == Approx(0.6 * g).epsilon(0.03));
  }
  SECTION("one pair overridden: each half carries half the weight, so the mean coefficient") {
    TwoPartSlider s(0.2);
    s.w.set_pair_friction(0, 2, 0.6);
    int changed = 0;
    for (const Manifold<double>& m : s.w.manifolds()) {
      const bool pair = (m.collider_a == 0 && m.collider_b == 2);
      CHECK(m.friction == Approx(pair ? 0.6 : 0.2).epsilon(1e-12));
      changed += pair;
    }
    CHECK(changed == 1);
    // Loads shift a little to the leading half (the friction acts 2 cm below the centre).
    const double a = s.deceleration();
    CHECK(a > 0.35 * g);
    CHECK(a < 0.45 * g);
  }
}

TEST_CASE("set_pair_friction refuses bad input naming the argument",
          "[physics][materials][input]") {
  TwoPartSlider s(0.5);
  test::check_throws_naming([&] { s.w.set_pair_friction(-1, 1, 0.5); }, "collider_a");
  test::check_throws_naming([&] { s.w.set_pair_friction(3, 1, 0.5); }, "collider_a");
  test::check_throws_naming([&] { s.w.set_pair_friction(0, 3, 0.5); }, "collider_b");
  test::check_throws_naming([&] { s.w.set_pair_friction(1, 2, 0.5); }, "collider_b");  // same body
  test::check_throws_naming([&] { s.w.set_pair_friction(0, 1, -0.1); }, "mu");
  test::check_throws_naming(
      [&] { s.w.set_pair_friction(0, 1, std::numeric_limits<double>::quiet_NaN()); }, "mu");
  test::check_throws_naming([&] { s.w.set_pair_friction(0, 1, 2e6); }, "mu");
  for (const Manifold<double>& m : s.w.manifolds()) CHECK(m.friction == Approx(0.5));
}

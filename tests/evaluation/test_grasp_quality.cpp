// SPDX-License-Identifier: BSD-3-Clause
// The Ferrari-Canny epsilon (Q1): the contact wrenches and the torque scale (always), and, where
// qhull was found, epsilon on grasps with a known answer, checked against an independent
// computation from the raw wrenches, its invariances and monotonicity, and the hand scene's
// contacts.
#include "evaluation_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <catch2/catch.hpp>
#include "support/throws.hpp"

#ifdef TOPOGRASP_HAVE_QHULL
#include <topograsp/evaluation/grasp_quality.hpp>
#endif

using namespace topograsp;
using Wrenches = Eigen::Matrix<double, 6, Eigen::Dynamic>;

namespace {

ContactForQuality contact(const Vec3& p, const Vec3& n, double mu) { return {p, n, mu}; }

// A cube (half side 0.05 m) centred at the origin: a contact at point p on the face whose
// outward normal is f pushes along -f.
ContactForQuality on_cube(const Vec3& p, const Vec3& outward, double mu) {
  return contact(p, -outward, mu);
}

constexpr double half_side = 0.05;  // the cube's half side (m)

// One contact at the centre of each of the faces +-x and +-y.
std::vector<ContactForQuality> four_finger_cube(double mu) {
  return {on_cube({half_side, 0, 0}, Vec3::UnitX(), mu),
          on_cube({-half_side, 0, 0}, -Vec3::UnitX(), mu),
          on_cube({0, half_side, 0}, Vec3::UnitY(), mu),
          on_cube({0, -half_side, 0}, -Vec3::UnitY(), mu)};
}

Wrenches wrenches_of(const std::vector<ContactForQuality>& c, const Vec3& centre, double scale,
                     int edges = 8) {
  Wrenches w;
  QualityOptions o;
  o.edges = edges;
  contact_wrenches(c, centre, scale, o, w);
  return w;
}

#ifdef TOPOGRASP_HAVE_QHULL

// A thumb on the +x face against two fingers on the -x face.
std::vector<ContactForQuality> three_finger_cube(double mu) {
  return {on_cube({half_side, 0, 0}, Vec3::UnitX(), mu),
          on_cube({-half_side, 0.03, 0}, -Vec3::UnitX(), mu),
          on_cube({-half_side, -0.03, 0}, -Vec3::UnitX(), mu)};
}

// GraspIt's torque scale for the cube about its centre: its half diagonal.
const double cube_scale = std::sqrt(3.0) * half_side;

// The support function of the wrench set: h(u) = max_i w_i . u.
double support(const Wrenches& w, const Vec<6>& u) { return (u.transpose() * w).maxCoeff(); }

// An independent estimate of epsilon = min over unit u of h(u) (the inscribed-ball radius of the
// hull when it holds the origin): many random directions, then a shrinking random local search
// from the best of them. Every value it returns is h of some unit u, so it is >= epsilon.
double sampled_epsilon(const Wrenches& w) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  auto random_unit = [&] {
    Vec<6> u;
    for (int d = 0; d < 6; ++d) u[d] = normal(rng);
    return Vec<6>(u.normalized());
  };
  std::vector<std::pair<double, Vec<6>>> samples;
  for (int s = 0; s < 20000; ++s) {
    const Vec<6> u = random_unit();
    samples.emplace_back(support(w, u), u);
  }
  std::partial_sort(samples.begin(), samples.begin() + 10, samples.end(),
                    [](const auto& l, const auto& r) { return l.first < r.first; });
  double best = std::numeric_limits<double>::infinity();
  for (int start = 0; start < 10; ++start) {
    auto [h, u] = samples[static_cast<std::size_t>(start)];
    for (double step = 0.2; step > 1e-6; step *= 0.5)
      for (int t = 0; t < 300; ++t) {
        const Vec<6> v = (u + step * random_unit()).normalized();
        const double hv = support(w, v);
        if (hv < h) {
          h = hv;
          u = v;
        }
      }
    best = std::min(best, h);
  }
  return best;
}

#endif  // TOPOGRASP_HAVE_QHULL

}  // namespace

TEST_CASE("contact wrenches: unit normal force on the cone's edges, torques over the scale",
          "[evaluation][quality]") {
  const Vec3 p(0.1, 0.2, -0.3), centre(0.01, -0.02, 0.03);
  const Vec3 n = Vec3(1, 2, 2) / 3.0;
  const double mu = 0.7, scale = 0.25;
  const Wrenches w = wrenches_of({contact(p, 3.0 * n, mu)}, centre, scale);  // normalised
  REQUIRE(w.cols() == 8);
  Vec3 mean_force = Vec3::Zero();
  for (Eigen::Index k = 0; k < w.cols(); ++k) {
    const Vec3 f = w.col(k).head<3>();
    CHECK(f.dot(n) == Approx(1.0));                  // unit normal force
    CHECK((f - f.dot(n) * n).norm() == Approx(mu));  // on the cone's boundary
    CHECK((w.col(k).tail<3>() - (p - centre).cross(f) / scale).norm() < 1e-15);
    mean_force += f / 8.0;
    if (k > 0) {  // equally spaced: 45 degrees between neighbouring tangential parts
      const Vec3 t0 = w.col(k - 1).head<3>() - n, t1 = f - n;
      CHECK(t0.dot(t1) / (mu * mu) == Approx(std::cos(std::numbers::pi / 4)));
    }
  }
  CHECK((mean_force - n).norm() < 1e-14);
  // A frictionless contact gives one wrench whatever the edge count.
  const Wrenches w0 = wrenches_of({contact(p, n, 0.0)}, centre, scale, 16);
  REQUIRE(w0.cols() == 1);
  CHECK((w0.col(0).head<3>() - n).norm() < 1e-15);
  // More edges, more wrenches.
  CHECK(wrenches_of({contact(p, n, mu), contact(-p, -n, 0.0)}, centre, scale, 64).cols() == 65);
}

TEST_CASE("contact wrenches: bad input is refused naming the argument", "[evaluation][quality]") {
  const std::vector<ContactForQuality> good = four_finger_cube(0.5);
  Wrenches w;
  auto call = [&](std::vector<ContactForQuality> c, Vec3 centre, double scale, int edges) {
    QualityOptions o;
    o.edges = edges;
    contact_wrenches(c, centre, scale, o, w);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto with = [&](int i, auto edit) {
    std::vector<ContactForQuality> c = good;
    edit(c[static_cast<std::size_t>(i)]);
    return c;
  };
  const Vec3 o = Vec3::Zero();
  test::check_throws_naming([&] { call(with(2, [&](auto& c) { c.point.x() = nan; }), o, 1.0, 8); },
                            "contacts[2].point");
  test::check_throws_naming([&] { call(with(1, [](auto& c) { c.normal.setZero(); }), o, 1.0, 8); },
                            "contacts[1].normal");
  test::check_throws_naming([&] { call(with(0, [&](auto& c) { c.normal.y() = nan; }), o, 1.0, 8); },
                            "contacts[0].normal");
  test::check_throws_naming([&] { call(with(3, [](auto& c) { c.friction = -0.1; }), o, 1.0, 8); },
                            "contacts[3].friction");
  test::check_throws_naming([&] { call(with(3, [&](auto& c) { c.friction = nan; }), o, 1.0, 8); },
                            "contacts[3].friction");
  test::check_throws_naming([&] { call(good, Vec3(0, nan, 0), 1.0, 8); }, "centre");
  test::check_throws_naming([&] { call(good, o, 0.0, 8); }, "torque_scale");
  test::check_throws_naming([&] { call(good, o, -1.0, 8); }, "torque_scale");
  test::check_throws_naming([&] { call(good, o, nan, 8); }, "torque_scale");
  test::check_throws_naming([&] { call(good, o, 1.0, 2); }, "options.edges");
  test::check_throws_naming([&] { call(good, o, 1.0, QualityOptions::k_max_edges + 1); },
                            "options.edges");
  CHECK_NOTHROW(call({}, o, 1.0, 3));  // no contact: no wrench, not an error
  CHECK(w.cols() == 0);
}

TEST_CASE("affine dimension of a wrench set", "[evaluation][quality]") {
  CHECK(affine_dimension(Wrenches(6, 0)) == 0);
  CHECK(affine_dimension(Wrenches::Random(6, 1)) == 0);
  CHECK(affine_dimension(Wrenches::Random(6, 2)) == 1);
  CHECK(affine_dimension(Wrenches::Random(6, 7)) == 6);
  Wrenches flat = Wrenches::Random(6, 40);
  flat.row(3).setConstant(0.5);  // a hyperplane
  CHECK(affine_dimension(flat) == 5);
}

TEST_CASE("max_radius is the farthest surface point from the centre", "[evaluation][quality]") {
  const std::vector<ShapeSpec> box_only = {box("", Pose{}, {0.1, 0.2, 0.3})};
  CHECK(max_radius(box_only, Vec3::Zero()) == Approx(std::sqrt(0.01 + 0.04 + 0.09)));
  CHECK(max_radius(box_only, Vec3(0.1, 0, 0)) == Approx(std::sqrt(0.04 + 0.04 + 0.09)));
  const std::vector<ShapeSpec> ball = {sphere("", {0.0, 0.0, 0.2}, 0.05)};
  CHECK(max_radius(ball, Vec3::Zero()) == Approx(0.25));
  // A cylinder (radius 0.03, half height 0.1) along z: the rim corner, from an off-axis centre.
  const std::vector<ShapeSpec> can = {cylinder("", Pose{}, 0.03, 0.1)};
  CHECK(max_radius(can, Vec3(0.01, 0, 0.02)) == Approx(std::hypot(0.04, 0.12)));
  // A capsule along x (rotated), from its middle: half length plus radius.
  const std::vector<ShapeSpec> pill = {capsule("", {-0.1, 0, 0}, {0.1, 0, 0}, 0.02)};
  CHECK(max_radius(pill, Vec3::Zero()) == Approx(0.12));
  // Several shapes: the farthest of them, e.g. a hammer-like head and handle.
  const std::vector<ShapeSpec> hammer = {box("", at(0, 0, 0.15), {0.05, 0.015, 0.015}),
                                         cylinder("", Pose{}, 0.015, 0.15)};
  CHECK(max_radius(hammer, Vec3::Zero()) ==
        Approx(std::sqrt(0.05 * 0.05 + 0.015 * 0.015 + 0.165 * 0.165)));
  test::check_throws_naming([&] { (void)max_radius({}, Vec3::Zero()); }, "shapes");
  test::check_throws_naming(
      [&] { (void)max_radius(ball, Vec3(std::numeric_limits<double>::infinity(), 0, 0)); },
      "centre");
  const std::vector<ShapeSpec> bad = {box("", Pose{}, {0.1, -0.2, 0.3})};
  test::check_throws_naming([&] { (void)max_radius(bad, Vec3::Zero()); }, "shapes[0].size");
}

TEST_CASE("the hand scene's contact points: into the object, with the pair's friction",
          "[evaluation][quality]") {
  HandScene<models::schunk_sdh> scene = test::sdh_bottle_scene(0.8);
  CHECK(scene.hand_contact_points().empty());  // before any step
  const auto closed = close_hand(scene, CloseOptions{});
  REQUIRE(closed.status == Status::success);
  const std::vector<ContactForQuality> c = scene.hand_contact_points();
  CHECK(static_cast<int>(c.size()) == scene.hand_contacts());
  REQUIRE(c.size() >= 2);
  const Vec3 centre = scene.object_com();
  const Vec3 axis = scene.object_pose().linear().col(2);  // the bottle's axis
  for (const ContactForQuality& k : c) {
    CHECK(k.normal.norm() == Approx(1.0));
    CHECK(k.friction == 0.8);
    // On the bottle's side, the normal into the object points at the axis.
    Vec3 radial = k.point - centre;
    radial -= radial.dot(axis) * axis;
    CHECK(k.normal.dot(-radial.normalized()) > 0.9);
  }
  // A larger separation admits at least as many points.
  CHECK(scene.hand_contact_points(0.01).size() >= c.size());
#ifdef TOPOGRASP_HAVE_QHULL
  const GraspQuality q = ferrari_canny_epsilon(c, centre, 0.1);
  CHECK(std::isfinite(q.epsilon));
  CHECK(q.wrenches == 8 * static_cast<int>(c.size()));
#endif
}

#ifdef TOPOGRASP_HAVE_QHULL

TEST_CASE("Q1: two opposite frictionless contacts on a sphere are not force closure",
          "[evaluation][quality][qhull]") {
  const double r = 0.04;
  const std::vector<ContactForQuality> c = {contact({r, 0, 0}, -Vec3::UnitX(), 0.0),
                                            contact({-r, 0, 0}, Vec3::UnitX(), 0.0)};
  const GraspQuality q = ferrari_canny_epsilon(c, Vec3::Zero(), r);
  CHECK(q.status == GraspQualityStatus::degenerate);
  CHECK(q.epsilon == 0.0);
  CHECK(q.wrenches == 2);
  CHECK_THAT(q.reason, Catch::Contains("at least 7"));
  CHECK(to_string(q.status) == "degenerate");
}

TEST_CASE(
    "Q1: two opposite contacts with friction on a sphere cannot resist a torque about "
    "their axis",
    "[evaluation][quality][qhull]") {
  const double r = 0.04;
  for (const int edges : {8, 64}) {
    QualityOptions o;
    o.edges = edges;
    const std::vector<ContactForQuality> c = {contact({r, 0, 0}, -Vec3::UnitX(), 1.0),
                                              contact({-r, 0, 0}, Vec3::UnitX(), 1.0)};
    const GraspQuality q = ferrari_canny_epsilon(c, Vec3::Zero(), r, o);
    INFO(q.reason);
    CHECK(q.status != GraspQualityStatus::force_closure);
    CHECK(q.epsilon <= 0.0);
    // Every wrench has zero torque about x: the set is flat, 5 of 6 dimensions.
    CHECK(q.status == GraspQualityStatus::degenerate);
    CHECK_THAT(q.reason, Catch::Contains("only 5 of 6"));
  }
}

TEST_CASE("Q1: no contact, one contact", "[evaluation][quality][qhull]") {
  CHECK(ferrari_canny_epsilon(std::span<const ContactForQuality>{}, Vec3::Zero(), 1.0).status ==
        GraspQualityStatus::degenerate);
  const std::vector<ContactForQuality> one = {contact({0.1, 0, 0}, -Vec3::UnitX(), 1.0)};
  const GraspQuality q = ferrari_canny_epsilon(one, Vec3::Zero(), 0.1);
  CHECK(q.status == GraspQualityStatus::degenerate);
  CHECK(q.epsilon == 0.0);
  CHECK(q.wrenches == 8);
}

TEST_CASE("Q1: contacts that can only push one way: the signed value is negative",
          "[evaluation][quality][qhull]") {
  // Contacts with one normal give wrenches in one hyperplane (unit normal force): flat.
  std::vector<ContactForQuality> c;
  for (const double x : {-0.03, 0.03})
    for (const double y : {-0.03, 0.03})
      c.push_back(on_cube({x, y, half_side}, Vec3::UnitZ(), 0.5));
  CHECK(ferrari_canny_epsilon(c, Vec3::Zero(), cube_scale).status ==
        GraspQualityStatus::degenerate);
  // Add two on the +x face: the hull is full, but no force has a positive component along
  // (1, 0, 1) (mu 0.5 < 1), so the origin is outside it.
  c.push_back(on_cube({half_side, 0.02, 0.01}, Vec3::UnitX(), 0.5));
  c.push_back(on_cube({half_side, -0.02, -0.02}, Vec3::UnitX(), 0.5));
  const GraspQuality q = ferrari_canny_epsilon(c, Vec3::Zero(), cube_scale);
  INFO(q.reason);
  REQUIRE(q.status == GraspQualityStatus::not_force_closure);
  CHECK(q.epsilon < -0.01);
  // The value belongs to a real facet: the wrenches' support along its normal.
  const Wrenches w = wrenches_of(c, Vec3::Zero(), cube_scale);
  CHECK(support(w, q.weakest_direction) == Approx(q.epsilon).margin(2e-4));
}

TEST_CASE(
    "Q1: three and four fingers on a cube are force closure, and epsilon agrees with an "
    "independent computation from the raw wrenches",
    "[evaluation][quality][qhull]") {
  // qhull pre-merges facets whose centrums lie within 1e-4 (GraspIt's C-0.0001): the facets
  // are exact to about that.
  constexpr double merge = 2e-4;
  for (const auto& [name, grasp] :
       {std::pair{"three", three_finger_cube(0.5)}, std::pair{"four", four_finger_cube(0.5)}}) {
    INFO(name << " fingers");
    const GraspQuality q = ferrari_canny_epsilon(grasp, Vec3::Zero(), cube_scale);
    INFO(q.reason);
    REQUIRE(q.status == GraspQualityStatus::force_closure);
    CHECK(q.epsilon > 0.01);
    CHECK(q.facets > 0);
    CHECK(q.volume > 0.0);
    const Wrenches w = wrenches_of(grasp, Vec3::Zero(), cube_scale);
    CHECK(q.wrenches == w.cols());
    // The weakest direction is a unit facet normal that touches the wrenches at distance epsilon.
    CHECK(q.weakest_direction.norm() == Approx(1.0));
    CHECK(support(w, q.weakest_direction) == Approx(q.epsilon).margin(merge));
    // No direction does better: the sampled minimum of h(u) is >= epsilon and close to it.
    const double sampled = sampled_epsilon(w);
    INFO("epsilon " << q.epsilon << ", sampled minimum of the support function " << sampled);
    CHECK(q.epsilon <= sampled + merge);
    CHECK(sampled <= q.epsilon * 1.02 + merge);
  }
}

TEST_CASE("Q1 by hand: twelve frictionless contacts on a cube give epsilon 1/sqrt(3)",
          "[evaluation][quality][qhull]") {
  // Frictionless contacts at the centres of the six faces: unit forces without torque, so no
  // torque is resisted: flat.
  std::vector<ContactForQuality> six;
  for (int d = 0; d < 3; ++d)
    for (const double s : {-1.0, 1.0}) {
      const Vec3 outward = s * Vec3::Unit(d);
      six.push_back(on_cube(half_side * outward, outward, 0.0));
    }
  CHECK(ferrari_canny_epsilon(six, Vec3::Zero(), cube_scale).status ==
        GraspQualityStatus::degenerate);
  // Two per face instead, offset by +-b: on the x faces along z, on the y faces along x, on the z
  // faces along y. With torque scale b each wrench is a unit force plus a unit torque: the x faces
  // give the four points +-e1 +-e5 of R^6 (force x, torque y), the y faces +-e2 +-e6, the z faces
  // +-e3 +-e4. The hull is the convex hull of three unit squares (half side 1) in orthogonal
  // planes, so its support function is h(u) = max over the planes k of |u_k1| + |u_k2| >=
  // |u_k| (the squares' inradius is 1). The minimum over unit u puts |u_k| = 1/sqrt(3) in each
  // plane along a square's axis: epsilon = 1/sqrt(3).
  const double b = 0.02;
  std::vector<ContactForQuality> twelve;
  for (int d = 0; d < 3; ++d)
    for (const double s : {-1.0, 1.0})
      for (const double t : {-1.0, 1.0}) {
        const Vec3 outward = s * Vec3::Unit(d);
        twelve.push_back(
            on_cube(half_side * outward + t * b * Vec3::Unit((d + 2) % 3), outward, 0.0));
      }
  const GraspQuality q = ferrari_canny_epsilon(twelve, Vec3::Zero(), b);
  INFO(q.reason);
  REQUIRE(q.status == GraspQualityStatus::force_closure);
  CHECK(q.wrenches == 12);
  CHECK(q.epsilon == Approx(1.0 / std::sqrt(3.0)).epsilon(1e-9));
  const Wrenches w = wrenches_of(twelve, Vec3::Zero(), b);
  CHECK(support(w, q.weakest_direction) == Approx(q.epsilon).epsilon(1e-9));
  CHECK(q.epsilon <= sampled_epsilon(w) + 1e-9);

  // The same wrenches shifted so that the origin lies on the nearest facet's plane: epsilon 0,
  // not force closure; shifted further, negative.
  const Vec<6> u = q.weakest_direction;
  const GraspQuality on = ferrari_canny_epsilon(Wrenches(w.colwise() - q.epsilon * u));
  CHECK(on.status == GraspQualityStatus::not_force_closure);
  CHECK(on.epsilon == 0.0);
  const GraspQuality out = ferrari_canny_epsilon(Wrenches(w.colwise() - (q.epsilon + 0.1) * u));
  CHECK(out.status == GraspQualityStatus::not_force_closure);
  CHECK(out.epsilon == Approx(-0.1).epsilon(1e-9));
}

TEST_CASE("Q1 does not depend on where the grasp is: rotated and translated, same epsilon",
          "[evaluation][quality][qhull]") {
  const std::vector<ContactForQuality> base = four_finger_cube(0.6);
  const Eigen::Isometry3d T =
      test::z_along(Vec3(0.3, -0.5, 0.8).normalized(), Vec3(0.4, -1.2, 2.5));
  auto moved = [&](const Eigen::Isometry3d& X) {
    std::vector<ContactForQuality> c = base;
    for (ContactForQuality& k : c) {
      k.point = X * k.point;
      k.normal = X.linear() * k.normal;
    }
    return c;
  };
  for (const int edges : {8, 16}) {
    INFO(edges << " edges");
    QualityOptions o;
    o.edges = edges;
    const double e0 = ferrari_canny_epsilon(base, Vec3::Zero(), cube_scale, o).epsilon;
    REQUIRE(e0 > 0.0);
    // Translated: the same wrenches up to rounding.
    Eigen::Isometry3d shift = Eigen::Isometry3d::Identity();
    shift.translation() = Vec3(0.4, -1.2, 2.5);
    CHECK(ferrari_canny_epsilon(moved(shift), shift.translation(), cube_scale, o).epsilon ==
          Approx(e0).epsilon(1e-6));
    // Rotated too: the wrench set turns with the grasp except for where the linearised cones'
    // edges fall around each normal (their tangent basis follows the world axes), which moves
    // epsilon by less than the linearisation itself (see the edge-count test).
    const double e1 = ferrari_canny_epsilon(moved(T), T.translation(), cube_scale, o).epsilon;
    CHECK(e1 == Approx(e0).epsilon(edges == 8 ? 0.05 : 0.02));
  }
}

TEST_CASE("Q1: more friction never lowers epsilon; more edges converge",
          "[evaluation][quality][qhull]") {
  constexpr double merge = 2e-4;
  for (const bool four : {false, true}) {
    INFO((four ? "four" : "three") << " fingers");
    double previous = -std::numeric_limits<double>::infinity();
    for (const double mu : {0.2, 0.3, 0.5, 0.8, 1.2}) {
      const auto grasp = four ? four_finger_cube(mu) : three_finger_cube(mu);
      const double e = ferrari_canny_epsilon(grasp, Vec3::Zero(), cube_scale).epsilon;
      INFO("mu " << mu << ": epsilon " << e);
      CHECK(e >= previous - merge);
      previous = e;
    }
    const auto grasp = four ? four_finger_cube(0.5) : three_finger_cube(0.5);
    double e8 = 0.0;
    // (64 edges take seconds: 256 wrenches, 2e5 facets; docs/evaluation.md gives the numbers.)
    for (const int edges : {8, 16, 32}) {
      QualityOptions o;
      o.edges = edges;
      const double e = ferrari_canny_epsilon(grasp, Vec3::Zero(), cube_scale, o).epsilon;
      INFO(edges << " edges: epsilon " << e << ", 8 edges: " << e8);
      // 8 | 16 | 32: the coarser cone's edges are among the finer's, so epsilon never falls.
      CHECK(e >= e8 - merge);
      if (edges == 8) e8 = e;
      // Converged to a few percent: the 8-edge cone reaches cos(pi/8) = 0.92 of the circle's
      // radius between its edges; epsilon moves less.
      if (edges == 32) CHECK(e <= e8 * 1.05);
    }
  }
}

TEST_CASE("Q1: bad input is refused naming the argument", "[evaluation][quality][qhull]") {
  const std::vector<ContactForQuality> good = four_finger_cube(0.5);
  std::vector<ContactForQuality> bad = good;
  bad[1].normal.setZero();
  test::check_throws_naming([&] { (void)ferrari_canny_epsilon(bad, Vec3::Zero(), 0.1); },
                            "contacts[1].normal");
  test::check_throws_naming([&] { (void)ferrari_canny_epsilon(good, Vec3::Zero(), 0.0); },
                            "torque_scale");
  QualityOptions o;
  o.edges = 2;
  test::check_throws_naming([&] { (void)ferrari_canny_epsilon(good, Vec3::Zero(), 0.1, o); },
                            "options.edges");
  Wrenches w = wrenches_of(good, Vec3::Zero(), 0.1);
  w(4, 3) = std::numeric_limits<double>::infinity();
  test::check_throws_naming([&] { (void)ferrari_canny_epsilon(w); }, "wrenches");
}

#endif  // TOPOGRASP_HAVE_QHULL

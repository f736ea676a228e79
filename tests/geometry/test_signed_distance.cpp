// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <topograsp/geometry.hpp>

#include "support/random.hpp"

using namespace topograsp;

namespace {

Primitive random_primitive(std::mt19937& rng, ShapeType type, double spread) {
  std::uniform_real_distribution<double> s(0.02, 0.1);
  const Eigen::Isometry3d T = test::random_pose(rng, spread);
  switch (type) {
    case ShapeType::sphere:
      return Primitive::sphere(T.translation(), s(rng));
    case ShapeType::capsule: {
      const Vec3 h = T.linear().col(2) * s(rng);
      return Primitive::capsule(T.translation() - h, T.translation() + h, s(rng) * 0.5);
    }
    case ShapeType::box:
      return Primitive::box(T, Vec3(s(rng), s(rng), s(rng)));
    case ShapeType::cylinder:
      return Primitive::cylinder(T, s(rng), s(rng));
  }
  return {};
}

// A random point inside s.
Vec3 random_inside(std::mt19937& rng, const Primitive& s) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    const Vec3 l(u(rng), u(rng), u(rng));
    switch (s.type) {
      case ShapeType::sphere:
        if (l.norm() <= 1.0) return s.p + s.size[0] * l;
        break;
      case ShapeType::capsule:
        if (l.norm() <= 1.0) return s.p + s.R * Vec3(0, 0, s.size[1] * u(rng)) + s.size[0] * l;
        break;
      case ShapeType::box:
        return s.p + s.R * s.size.cwiseProduct(l);
      case ShapeType::cylinder:
        if (l.head<2>().norm() <= 1.0)
          return s.p + s.R * Vec3(s.size[0] * l.x(), s.size[0] * l.y(), s.size[1] * l.z());
        break;
    }
  }
}

Primitive translated(Primitive s, const Vec3& t) {
  s.p += t;
  return s;
}

// The support function of the whole shape (core and round radius) in the unit direction u.
double support(const Primitive& s, const Vec3& u) {
  return u.dot(detail::core_support(s, u)) + detail::round_radius(s);
}

// An upper bound on the penetration depth of a and b, the least over unit u of the overlap of
// their extents along u, h_a(u) + h_b(-u) (moving b by that along u makes them touch): the least
// over a Fibonacci sphere of 20000 directions, refined from its 8 best by random search on
// shrinking scales (0.03 rad down to 1e-10). It converges from above; on these shapes (2 to 10 cm)
// it is within about 3e-6 m of the true depth (a sphere against a cylinder, closed form: within
// 2e-7 m). Negative when the shapes are apart (then not a distance).
double oracle_depth(const Primitive& a, const Primitive& b) {
  constexpr int n = 20000;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  const auto overlap = [&](const Vec3& u) { return support(a, u) + support(b, -u); };
  std::vector<std::pair<double, Vec3>> grid;
  grid.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z), t = golden * i;
    const Vec3 u(r * std::cos(t), r * std::sin(t), z);
    grid.emplace_back(overlap(u), u);
  }
  std::partial_sort(grid.begin(), grid.begin() + 8, grid.end(),
                    [](const auto& x, const auto& y) { return x.first < y.first; });
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  double best = grid[0].first;
  for (int s = 0; s < 8; ++s) {
    auto [v, u] = grid[static_cast<std::size_t>(s)];
    for (double step = 0.03; step > 1e-10; step *= 0.8)
      for (int k = 0; k < 100; ++k) {
        const Vec3 t = (u + step * Vec3(g(rng), g(rng), g(rng))).normalized();
        const double o = overlap(t);
        if (o < v) {
          v = o;
          u = t;
        }
      }
    best = std::min(best, v);
  }
  return best;
}

const std::array<ShapeType, 4> k_types{ShapeType::sphere, ShapeType::capsule, ShapeType::box,
                                       ShapeType::cylinder};

}  // namespace

TEST_CASE("signed distance of separated shapes is the exact distance for every pair",
          "[geometry]") {
  std::mt19937 rng(42);
  for (ShapeType ta : k_types)
    for (ShapeType tb : k_types) {
      int separated = 0;
      for (int trial = 0; trial < 60; ++trial) {
        const Primitive a = random_primitive(rng, ta, 0.15), b = random_primitive(rng, tb, 0.15);
        const Contact c = signed_distance(a, b);
        if (c.distance <= 1e-6) continue;
        ++separated;
        INFO(to_string(ta) << " vs " << to_string(tb) << " trial " << trial);
        REQUIRE(std::isfinite(c.distance));
        CHECK(c.normal.norm() == Approx(1.0).epsilon(1e-12));
        CHECK((c.point_b - c.point_a - c.distance * c.normal).norm() < 1e-12);
        // The witnesses lie on the surfaces and realise the distance ...
        CHECK(std::abs(signed_distance(a, c.point_a)) < 1e-10);
        CHECK(std::abs(signed_distance(b, c.point_b)) < 1e-10);
        CHECK(signed_distance(b, c.point_a) == Approx(c.distance).margin(1e-10));
        // ... and no point of A is closer to B.
        for (int k = 0; k < 200; ++k)
          CHECK(signed_distance(b, random_inside(rng, a)) >= c.distance - 1e-10);
        // Symmetry.
        const Contact r = signed_distance(b, a);
        CHECK(r.distance == Approx(c.distance).margin(1e-11));
      }
      CHECK(separated > 10);
    }
}

TEST_CASE("signed distance of overlapping shapes is minus the penetration depth", "[geometry]") {
  std::mt19937 rng(43);
  std::normal_distribution<double> g(0.0, 1.0);
  for (ShapeType ta : k_types)
    for (ShapeType tb : k_types) {
      int overlapping = 0;
      for (int trial = 0; trial < 60; ++trial) {
        const Primitive a = random_primitive(rng, ta, 0.05), b = random_primitive(rng, tb, 0.05);
        const Contact c = signed_distance(a, b);
        // With a cylinder the depth is iterative (EPA): compared with the oracle, and whether the
        // pair overlaps is the oracle's call, so that a depth of 0 cannot skip the checks.
        const bool curved = ta == ShapeType::cylinder || tb == ShapeType::cylinder;
        const double oracle = curved ? oracle_depth(a, b) : 0.0;
        if (curved) {
          INFO(to_string(ta) << " vs " << to_string(tb) << " trial " << trial << " d " << c.distance
                             << " oracle " << oracle);
          if (oracle > 1e-4) {
            // EPA's depth is a lower bound (its polytope lies inside the Minkowski difference),
            // the oracle an upper bound within about 3e-6 m.
            CHECK(-c.distance <= oracle + 1e-9);
            CHECK(-c.distance >= oracle - 1e-5);
          } else if (oracle < -1e-4) {
            CHECK(c.distance > 0.0);
          }
        }
        if (c.distance >= -1e-4) continue;
        ++overlapping;
        INFO(to_string(ta) << " vs " << to_string(tb) << " trial " << trial << " d " << c.distance);
        // EPA on a cylinder's curved rim stops at a tolerance; polytope cores are exact.
        const double tol_depth = curved ? 1e-7 : 1e-10, tol_witness = curved ? 3e-5 : 1e-10;
        CHECK(c.normal.norm() == Approx(1.0).epsilon(1e-12));
        CHECK((c.point_b - c.point_a - c.distance * c.normal).norm() < tol_witness);
        // Moving B by the depth along the normal separates the shapes exactly ...
        const double depth = -c.distance;
        CHECK(signed_distance(a, translated(b, depth * c.normal)).distance ==
              Approx(0.0).margin(tol_depth));
        CHECK(signed_distance(a, translated(b, (depth + 1e-3) * c.normal)).distance ==
              Approx(1e-3).margin(tol_depth));
        // ... and no shorter move in another direction does.
        for (int k = 0; k < 50; ++k) {
          const Vec3 u = Vec3(g(rng), g(rng), g(rng)).normalized();
          CHECK(signed_distance(a, translated(b, 0.999 * depth * u)).distance < 1e-9);
        }
        const Contact r = signed_distance(b, a);
        CHECK(r.distance == Approx(c.distance).margin(tol_depth));
      }
      CHECK(overlapping > 10);
    }
}

TEST_CASE("the distance changes by the normal component of a rigid motion", "[geometry]") {
  // d d = n . v_B(point_b) - n . v_A(point_a): the formula every distance Jacobian relies on.
  std::mt19937 rng(44);
  std::normal_distribution<double> g(0.0, 1.0);
  for (ShapeType ta : k_types)
    for (ShapeType tb : k_types)
      for (int trial = 0; trial < 25; ++trial) {
        const Primitive a = random_primitive(rng, ta, 0.1), b = random_primitive(rng, tb, 0.1);
        const Contact c = signed_distance(a, b);
        const Vec3 w(g(rng), g(rng), g(rng)), v(g(rng), g(rng), g(rng)), o = random_inside(rng, b);
        // Rigid motion of B: angular velocity w about o plus translation v.
        const auto moved = [&](double t) {
          Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
          T.translate(o + t * v);
          T.rotate(Eigen::AngleAxisd(t * w.norm(), w.normalized()));
          T.translate(-o);
          return b.transformed(T);
        };
        const double h = 1e-6;
        const double fd =
            (signed_distance(a, moved(h)).distance - signed_distance(a, moved(-h)).distance) /
            (2 * h);
        const double analytic = c.normal.dot(v + w.cross(c.point_b - o));
        INFO(to_string(ta) << " vs " << to_string(tb) << " trial " << trial << " d " << c.distance);
        // With a cylinder GJK and EPA approach the curved rim iteratively: the witness points
        // (and so the gradient) are less accurate than the distance itself.
        const bool curved = ta == ShapeType::cylinder || tb == ShapeType::cylinder;
        CHECK(analytic == Approx(fd).margin(!curved ? 1e-6 : c.distance < 0.0 ? 2e-4 : 1e-5));
      }
}

TEST_CASE("signed distance closed-form cases", "[geometry]") {
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T = I;
  SECTION("parallel cylinders side by side") {
    T.translation() = Vec3(0.08, 0.01, 0.02);
    const Contact c =
        signed_distance(Primitive::cylinder(I, 0.05, 0.1), Primitive::cylinder(T, 0.04, 0.1));
    CHECK(c.distance == Approx(std::hypot(0.08, 0.01) - 0.09).margin(1e-12));
    T.translation() = Vec3(0.3, 0.01, 0.02);
    CHECK(signed_distance(Primitive::cylinder(I, 0.05, 0.1), Primitive::cylinder(T, 0.04, 0.1))
              .distance == Approx(std::hypot(0.3, 0.01) - 0.09).margin(1e-12));
  }
  SECTION("capsule lying on a box face, and sinking into it") {
    const Primitive bx = Primitive::box(I, Vec3(0.1, 0.2, 0.3));
    const Contact c =
        signed_distance(Primitive::capsule(Vec3(0.15, -0.1, 0), Vec3(0.15, 0.1, 0.1), 0.01), bx);
    CHECK(c.distance == Approx(0.04).margin(1e-14));
    CHECK((c.normal + Vec3::UnitX()).norm() < 1e-12);
    const Contact p =
        signed_distance(Primitive::capsule(Vec3(0.07, -0.1, 0), Vec3(0.07, 0.1, 0), 0.01), bx);
    CHECK(p.distance == Approx(-0.04).margin(1e-14));
  }
  SECTION("sphere inside a box and a cylinder") {
    const Primitive s = Primitive::sphere(Vec3(0.0, 0.0, 0.25), 0.02);
    CHECK(signed_distance(s, Primitive::box(I, Vec3(0.1, 0.2, 0.3))).distance ==
          Approx(-0.07).margin(1e-15));
    CHECK(signed_distance(s, Primitive::cylinder(I, 0.1, 0.3)).distance ==
          Approx(-0.07).margin(1e-15));
    CHECK(signed_distance(Primitive::cylinder(I, 0.1, 0.3), Vec3(0.2, 0.0, 0.4)) ==
          Approx(std::hypot(0.1, 0.1)).margin(1e-15));
  }
  SECTION("crossing capsules get a normal across both axes") {
    const Contact c = signed_distance(Primitive::capsule(Vec3(-1, 0, 0), Vec3(1, 0, 0), 0.1),
                                      Primitive::capsule(Vec3(0, -1, 0), Vec3(0, 1, 0), 0.1));
    CHECK(c.distance == Approx(-0.2));
    CHECK(std::abs(c.normal.z()) == Approx(1.0));
    CHECK(c.point_a.allFinite());
  }
  SECTION("concentric shapes give finite answers") {
    const Contact a =
        signed_distance(Primitive::sphere(Vec3::Zero(), 0.1), Primitive::sphere(Vec3::Zero(), 0.2));
    CHECK(a.distance == Approx(-0.3));
    const Contact b = signed_distance(Primitive::box(I, Vec3(0.1, 0.1, 0.1)),
                                      Primitive::box(I, Vec3(0.1, 0.1, 0.1)));
    CHECK(b.distance == Approx(-0.2).margin(1e-12));
    const Contact c =
        signed_distance(Primitive::cylinder(I, 0.1, 0.1), Primitive::cylinder(I, 0.1, 0.1));
    CHECK(std::isfinite(c.distance));
    CHECK(c.distance < -0.19);
  }
}

TEST_CASE("primitives and composites reject bad input naming the argument", "[geometry]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  CHECK_THROWS_WITH(Primitive::sphere(Vec3(nan, 0, 0), 1.0), Catch::StartsWith("centre"));
  CHECK_THROWS_WITH(Primitive::sphere(Vec3::Zero(), 0.0), Catch::StartsWith("radius"));
  CHECK_THROWS_WITH(Primitive::capsule(Vec3::Zero(), Vec3(nan, 0, 0), 1.0), Catch::StartsWith("b"));
  CHECK_THROWS_WITH(Primitive::box(T, Vec3(1, -1, 1)), Catch::StartsWith("half"));
  CHECK_THROWS_WITH(Primitive::cylinder(T, 1.0, -0.5), Catch::StartsWith("half_height"));
  T.translation().x() = nan;
  CHECK_THROWS_WITH(Primitive::cylinder(T, 1.0, 0.5), Catch::StartsWith("pose"));
  Primitive broken;
  broken.size = Vec3(-1, 0, 0);
  CHECK_THROWS_AS(Composite({broken}), invalid_argument);
  CHECK_THROWS_WITH(Composite({broken}), Catch::StartsWith("parts"));
}

// Found by fuzz/narrow_phase
// (fuzz/regressions/narrow_phase/signed_distance_coincident_boxes_positive): two boxes with the
// same centre whose faces coincide (rotations equal up to 7e-13) stalled GJK on a flat simplex
// through the origin, and the overlap of 2 mm came out as a separation of +3.6e-11 m.
TEST_CASE("signed_distance of boxes with coinciding centres and faces is their overlap",
          "[geometry][signed_distance]") {
  Primitive a;
  a.type = ShapeType::box;
  a.p = Vec3(-3.0, -3.0, -3.0);
  a.R << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  a.size = Vec3(0.001, 0.0010000000004173116, 1.5218078431372548);
  Primitive b = a;
  b.size = Vec3(0.001, 0.001, 0.001);
  b.R << -6.8967054289714724e-13, 6.8961503174591599e-13, 1, 1, -6.8967054289714724e-13,
      6.8961503174591599e-13, 6.8961503174591599e-13, 1, -6.8967054289714724e-13;
  const Contact c = signed_distance(a, b);
  CHECK(c.distance == Approx(-0.002).margin(1e-6));
  // The same with exactly equal rotations, and offset along the long axis.
  Primitive e = b;
  e.R = a.R;
  CHECK(signed_distance(a, e).distance == Approx(-0.002).margin(1e-6));
  e.p += 0.5 * a.R.col(2);
  CHECK(signed_distance(a, e).distance == Approx(-0.002).margin(1e-6));
}

namespace {

// The pairs fuzz_narrow_phase found: a bar of half extents \p size at \p p turned by \p R, and
// a 2 mm cube at (-3, -3, -3) with its axes permuted (to 1e-12).
std::pair<Primitive, Primitive> bar_and_cube(const Vec3& size, const Vec3& p, const Mat3& R) {
  Primitive bar, cube;
  bar.type = cube.type = ShapeType::box;
  bar.size = size;
  bar.p = p;
  bar.R = R;
  cube.size = Vec3(0.001, 0.001, 0.001);
  cube.p = Vec3(-3, -3, -3);
  const double e1 = -6.8967054289714724e-13, e2 = 6.8961503174591599e-13;
  cube.R << e1, e2, 1, 1, e1, e2, e2, 1, e1;
  return {bar, cube};
}

}  // namespace

TEST_CASE("a flat GJK simplex through the origin still gives the overlap's depth",
          "[geometry][signed_distance]") {
  // Found by fuzz_narrow_phase (fuzz/regressions/narrow_phase/epa_flat_simplex_zero_depth): a
  // 2 mm cube inside a 2 mm x 2 mm x 3 m bar, same centre, axes permuted; GJK ended on a triangle
  // along the bar's diagonal, EPA's tetrahedron missed the origin, and the distance was 0.
  Mat3 R;
  R << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  const auto [a, b] = bar_and_cube(Vec3(0.001, 0.0010000000004173116, 1.5218078431372548),
                                   Vec3(-3, -2.9999999999562803, -3), R);
  CHECK(signed_distance(a, b).distance == Approx(-0.002).margin(1e-9));
  CHECK(signed_distance(b, a).distance == Approx(-0.002).margin(1e-9));
}

TEST_CASE("two overlapping boxes are as deep as their least overlap over the 15 axes",
          "[geometry][signed_distance]") {
  // Found by fuzz_narrow_phase (fuzz/regressions/narrow_phase/epa_short_box_depth): a 2 mm cube
  // across a 2 mm x 2 mm x 3 m bar, turned; EPA stopped at 1.85 mm, short of the depth, 2.393 mm
  // along the cross product of the two boxes' third axes (computed apart from the library, from
  // the 15 axes' overlaps).
  Mat3 R;
  R << -0.22175199524464206, -0.93063141796337345, 0.29112062191555726, 0.29112057727957635,
      0.22175205384198138, 0.93063141796377646, -0.93063143192642395, 0.29112057728086432,
      0.22175199524295142;
  const auto [a, b] =
      bar_and_cube(Vec3(0.001, 0.001, 1.5218078431372548), Vec3(-3, -2.9999306201893297, -3), R);
  const Contact ab = signed_distance(a, b), ba = signed_distance(b, a);
  CHECK(ab.distance == Approx(-0.002393032680916147).margin(1e-9));
  CHECK(ba.distance == Approx(-0.002393032680916147).margin(1e-9));
  CHECK(ab.normal.dot(ba.normal) == Approx(-1.0).margin(1e-9));
  // Moving B out along the normal by the depth and 0.1 mm more leaves them 0.1 mm apart.
  Primitive moved = b;
  moved.p += (0.002393032680916147 + 1e-4) * ab.normal;
  CHECK(signed_distance(a, moved).distance == Approx(1e-4).margin(1e-9));
  CHECK((ab.point_b - ab.point_a - ab.distance * ab.normal).norm() < 1e-10);
}

TEST_CASE("a capsule whose core is inside a box is as deep as the core's way out plus its radius",
          "[geometry][signed_distance]") {
  // Found by fuzz_narrow_phase (fuzz/regressions/narrow_phase/epa_capsule_core_inside_box): a
  // capsule of zero length (radius 1 mm) at the centre of a 2.06 x 2.01 mm x 3 m bar; GJK ended
  // on a flat simplex, EPA found no answer and the depth read 0 (distance -1 mm, the radius).
  // Its core leaves the bar across the nearer long face: 1.007 mm, plus the radius.
  Primitive bar;
  bar.type = ShapeType::box;
  bar.size = Vec3(0.0010305023193430394, 0.00100700132893581, 1.5218078431372548);
  bar.p = Vec3(-2.9999999985157046, -3, -3);
  bar.R << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  const Primitive point = Primitive::capsule(Vec3(-3, -3, -3), Vec3(-3, -3, -3), 0.001);
  const double depth = 0.00100700132893581 + 0.001;
  const Contact ab = signed_distance(bar, point), ba = signed_distance(point, bar);
  CHECK(ab.distance == Approx(-depth).margin(1e-9));
  CHECK(ba.distance == Approx(-depth).margin(1e-9));
  // The bar's second axis is the world's z: the way out is along +-z.
  CHECK(std::abs(ab.normal.z()) == Approx(1.0).margin(1e-9));

  // A 10 mm segment across the bar, tilted 30 degrees from the bar's short side in the bar's
  // x-y plane: its core leaves along the bar's first axis by the larger end's reach, and the
  // answer is the same as the least over the box's three axes and the segment's crossings.
  const double half = 0.005, tilt = std::numbers::pi / 6.0;
  const Vec3 along = std::cos(tilt) * bar.R.col(0) + std::sin(tilt) * bar.R.col(1);
  const Primitive rod =
      Primitive::capsule(Vec3(bar.p - half * along), Vec3(bar.p + half * along), 0.0005);
  // Along the bar's first axis the segment reaches half*cos(tilt) beyond the centre; the
  // Minkowski difference's extent there is a0 + half*cos(tilt); along the second axis
  // a1 + half*sin(tilt); along the third axis a2 (the segment is flat in it). Along the normal of
  // the face swept by the bar's third edge and the segment (in the bar's x-y plane, across the
  // segment), the segment has no extent and the bar reaches a0*sin + a1*cos.
  const double a0 = bar.size[0], a1 = bar.size[1], a2 = bar.size[2];
  const double expected = std::min({a0 + half * std::cos(tilt), a1 + half * std::sin(tilt), a2,
                                    a0 * std::sin(tilt) + a1 * std::cos(tilt)});
  CHECK(signed_distance(bar, rod).distance == Approx(-expected - 0.0005).margin(1e-9));
  CHECK(signed_distance(rod, bar).distance == Approx(-expected - 0.0005).margin(1e-9));
}

TEST_CASE("a small cube deep inside a large cylinder leaves it through the nearer cap",
          "[geometry][signed_distance]") {
  // Found by fuzz_narrow_phase (fuzz/regressions/narrow_phase/epa_unconverged_cylinder_depth): a
  // 2 mm cube 2.3 cm off the centre of a cylinder of radius and half height 2 m, along its axis;
  // EPA stopped at 1.63 m when a new face on the cap (coplanar with a kept one to 1e-10 m, the
  // cylinder being tilted by 1e-10) came out folded. The way out is through the nearer cap:
  // h_A(-axis) + h_B(axis), 1.9776 m (the side is about 2 m away).
  Primitive a, b;
  a.type = ShapeType::cylinder;
  a.size = Vec3(1.9999999967420008, 1.9999666380886756, 0);
  a.p = Vec3(-3, -2.9766536965034716, -2.9999547586776316);
  a.R << -1.6985790551871105e-10, 0.99999999999999989, 6.2972627112856117e-11,
      6.2972627112856117e-11, -6.2972738135158579e-11, 1, 0.99999999999999989,
      1.6985796102986228e-10, -6.2972738135158579e-11;
  b.type = ShapeType::box;
  b.size = Vec3(0.001, 0.001, 0.001);
  b.p = Vec3(-3, -3, -3);
  b.R << -4.4408920985006262e-16, 3.8857805861880479e-16, 1, 1, -4.4408920985006262e-16,
      3.8857805861880479e-16, 3.8857805861880479e-16, 1, -4.4408920985006262e-16;
  const Vec3 axis = a.R.col(2);
  const double depth = support(a, -axis) + support(b, axis);
  CHECK(depth == Approx(1.9776203).margin(1e-6));
  const Contact ab = signed_distance(a, b), ba = signed_distance(b, a);
  CHECK(ab.distance == Approx(-depth).margin(1e-9));
  CHECK(ba.distance == Approx(-depth).margin(1e-9));
  CHECK(-ab.distance == Approx(oracle_depth(a, b)).margin(1e-6));
  CHECK(std::abs(ab.normal.dot(axis)) == Approx(1.0).margin(1e-9));
}

// SPDX-License-Identifier: BSD-3-Clause
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include <catch2/catch.hpp>

#include <topograsp/task/winding.hpp>

using topograsp::Vec3;
using topograsp::winding;

namespace {

std::vector<Vec3> random_curve(std::mt19937& rng, int n) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec3> x(static_cast<std::size_t>(n));
  for (auto& v : x) v = Vec3(g(rng), g(rng), g(rng));
  return x;
}

// A closed planar star-shaped curve in the plane z = z0 through p's plane when z0 = p.z, winding
// k times monotonically around p.
std::vector<Vec3> planar_loop(const Vec3& p, int k, int per_turn) {
  std::vector<Vec3> x;
  const int n = k * per_turn;
  for (int i = 0; i <= n; ++i) {
    const double t = topograsp::two_pi * i / per_turn;
    const double r = 1.0 + 0.4 * std::sin(3.0 * t + 0.3) + 0.1 * std::cos(7.0 * t);
    x.push_back(p + Vec3(r * std::cos(t), r * std::sin(t), 0.0));
  }
  x.back() = x.front();
  return x;
}

}  // namespace

TEST_CASE("a planar closed curve winding k times around p gives k", "[task][winding]") {
  const Vec3 p(0.3, -1.2, 2.0);
  for (int k = 1; k <= 3; ++k) {
    for (int per_turn : {3, 7, 50}) {
      const auto x = planar_loop(p, k, per_turn);
      CHECK(winding(x, p) == Approx(k).margin(1e-12));
    }
  }
}

TEST_CASE("a closed curve not around p nor through its plane gives less than 1",
          "[task][winding]") {
  const Vec3 p(0, 0, 0);
  auto x = planar_loop(Vec3(5, 0, 0), 1, 40);
  // Far away the curve subtends small angles; going around a loop beside p does not wrap it.
  CHECK(winding(x, p) < 1.0);
  CHECK(winding(x, p) > 0.0);
}

TEST_CASE("winding is invariant under rotation, translation and scaling about p",
          "[task][winding]") {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const auto x = random_curve(rng, 2 + trial);
    const Vec3 p = random_curve(rng, 1)[0];
    const double w = winding(x, p);
    const Eigen::Matrix3d R = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    const Vec3 t = random_curve(rng, 1)[0] * 10.0;
    const double s = std::exp(std::uniform_real_distribution<double>(-5, 5)(rng));
    std::vector<Vec3> rotated, moved, scaled;
    for (const Vec3& v : x) {
      rotated.push_back(p + R * (v - p));
      moved.push_back(v + t);
      scaled.push_back(p + s * (v - p));
    }
    CHECK(winding(rotated, p) == Approx(w).margin(1e-12));
    CHECK(winding(moved, Vec3(p + t)) == Approx(w).margin(1e-12));
    CHECK(winding(scaled, p) == Approx(w).margin(1e-12));
  }
}

TEST_CASE("a straight segment far from p gives nearly 0", "[task][winding]") {
  const std::vector<Vec3> x{Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0)};
  const double w = winding(x, Vec3(0, 1000, 0));
  CHECK(w > 0.0);
  CHECK(w == Approx(1.0 / (topograsp::two_pi * 1000.0)).epsilon(1e-6));
  // Seen from a point on its own line a segment subtends no angle at all.
  CHECK(winding(x, Vec3(3, 0, 0)) == 0.0);
}

TEST_CASE("a straight segment through p's far side gives one half", "[task][winding]") {
  const std::vector<Vec3> x{Vec3(-1e6, 1, 0), Vec3(1e6, 1, 0)};
  CHECK(winding(x, Vec3(0, 0, 0)) == Approx(0.5).margin(1e-6));
}

TEST_CASE("reversing the curve leaves the winding unchanged", "[task][winding]") {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 10; ++trial) {
    auto x = random_curve(rng, 9);
    const Vec3 p = random_curve(rng, 1)[0];
    const double w = winding(x, p);
    std::reverse(x.begin(), x.end());
    CHECK(winding(x, p) == Approx(w).margin(1e-14));
  }
}

TEST_CASE("concatenating curves adds their windings", "[task][winding]") {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 10; ++trial) {
    const auto a = random_curve(rng, 6);
    auto b = random_curve(rng, 5);
    b.front() = a.back();
    const Vec3 p = random_curve(rng, 1)[0];
    std::vector<Vec3> ab = a;
    ab.insert(ab.end(), b.begin() + 1, b.end());
    CHECK(winding(ab, p) == Approx(winding(a, p) + winding(b, p)).margin(1e-13));
  }
}

TEST_CASE("a vertex at p contributes no angle", "[task][winding]") {
  const Vec3 p(1, 2, 3);
  const std::vector<Vec3> x{p + Vec3(1, 0, 0), p, p + Vec3(0, 1, 0), p + Vec3(-1, 0, 0)};
  const double w = winding(x, p);
  REQUIRE(std::isfinite(w));
  // Only the segment from (0,1,0) to (-1,0,0) counts: a quarter turn.
  CHECK(w == Approx(0.25).margin(1e-15));
  std::array<Vec3, 4> g;
  const double wg = topograsp::winding_gradient(x, p, g);
  CHECK(wg == w);
  for (const Vec3& v : g) CHECK(v.allFinite());
  CHECK(g[1].isZero());
  // Consecutive equal points (a zero-length segment) add nothing either.
  const std::vector<Vec3> y{p + Vec3(1, 0, 0), p + Vec3(1, 0, 0), p + Vec3(0, 1, 0)};
  CHECK(winding(y, p) == Approx(0.25).margin(1e-15));
}

TEST_CASE("winding accepts any contiguous range of vectors", "[task][winding]") {
  const std::array<Vec3, 3> a{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0)};
  const std::vector<Vec3> v(a.begin(), a.end());
  const std::span<const Vec3> s(a);
  const Vec3 p = Vec3::Zero();
  CHECK(winding(a, p) == Approx(0.5));
  CHECK(winding(v, p) == winding(a, p));
  CHECK(winding(s, p) == winding(a, p));
}

TEST_CASE("the winding gradient matches central differences", "[task][winding]") {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 30; ++trial) {
    auto x = random_curve(rng, 2 + trial % 9);
    const Vec3 p = random_curve(rng, 1)[0];
    std::vector<Vec3> g(x.size());
    const double w = topograsp::winding_gradient(x, p, g);
    CHECK(w == winding(x, p));
    const double h = 1e-6;
    Vec3 gp = Vec3::Zero();
    for (std::size_t i = 0; i < x.size(); ++i) {
      gp -= g[i];
      for (int k = 0; k < 3; ++k) {
        auto xp = x, xm = x;
        xp[i][k] += h;
        xm[i][k] -= h;
        const double fd = (winding(xp, p) - winding(xm, p)) / (2 * h);
        CHECK(g[i][k] == Approx(fd).margin(1e-7));
      }
    }
    // The gradient with respect to p is minus the sum of the vertex gradients.
    for (int k = 0; k < 3; ++k) {
      Vec3 pp = p, pm = p;
      pp[k] += h;
      pm[k] -= h;
      CHECK(gp[k] == Approx((winding(x, pp) - winding(x, pm)) / (2 * h)).margin(1e-7));
    }
  }
}

TEST_CASE("the winding of nearly straight and nearly folded angles stays accurate",
          "[task][winding]") {
  // acos of a normalised dot product loses about half the digits here; atan2 does not.
  const double e = 1e-9;
  const std::vector<Vec3> straight{Vec3(1, 0, 0), Vec3(1, e, 0)};
  CHECK(winding(straight, Vec3::Zero()) * topograsp::two_pi == Approx(e).epsilon(1e-6));
  const std::vector<Vec3> folded{Vec3(1, 0, 0), Vec3(-1, e, 0)};
  CHECK(topograsp::pi - winding(folded, Vec3::Zero()) * topograsp::two_pi ==
        Approx(e).epsilon(1e-6));
}

TEST_CASE("winding rejects bad input naming the argument", "[task][winding]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Vec3> one{Vec3(1, 0, 0)};
  const std::vector<Vec3> none;
  const std::vector<Vec3> bad{Vec3(1, 0, 0), Vec3(nan, 0, 0)};
  const std::vector<Vec3> good{Vec3(1, 0, 0), Vec3(0, 1, 0)};
  using topograsp::invalid_argument;
  CHECK_THROWS_AS(winding(none, Vec3::Zero()), invalid_argument);
  CHECK_THROWS_WITH(winding(one, Vec3::Zero()), Catch::StartsWith("points"));
  CHECK_THROWS_WITH(winding(bad, Vec3::Zero()), Catch::StartsWith("points"));
  CHECK_THROWS_WITH(winding(good, Vec3(0, inf, 0)), Catch::StartsWith("p:"));
  std::vector<Vec3> g(3);
  CHECK_THROWS_WITH(topograsp::winding_gradient(good, Vec3::Zero(), g),
                    Catch::StartsWith("gradient"));
  CHECK_THROWS_AS(topograsp::winding_gradient(bad, Vec3::Zero(), std::span<Vec3>(g).first(2)),
                  invalid_argument);
}

TEST_CASE("winding and its gradient are scale-invariant over the whole finite range",
          "[task][winding]") {
  // A unit square around p (closed), tilted so that no coordinate is zero, and an axis-aligned
  // one: at 1e200 the axis-aligned square's gradient used to be NaN and the tilted one's value
  // NaN; at 1e-170 and 1e-300 the value used to be 0.
  const Vec3 p(0.1, -0.2, 0.05);
  const std::vector<Vec3> axis{Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0), Vec3(1, -1, 0),
                               Vec3(1, 1, 0)};
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  std::vector<Vec3> tilted;
  for (const Vec3& x : axis) tilted.push_back(R * (x + Vec3(0.2, -0.1, 0.0)));
  for (const std::vector<Vec3>* curve : {&axis, static_cast<const std::vector<Vec3>*>(&tilted)}) {
    std::vector<Vec3> g0(curve->size());
    const double w0 = topograsp::winding_gradient(*curve, Vec3::Zero(), g0);
    CHECK(w0 == Approx(1.0).margin(1e-12));
    for (const double scale :
         {1e-300, 1e-250,   1e-200,   1e-170,   1e-150,  1e-100,  1e-50,  1e-10,
          0.3,    1e10,     1e50,     1e100,    1e150,   1e170,   1e200,  1e250,
          1e300,  0x1p-251, 0x1p-250, 0x1p-249, 0x1p249, 0x1p250, 0x1p251}) {
      CAPTURE(scale);
      std::vector<Vec3> x;
      for (const Vec3& v : *curve) x.push_back(scale * v);
      std::vector<Vec3> g(x.size());
      const double w = topograsp::winding_gradient(x, Vec3::Zero(), g);
      REQUIRE(std::isfinite(w));
      CHECK(w == Approx(w0).margin(1e-13));
      CHECK(winding(x, Vec3::Zero()) == Approx(w0).margin(1e-13));
      for (std::size_t i = 0; i < x.size(); ++i)
        for (int k = 0; k < 3; ++k) {
          REQUIRE(std::isfinite(g[i][k]));
          // d w / d x scales as 1 / scale.
          CHECK(g[i][k] * scale == Approx(g0[i][k]).margin(1e-12));
        }
    }
    // Not scaled about the origin: p inside the square too.
    for (const double scale : {1e-300, 1e-170, 1e170, 1e300}) {
      std::vector<Vec3> x;
      for (const Vec3& v : *curve) x.push_back(scale * (v + p));
      CHECK(winding(x, scale * p) == Approx(w0).margin(1e-12));
    }
  }
}

TEST_CASE("winding is unchanged by a translation far from the origin", "[task][winding]") {
  // Power-of-two offsets keep X_i - p exact, so the value must not move at all beyond rounding.
  const std::vector<Vec3> square{Vec3(1, 1, 0.25), Vec3(-1, 1, 0.25), Vec3(-1, -1, -0.25),
                                 Vec3(1, -1, 0.25), Vec3(1, 1, 0.25)};
  const Vec3 p(0.125, 0.25, 0.0);
  const double w0 = winding(square, p);
  for (const double scale : {1e-250, 1.0, 1e250})
    for (const double offset : {0x1p20, 0x1p40}) {
      CAPTURE(scale, offset);
      const Vec3 t = Vec3(offset, -offset, 0.5 * offset) * scale;
      std::vector<Vec3> x;
      for (const Vec3& v : square) x.push_back(scale * v + t);
      std::vector<Vec3> g(x.size());
      const double w = topograsp::winding_gradient(x, scale * p + t, g);
      CHECK(w == Approx(w0).margin(1e-12));
      for (const Vec3& gi : g) CHECK(gi.allFinite());
    }
  // The largest coordinates: the square of size 2^1000 around 2^1020.
  std::vector<Vec3> x;
  for (const Vec3& v : square) x.push_back(0x1p1000 * v + Vec3::Constant(0x1p1020));
  CHECK(winding(x, 0x1p1000 * p + Vec3::Constant(0x1p1020)) == Approx(w0).margin(1e-12));
}

TEST_CASE("winding refuses points whose offset from p overflows", "[task][winding]") {
  const double big = std::numeric_limits<double>::max();
  const std::vector<Vec3> x{Vec3(big, 0, 0), Vec3(0, big, 0)};
  CHECK_THROWS_WITH(winding(x, Vec3(-big, 0, 0)),
                    Catch::StartsWith("points") && Catch::Contains("point 0 minus p overflows"));
  // Subnormal offsets count as a vertex at p: finite, zero.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<Vec3> t{Vec3(tiny, 0, 0), Vec3(0, tiny, 0), Vec3(-tiny, 0, 0)};
  std::vector<Vec3> g(3);
  CHECK(topograsp::winding_gradient(t, Vec3::Zero(), g) == 0.0);
  for (const Vec3& gi : g) CHECK(gi.isZero(0.0));
}

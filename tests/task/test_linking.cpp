// SPDX-License-Identifier: BSD-3-Clause
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task/hand_curve.hpp>
#include <topograsp/task/linking.hpp>
#include <topograsp/task/writhe_task.hpp>

#include "support/finite_diff.hpp"
#include "support/random.hpp"

using namespace topograsp;

namespace {

std::vector<Vec3> circle(const Vec3& c, const Vec3& u, const Vec3& v, double r, int n) {
  std::vector<Vec3> x;
  for (int i = 0; i < n; ++i) {
    const double t = two_pi * i / n;
    x.push_back(c + r * (std::cos(t) * u + std::sin(t) * v));
  }
  return x;
}

// A (p, q) curve on the torus of radii R, r: p turns around the axis, q around the tube, starting
// at tube angle theta0. Two of them half a tube turn apart make the (2p, 2q) torus link.
std::vector<Vec3> torus_curve(int p, int q, double theta0, int n) {
  std::vector<Vec3> x;
  const double R = 2.0, r = 0.7;
  for (int i = 0; i < n; ++i) {
    const double t = two_pi * i / n;
    const double phi = p * t, theta = q * t + theta0;
    x.push_back(Vec3((R + r * std::cos(theta)) * std::cos(phi),
                     (R + r * std::cos(theta)) * std::sin(phi), r * std::sin(theta)));
  }
  return x;
}

}  // namespace

TEST_CASE("the segment linking integral matches numerical quadrature", "[task][linking]") {
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    const Vec3 p1(g(rng), g(rng), g(rng)), p2(g(rng), g(rng), g(rng));
    const Vec3 p3(g(rng), g(rng), g(rng)), p4(g(rng), g(rng), g(rng));
    const int n = 600;
    double s = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Vec3 ra = p1 + (i + 0.5) / n * (p2 - p1), rb = p3 + (j + 0.5) / n * (p4 - p3);
        const Vec3 dr = ra - rb;
        s += dr.dot((p2 - p1).cross(p4 - p3)) / std::pow(dr.norm(), 3);
      }
    s /= n * n * 4.0 * pi;
    CHECK(segment_linking(p1, p2, p3, p4) == Approx(s).epsilon(1e-3).margin(1e-5));
  }
}

TEST_CASE("linking numbers: Hopf link, unlinked rings, (2,4) torus link", "[task][linking]") {
  SECTION("Hopf link is +-1, the sign set by orientation") {
    const auto a = circle(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 1.0, 40);
    auto b = circle(Vec3(1, 0, 0), Vec3::UnitX(), Vec3::UnitZ(), 1.0, 37);
    const double lk = linking_number(a, b);
    CHECK(std::abs(lk) == Approx(1.0).margin(1e-10));
    CHECK(linking_number(b, a) == Approx(lk).margin(1e-10));
    std::reverse(b.begin(), b.end());
    CHECK(linking_number(a, b) == Approx(-lk).margin(1e-10));
  }
  SECTION("unlinked rings give 0") {
    const auto a = circle(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 1.0, 30);
    const auto b = circle(Vec3(3, 0, 0), Vec3::UnitX(), Vec3::UnitZ(), 1.0, 30);
    const auto c = circle(Vec3(0, 0, 0.5), Vec3::UnitX(), Vec3::UnitY(), 2.0, 30);  // stacked
    CHECK(linking_number(a, b) == Approx(0.0).margin(1e-10));
    CHECK(linking_number(a, c) == Approx(0.0).margin(1e-10));
  }
  SECTION("the (2,4) torus link is +-2") {
    const auto a = torus_curve(1, 2, 0.0, 200), b = torus_curve(1, 2, pi, 200);
    CHECK(std::abs(linking_number(a, b)) == Approx(2.0).margin(1e-9));
  }
  SECTION("the writhe matrix of closed curves sums to the linking number") {
    auto a = circle(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 1.0, 12);
    auto b = circle(Vec3(1, 0, 0), Vec3::UnitX(), Vec3::UnitZ(), 1.0, 9);
    const double lk = linking_number(a, b);
    a.push_back(a.front());
    b.push_back(b.front());
    const MatX W = writhe_matrix(a, b);
    CHECK(W.rows() == 12);
    CHECK(W.cols() == 9);
    CHECK(W.sum() == Approx(lk).margin(1e-12));
  }
}

TEST_CASE("the segment linking gradient matches central differences", "[task][linking]") {
  std::mt19937 rng(6);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::array<Vec3, 4> p;
    for (Vec3& x : p) x = Vec3(g(rng), g(rng), g(rng));
    std::array<Vec3, 4> grad;
    const double w = segment_linking(p[0], p[1], p[2], p[3], &grad);
    CHECK(w == segment_linking(p[0], p[1], p[2], p[3]));
    for (std::size_t k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) {
        auto pp = p, pm = p;
        pp[k][c] += 1e-6;
        pm[k][c] -= 1e-6;
        const double fd = (segment_linking(pp[0], pp[1], pp[2], pp[3]) -
                           segment_linking(pm[0], pm[1], pm[2], pm[3])) /
                          2e-6;
        CHECK(grad[k][c] == Approx(fd).margin(1e-7));
      }
  }
}

TEST_CASE("touching segments contribute 0 without NaN", "[task][linking]") {
  std::array<Vec3, 4> g;
  const double w = segment_linking(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 1, 0), &g);
  CHECK(w == 0.0);
  for (const Vec3& v : g) CHECK(v.allFinite());
  CHECK(std::isfinite(segment_linking(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0))));
}

TEST_CASE("the writhe task Jacobian matches central differences", "[task][linking]") {
  std::mt19937 rng(8);
  const auto check_model = [&]<const auto & M>() {
    constexpr auto chain = hand_curve_chain<M, 0>();
    KinematicsData<M> d;
    for (int trial = 0; trial < 5; ++trial) {
      const Vec<M.nq> q = test::random_configuration<M>(rng);
      forward_kinematics(d, q);
      // A bar through the hand, near the palm centre.
      const Vec3 c = world_point(d, M.palm);
      std::normal_distribution<double> g(0.0, 0.05);
      const std::array<Vec3, 3> bar{c + Vec3(g(rng), g(rng), g(rng)) + Vec3(0.2, 0, 0),
                                    c + Vec3(g(rng), g(rng), g(rng)),
                                    c + Vec3(g(rng), g(rng), g(rng)) - Vec3(0.2, 0, 0)};
      const WritheTask<M, chain.size(), 3> task(chain, bar);
      INFO(M.name.view() << " trial " << trial);
      CHECK(test::jacobian_error(task, q) < 1e-6);
      CHECK(test::numeric_jacobian(task, q).cwiseAbs().maxCoeff() > 1e-4);
    }
  };
  check_model.operator()<models::schunk_sdh>();
  check_model.operator()<models::human_hand>();
  check_model.operator()<models::barrett_bh8>();
  check_model.operator()<models::schunk_arm_sdh>();
  check_model.operator()<models::human_hand_free>();
}

TEST_CASE("linking functions reject bad input naming the argument", "[task][linking]") {
  const std::vector<Vec3> one{Vec3::Zero()};
  const std::vector<Vec3> ok{Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()};
  const std::vector<Vec3> bad{Vec3::Zero(), Vec3(std::nan(""), 0, 0)};
  CHECK_THROWS_WITH(linking_number(one, ok), Catch::StartsWith("a"));
  CHECK_THROWS_WITH(linking_number(ok, bad), Catch::StartsWith("b"));
  CHECK_THROWS_WITH(writhe_matrix(ok, one), Catch::StartsWith("b"));
  constexpr auto& M = models::schunk_sdh;
  constexpr auto chain = hand_curve_chain<M, 0>();
  std::array<Vec3, 2> curve{Vec3::Zero(), Vec3(std::nan(""), 0, 0)};
  CHECK_THROWS_WITH((WritheTask<M, chain.size(), 2>(chain, curve)), Catch::StartsWith("curve"));
  auto broken = chain;
  broken[1].link = 99;
  curve[1] = Vec3::UnitX();
  CHECK_THROWS_WITH((WritheTask<M, chain.size(), 2>(broken, curve)), Catch::StartsWith("chain"));
}

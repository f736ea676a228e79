// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <cmath>

#include <topograsp/kinematics/least_squares.hpp>

using namespace topograsp;

namespace {

// A nonlinear residual with a known minimum: e(x) = (x0^2 - 4, x1 - 1, x0 x1 - 2), zero at
// x = (2, 1); counts its evaluations.
struct Problem {
  int evaluations = 0;
  Vec2 at;  // the point of the last evaluation
  double operator()(const Vec2& x, Vec3& e) {
    ++evaluations;
    at = x;
    e << x[0] * x[0] - 4.0, x[1] - 1.0, x[0] * x[1] - 2.0;
    return e.squaredNorm();
  }
  void jacobian(Mat<3, 2>& J) const { J << 2.0 * at[0], 0.0, 0.0, 1.0, at[1], at[0]; }
};

BoundedLeastSquaresResult fit(Problem& p, Vec2& x, Vec3& e, const Vec2& lo, const Vec2& hi,
                              const BoundedLeastSquaresOptions& o) {
  Mat<3, 2> J;
  const double cost = p(x, e);
  return bounded_least_squares(
      x, e, cost, lo, hi, [&](const Vec2& y, Vec3& ey) { return p(y, ey); },
      [&](Mat<3, 2>& Jt) { p.jacobian(Jt); }, J, o);
}

}  // namespace

TEST_CASE("bounded least squares reaches an interior minimum", "[kinematics][least_squares]") {
  Problem p;
  Vec2 x(3.0, 3.0);
  Vec3 e;
  BoundedLeastSquaresOptions o;
  o.iterations = 200;
  o.settled = 1e-20;
  const auto r = fit(p, x, e, Vec2(-10, -10), Vec2(10, 10), o);
  CHECK(x[0] == Approx(2.0).margin(1e-6));
  CHECK(x[1] == Approx(1.0).margin(1e-6));
  CHECK(r.cost < 1e-12);
  CHECK(r.cost == Approx(e.squaredNorm()));
  CHECK(r.accepted >= 1);
  CHECK(r.accepted <= r.iterations);
  CHECK(r.iterations <= 200);
}

TEST_CASE("bounded least squares keeps every step within the bounds",
          "[kinematics][least_squares]") {
  Problem p;
  Vec2 x(3.0, 0.0);
  Vec3 e;
  // x0 may not go below 2.5: the constrained minimum lies on that bound.
  const Vec2 lo(2.5, -10.0), hi(10.0, 10.0);
  BoundedLeastSquaresOptions o;
  o.iterations = 200;
  const auto r = fit(p, x, e, lo, hi, o);
  CHECK(x[0] == Approx(2.5));
  CHECK(x[1] >= lo[1]);
  CHECK(r.cost > 0.1);  // the bound keeps it from the unconstrained minimum
  CHECK(r.accepted >= 1);
}

TEST_CASE("bounded least squares leaves a minimum where it is and restores the kinematics",
          "[kinematics][least_squares]") {
  Problem p;
  Vec2 x(2.0, 1.0);
  Vec3 e;
  BoundedLeastSquaresOptions o;
  o.iterations = 5;
  const auto r = fit(p, x, e, Vec2(-10, -10), Vec2(10, 10), o);
  CHECK(r.accepted == 0);
  CHECK(r.iterations == 5);
  CHECK(x == Vec2(2.0, 1.0));
  CHECK(r.cost == 0.0);
  // After each rejected step the residual was evaluated at x again.
  CHECK(p.at == x);
}

TEST_CASE("bounded least squares stops when the damping passes its cap",
          "[kinematics][least_squares]") {
  Problem p;
  Vec2 x(2.0, 1.0);  // the minimum: every step is rejected, the damping grows tenfold each time
  Vec3 e;
  BoundedLeastSquaresOptions o;
  o.iterations = 100;
  o.max_damping = 1.0;  // 1e-3 -> 1e-2 -> 1e-1 -> 1 -> 10: the fourth rejection stops it
  const auto r = fit(p, x, e, Vec2(-10, -10), Vec2(10, 10), o);
  CHECK(r.accepted == 0);
  CHECK(r.iterations == 4);
}

TEST_CASE("bounded least squares takes no step with zero iterations",
          "[kinematics][least_squares]") {
  Problem p;
  Vec2 x(3.0, 3.0);
  Vec3 e;
  BoundedLeastSquaresOptions o;
  o.iterations = 0;
  const auto r = fit(p, x, e, Vec2(-10, -10), Vec2(10, 10), o);
  CHECK(r.iterations == 0);
  CHECK(r.accepted == 0);
  CHECK(x == Vec2(3.0, 3.0));
  CHECK(p.evaluations == 1);  // the caller's start only
}

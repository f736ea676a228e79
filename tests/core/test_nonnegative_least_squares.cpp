// SPDX-License-Identifier: BSD-3-Clause
// nonnegative_least_squares() (core/nonnegative_least_squares.hpp): interior and bound-active
// solutions with known answers, the optimality conditions on random problems, bad input.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include <topograsp/core/nonnegative_least_squares.hpp>

using namespace topograsp;

TEST_CASE("nonnegative least squares: an interior minimum is the unconstrained one",
          "[core][nnls]") {
  Eigen::MatrixXd A(3, 2);
  A << 1, 0, 0, 1, 1, 1;
  const Eigen::VectorXd x_true = Eigen::Vector2d(0.5, 2.0);
  const NonnegativeLeastSquares r = nonnegative_least_squares(A, A * x_true);
  CHECK(r.converged);
  CHECK(r.x[0] == Approx(0.5));
  CHECK(r.x[1] == Approx(2.0));
  CHECK(r.residual == Approx(0.0).margin(1e-9));
}

TEST_CASE("nonnegative least squares: a negative unconstrained minimum sits on the bound",
          "[core][nnls]") {
  // min (x0 - 1)^2 + (x1 + 1)^2 over x >= 0: x = (1, 0), residual 1.
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2, 2);
  const NonnegativeLeastSquares r = nonnegative_least_squares(A, Eigen::Vector2d(1.0, -1.0));
  CHECK(r.x[0] == Approx(1.0));
  CHECK(r.x[1] == 0.0);
  CHECK(r.residual == Approx(1.0));
  // A column that only points away from b stays at 0, the other takes the projection.
  Eigen::MatrixXd B(2, 2);
  B << 1, -1, 1, -1;
  const NonnegativeLeastSquares s = nonnegative_least_squares(B, Eigen::Vector2d(2.0, 0.0));
  CHECK(s.x[0] == Approx(1.0));
  CHECK(s.x[1] == 0.0);
  CHECK(s.residual == Approx(std::sqrt(2.0)));
}

TEST_CASE("nonnegative least squares meets its optimality conditions on random problems",
          "[core][nnls]") {
  // Karush-Kuhn-Tucker: x >= 0, the gradient w = A'(b - A x) <= 0 everywhere, and w = 0 where
  // x > 0. Wide and tall problems, as the grasp's (7 + nq rows, 8 columns per contact).
  std::srand(7);
  for (const auto& [rows, cols] : {std::pair{27, 200}, std::pair{12, 5}, std::pair{6, 6}}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::MatrixXd A = Eigen::MatrixXd::Random(rows, cols);
      const Eigen::VectorXd b = Eigen::VectorXd::Random(rows);
      const NonnegativeLeastSquares r = nonnegative_least_squares(A, b);
      INFO(rows << " x " << cols << ", trial " << trial);
      REQUIRE(r.converged);
      CHECK(r.x.minCoeff() >= 0.0);
      const Eigen::VectorXd w = A.transpose() * (b - A * r.x);
      for (int j = 0; j < cols; ++j) {
        CHECK(w[j] <= 1e-9);
        if (r.x[j] > 0.0) CHECK(std::abs(w[j]) <= 1e-9);
      }
      CHECK(r.residual == Approx((A * r.x - b).norm()).margin(1e-9));
    }
  }
}

TEST_CASE("nonnegative least squares: no columns, a zero right-hand side", "[core][nnls]") {
  const NonnegativeLeastSquares empty =
      nonnegative_least_squares(Eigen::MatrixXd(3, 0), Eigen::Vector3d(1, 2, 2));
  CHECK(empty.x.size() == 0);
  CHECK(empty.residual == Approx(3.0));
  const NonnegativeLeastSquares zero =
      nonnegative_least_squares(Eigen::MatrixXd::Random(4, 3), Eigen::VectorXd::Zero(4));
  CHECK(zero.x.isZero());
  CHECK(zero.iterations == 0);
}

TEST_CASE("nonnegative least squares names the argument it rejects", "[core][nnls]") {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2, 2);
  CHECK_THROWS_AS(nonnegative_least_squares(A, Eigen::Vector3d(1, 2, 3)), invalid_argument);
  CHECK_THROWS_WITH(nonnegative_least_squares(A, Eigen::Vector3d(1, 2, 3)),
                    Catch::StartsWith("b: expected a vector of size 2"));
  CHECK_THROWS_WITH(
      nonnegative_least_squares(A, Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 0)),
      Catch::StartsWith("b: expected finite entries"));
  A(1, 0) = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(nonnegative_least_squares(A, Eigen::Vector2d(1, 2)),
                    Catch::StartsWith("A: expected finite entries"));
}

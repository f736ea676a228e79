// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// nonnegative_least_squares(): min |A x - b| over x >= 0 by Lawson and Hanson's active-set
/// method (Solving Least Squares Problems, 1974, chapter 23), for the small dense problems of the
/// library (a grasp's contact forces: docs/evaluation.md, "The balanced hold").
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>

namespace topograsp {

/// What nonnegative_least_squares() found.
struct NonnegativeLeastSquares {
  Eigen::VectorXd x;      ///< the minimiser, every entry >= 0
  double residual = 0.0;  ///< |A x - b|
  int iterations = 0;     ///< columns brought into the passive set
  bool converged = true;  ///< false if the iteration limit (3 x columns) stopped it
};

/// Minimises |A x - b| over x >= 0 (Lawson-Hanson): x starts at 0; while some column not yet
/// used would lower the residual (its entry of the gradient A'(b - A x) is above a tolerance
/// scaled by |A| |b|), it joins the passive set and x is the unconstrained least-squares
/// solution over that set, stepped back to the bound (dropping the columns that reach 0) where
/// an entry would turn negative. For problems of a few hundred columns (each iteration one
/// Cholesky factorisation of the passive columns' normal equations); stops after 3 x columns
/// iterations (converged = false).
/// \throws topograsp::invalid_argument naming "A" or "b" for non-finite entries, or "b" when its
/// size differs from A's rows.
template <class = void>
[[nodiscard]] NonnegativeLeastSquares nonnegative_least_squares(const Eigen::MatrixXd& A,
                                                                const Eigen::VectorXd& b) {
  require_finite(A, "A");
  require_size(b, A.rows(), "b");
  require_finite(b, "b");
  const Eigen::Index n = A.cols();
  NonnegativeLeastSquares out;
  out.x = Eigen::VectorXd::Zero(n);
  if (n == 0 || A.rows() == 0) {  // nothing to choose (and no block of an empty matrix to take)
    out.residual = b.norm();
    return out;
  }
  const double tolerance = 10.0 * std::numeric_limits<double>::epsilon() *
                           std::max<Eigen::Index>(n, A.rows()) * std::max(1.0, A.norm()) *
                           std::max(1.0, b.norm());
  std::vector<bool> passive(static_cast<std::size_t>(n), false);
  std::vector<Eigen::Index> set;
  Eigen::VectorXd x = out.x;
  // The least-squares solution over the passive columns: their normal equations (few: at most
  // A's rows are ever passive at once, and they stay linearly independent) solved by a plain
  // Cholesky factorisation, regularised by a relative 1e-12 on the diagonal. Scalar loops on
  // purpose: Eigen's blocked products, LDLT and QR cost a user's translation unit seconds to
  // compile, for matrices of a few dozen entries.
  Eigen::MatrixXd gram;
  Eigen::VectorXd rhs;
  const auto solve_passive = [&]() {
    const auto p = static_cast<Eigen::Index>(set.size());
    gram.resize(p, p);
    rhs.resize(p);
    for (Eigen::Index i = 0; i < p; ++i) {
      rhs[i] = A.col(set[static_cast<std::size_t>(i)]).dot(b);
      for (Eigen::Index j = 0; j <= i; ++j)
        gram(i, j) =
            A.col(set[static_cast<std::size_t>(i)]).dot(A.col(set[static_cast<std::size_t>(j)]));
    }
    for (Eigen::Index i = 0; i < p; ++i) gram(i, i) *= 1.0 + 1e-12;
    // Cholesky in place (lower triangle), then forward and back substitution.
    for (Eigen::Index j = 0; j < p; ++j) {
      double d = gram(j, j);
      for (Eigen::Index k = 0; k < j; ++k) d -= gram(j, k) * gram(j, k);
      d = std::sqrt(std::max(d, std::numeric_limits<double>::min()));
      gram(j, j) = d;
      for (Eigen::Index i = j + 1; i < p; ++i) {
        double v = gram(i, j);
        for (Eigen::Index k = 0; k < j; ++k) v -= gram(i, k) * gram(j, k);
        gram(i, j) = v / d;
      }
    }
    for (Eigen::Index i = 0; i < p; ++i) {
      for (Eigen::Index k = 0; k < i; ++k) rhs[i] -= gram(i, k) * rhs[k];
      rhs[i] /= gram(i, i);
    }
    for (Eigen::Index i = p - 1; i >= 0; --i) {
      for (Eigen::Index k = i + 1; k < p; ++k) rhs[i] -= gram(k, i) * rhs[k];
      rhs[i] /= gram(i, i);
    }
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < p; ++i) z[set[static_cast<std::size_t>(i)]] = rhs[i];
    return z;
  };
  const int max_iterations = 3 * static_cast<int>(std::max<Eigen::Index>(n, 1));
  while (true) {
    const Eigen::VectorXd r = b - A.lazyProduct(x);
    const Eigen::VectorXd w = A.transpose().lazyProduct(r);
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!passive[static_cast<std::size_t>(j)] && w[j] > tolerance && (best < 0 || w[j] > w[best]))
        best = j;
    if (best < 0) break;
    if (out.iterations == max_iterations) {
      out.converged = false;
      break;
    }
    ++out.iterations;
    passive[static_cast<std::size_t>(best)] = true;
    set.push_back(best);
    Eigen::VectorXd z = solve_passive();
    // Step back towards x until no passive entry is negative, dropping those that reach 0.
    for (int inner = 0; inner < max_iterations; ++inner) {
      double alpha = 1.0;
      bool negative = false;
      for (const Eigen::Index j : set)
        if (z[j] <= 0.0) {
          negative = true;
          alpha = std::min(alpha, x[j] / (x[j] - z[j]));
        }
      if (!negative) break;
      x += alpha * (z - x);
      std::erase_if(set, [&](Eigen::Index j) {
        const bool drop = x[j] <= tolerance;
        if (drop) {
          passive[static_cast<std::size_t>(j)] = false;
          x[j] = 0.0;
        }
        return drop;
      });
      z = set.empty() ? Eigen::VectorXd(Eigen::VectorXd::Zero(n)) : solve_passive();
    }
    x = z;
  }
  out.x = x.cwiseMax(0.0);
  out.residual = (A.lazyProduct(out.x) - b).norm();
  return out;
}

}  // namespace topograsp

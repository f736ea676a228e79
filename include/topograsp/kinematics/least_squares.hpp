// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Bounded Levenberg-Marquardt: the damped least-squares fit of a configuration within its limits,
/// shared by the fingertip mapping (grasp/transfer.hpp) and the keypoint fit
/// (grasp/keypoint_fit.hpp). docs/transfer.md states the iteration.
#pragma once

#include <algorithm>
#include <limits>

#include <Eigen/Cholesky>

#include <topograsp/core/eigen.hpp>

namespace topograsp {

/// When bounded_least_squares() stops, besides a step that cannot lower the cost further.
struct BoundedLeastSquaresOptions {
  int iterations = 100;  ///< trial steps at most
  /// An accepted step that lowers the cost by less than this ends the fit (the fit has settled).
  double settled = 1e-12;
  /// A rejected step that raises the damping above this ends the fit (no step can lower the cost).
  double max_damping = std::numeric_limits<double>::infinity();
};

/// What bounded_least_squares() did.
struct BoundedLeastSquaresResult {
  int iterations = 0;  ///< trial steps taken
  int accepted = 0;    ///< of them, accepted (0: x is where it started)
  double cost = 0.0;   ///< |e|^2 at the final x
};

/// Minimises |e(x)|^2 over lo <= x <= hi by damped Gauss-Newton steps (Levenberg-Marquardt): from
/// the damping 1e-3, each trial step x - (J'J + lambda I)^-1 J'e is clamped to the bounds and taken
/// if it lowers the cost (lambda divided by 3, down to 1e-9), else the damping is multiplied by 10.
///
/// \p x holds the start and receives the fit; \p e the residual at the start and then at the fit;
/// \p cost is |e|^2 at the start. `residual(y, ey)` writes the residual at y into ey and returns
/// |ey|^2; `jacobian(J)` writes the rows of \p J it owns at the point of the last residual
/// evaluation that was kept (rows it does not write, such as a constant prior, keep their values).
/// After a rejected step residual(x, e) is evaluated again, so that the caller's kinematics are
/// those of x. Nothing is checked: the caller passes a finite start and bounds with lo <= hi.
template <int N, int R, class Residual, class Jacobian>
BoundedLeastSquaresResult bounded_least_squares(Vec<N>& x, Vec<R>& e, double cost, const Vec<N>& lo,
                                                const Vec<N>& hi, Residual&& residual,
                                                Jacobian&& jacobian, Mat<R, N>& J,
                                                const BoundedLeastSquaresOptions& options) {
  BoundedLeastSquaresResult out;
  double lambda = 1e-3;
  for (int it = 0; it < options.iterations; ++it) {
    jacobian(J);
    const Mat<N, N> H = J.transpose() * J + lambda * Mat<N, N>::Identity();
    const Vec<N> trial = (x - H.ldlt().solve(J.transpose() * e)).cwiseMax(lo).cwiseMin(hi);
    Vec<R> et;
    const double c = residual(trial, et);
    ++out.iterations;
    if (c < cost) {
      const bool settled = cost - c < options.settled;
      ++out.accepted;
      x = trial;
      e = et;
      cost = c;
      lambda = std::max(lambda / 3.0, 1e-9);
      if (settled) break;
    } else {
      lambda *= 10.0;
      (void)residual(x, e);  // restore the caller's kinematics of x
      if (lambda > options.max_damping) break;
    }
  }
  out.cost = cost;
  return out;
}

}  // namespace topograsp

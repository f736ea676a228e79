// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The dense kernels of the AICO messages and beliefs (internal): in-place Cholesky, the
/// Woodbury-form message update and the damped belief.
#pragma once

#include <Eigen/Cholesky>

#include <topograsp/core/eigen.hpp>

namespace topograsp::detail {

/// Factors the lower triangle of \p m in place as L L'; false if \p m is not positive definite
/// (or has non-finite entries). Allocates nothing.
template <int N>
[[nodiscard]] bool cholesky_in_place(Mat<N, N>& m) noexcept {
  Eigen::LLT<Eigen::Ref<Mat<N, N>>, Eigen::Lower> llt(m);
  return llt.info() == Eigen::Success && m.diagonal().allFinite();
}

/// The message update shared by the forward and backward passes, in place and without inverting
/// \p P (which may be singular, e.g. the task precision alone at the horizon):
///   P   <- P - P (C + P)^-1 P   = (C^-1 + P^-1)^-1
///   eta <- eta - P (C + P)^-1 eta
/// with C positive definite, added to a copy of P by \p add_C. Uses one Cholesky of C + P = L L'
/// and Y = L^-1 P: P - Y'Y (a symmetric rank update), eta - Y' L^-1 eta. False if C + P is not
/// positive definite.
template <int N, class AddC>
[[nodiscard]] bool woodbury_update(Mat<N, N>& P, Vec<N>& eta, Mat<N, N>& L, Mat<N, N>& Y, Vec<N>& z,
                                   const AddC& add_C) noexcept {
  L = P;
  add_C(L);
  if (!cholesky_in_place(L)) return false;
  Y = P;
  L.template triangularView<Eigen::Lower>().solveInPlace(Y);
  z = eta;
  L.template triangularView<Eigen::Lower>().solveInPlace(z);
  eta.noalias() -= Y.transpose() * z;
  P.template selfadjointView<Eigen::Lower>().rankUpdate(Y.transpose(), -1.0);
  P.template triangularView<Eigen::StrictlyUpper>() = P.transpose();
  return true;
}

/// Solves (L L') x = rhs in place in \p rhs with the factor in the lower triangle of \p L.
template <int N>
void cholesky_solve_in_place(const Mat<N, N>& L, Vec<N>& rhs) noexcept {
  L.template triangularView<Eigen::Lower>().solveInPlace(rhs);
  L.template triangularView<Eigen::Lower>().transpose().solveInPlace(rhs);
}

}  // namespace topograsp::detail

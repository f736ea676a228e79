// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The two interfaces the task layer is built on: a TaskVariable (one map phi(q) with its
/// Jacobian) and a TaskStack (what a planner such as AICO consumes: the whitened residual of all
/// tasks at a time step).
#pragma once

#include <concepts>

#include <topograsp/kinematics/data.hpp>

namespace topograsp {

/// A task variable: a map phi from the configuration to R^dim with its exact Jacobian, both read
/// from one forward-kinematics result so that many tasks share one kinematics pass.
///
/// A model of it declares `using Kinematics = KinematicsData<M>;` and `static constexpr int dim`,
/// and provides `value(d)` (phi(q), dim) and `evaluate(d, phi, J)` (phi(q) and dphi/dq, dim x nq),
/// where d was filled by forward_kinematics() at q.
template <class T>
concept TaskVariable =
    requires {
      typename T::Kinematics;
      { T::dim } -> std::convertible_to<int>;
    } && requires(const T& t, const typename T::Kinematics& d, Vec<T::dim>& phi,
                  Mat<T::dim, T::Kinematics::nq>& J) {
      { t.value(d) } -> std::same_as<Vec<T::dim>>;
      { t.evaluate(d, phi, J) } -> std::same_as<void>;
    };

/// A stack of tasks with their targets and precisions over a horizon of T steps, as a planner
/// sees it: at step t (0..T) the whitened residual e and its Jacobian J (dim x nq), so that the
/// cost of the step is |e|^2 = sum_i rho_i(t) |phi_i(q) - y*_i(t)|^2 and the Gauss-Newton terms
/// are J'J and J'(J q - e).
template <class S>
concept TaskStack =
    requires {
      typename S::Kinematics;
      { S::dim } -> std::convertible_to<int>;
    } && requires(const S& s, const typename S::Kinematics& d, int t, int T, Vec<S::dim>& e,
                  Mat<S::dim, S::Kinematics::nq>& J) {
      { s.residual(d, t, T, e, J) } -> std::same_as<void>;
    };

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TopologicalStack: a TaskStack plus a topology-space task variable pulled toward a target
/// trajectory y_t (the coupling factors of the paper's Fig. 4).
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <utility>
#include <vector>

#include <topograsp/aico/detail/task_parts.hpp>
#include <topograsp/task/concepts.hpp>

namespace topograsp {

namespace detail {
template <class Base, int K>
constexpr auto topological_task_dims() noexcept {
  if constexpr (HasTaskDims<Base>) {
    std::array<int, Base::task_dims.size() + 1> d{};
    for (std::size_t i = 0; i < Base::task_dims.size(); ++i) d[i] = Base::task_dims[i];
    d[Base::task_dims.size()] = K;
    return d;
  } else {
    return std::array<int, 2>{Base::dim, K};
  }
}
}  // namespace detail

/// The TaskStack \p Base with one more task: the topology variable \p Var (e.g. the windings of
/// two hand curves, WindingTask) pulled toward targets y_t, i.e. the factors
/// \f$\exp(-\frac{\rho_t}{2} |\varphi(q_t) - y_t|^2)\f$ of the paper's eq. (1). Its residual is
/// Base's rows, then \f$\sqrt{\rho_t} (\varphi(q_t) - y_t)\f$ with \f$\rho_t\f$ = precision for
/// t < T and end_precision at t = T. The per-task costs of an AICO result list Base's tasks, then
/// this one.
template <TaskStack Base, TaskVariable Var>
  requires std::same_as<typename Base::Kinematics, typename Var::Kinematics>
struct TopologicalStack {
  using Kinematics = typename Base::Kinematics;
  static constexpr int nq = Kinematics::nq;
  static constexpr int k = Var::dim;  ///< dimension of the topology space
  static constexpr int dim = Base::dim + Var::dim;
  static constexpr auto task_dims = detail::topological_task_dims<Base, Var::dim>();

  Base base;                    ///< the other tasks
  Var variable;                 ///< phi: configuration -> topology space
  std::vector<Vec<k>> targets;  ///< y_0..y_T (T + 1 of them)
  double precision = 1e2;       ///< coupling precision rho for t < T
  double end_precision = 1e4;   ///< coupling precision at t = T

  /// The stacked residual at step t of T. Requires forward_kinematics(d, q) first and
  /// targets.size() == T + 1.
  void residual(const Kinematics& d, int t, int T, Vec<dim>& e, Mat<dim, nq>& J) const noexcept {
    Vec<Base::dim> eb;
    Mat<Base::dim, nq> Jb;
    base.residual(d, t, T, eb, Jb);
    e.template head<Base::dim>() = eb;
    J.template topRows<Base::dim>() = Jb;
    Vec<k> phi;
    Mat<k, nq> Jv;
    variable.evaluate(d, phi, Jv);
    const double s = std::sqrt(t == T ? end_precision : precision);
    e.template tail<k>() = s * (phi - targets[static_cast<std::size_t>(t)]);
    J.template bottomRows<k>() = s * Jv;
  }
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TaskSet: a compile-time set of scheduled task variables, the TaskStack a planner consumes.
#pragma once

#include <array>
#include <cmath>
#include <tuple>
#include <type_traits>
#include <utility>

#include <topograsp/task/concepts.hpp>
#include <topograsp/task/schedule.hpp>

namespace topograsp {

/// A fixed set of task variables, each with a target and a precision schedule, evaluated from one
/// forward-kinematics result. Models TaskStack: at step t of 0..T the whitened residual stacks
/// e_i = sqrt(rho_i(t)) (phi_i(q) - y*_i(t)) with Jacobian rows sqrt(rho_i(t)) J_i, so the cost of
/// the step is |e|^2 = sum_i rho_i(t) |phi_i(q) - y*_i(t)|^2. Stored in a std::tuple; every loop
/// over the tasks is a fold, every size is fixed at compile time; nothing allocates.
///
/// All tasks must share one Kinematics type (the same model).
template <TaskVariable... Tasks>
  requires(sizeof...(Tasks) > 0)
class TaskSet {
  using First = std::tuple_element_t<0, std::tuple<Tasks...>>;

 public:
  using Kinematics = typename First::Kinematics;
  static_assert((std::is_same_v<typename Tasks::Kinematics, Kinematics> && ...),
                "every task of a TaskSet must be built on the same model");
  static constexpr int nq = Kinematics::nq;
  /// Total dimension: the sum of the tasks' dimensions.
  static constexpr int dim = (Tasks::dim + ...);
  /// Number of tasks.
  static constexpr std::size_t size = sizeof...(Tasks);

  /// A set of the given scheduled tasks, in order.
  explicit TaskSet(Scheduled<Tasks>... entries) : entries_(std::move(entries)...) {}

  /// The whitened residual e (dim) and its Jacobian J (dim x nq) at step \p t of 0..\p T.
  /// Requires forward_kinematics(d, q) first.
  void residual(const Kinematics& d, int t, int T, Vec<dim>& e, Mat<dim, nq>& J) const noexcept {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      (residual_of<I>(d, t, T, e, J), ...);
    }(std::make_index_sequence<size>{});
  }

  /// The cost |e|^2 of step \p t of 0..\p T (no Jacobians). Requires forward_kinematics(d, q).
  [[nodiscard]] double cost(const Kinematics& d, int t, int T) const noexcept {
    const std::array<double, size> c = task_costs(d, t, T);
    double sum = 0.0;
    for (double x : c) sum += x;
    return sum;
  }

  /// The cost rho_i(t) |phi_i(q) - y*_i(t)|^2 of each task at step \p t of 0..\p T.
  [[nodiscard]] std::array<double, size> task_costs(const Kinematics& d, int t,
                                                    int T) const noexcept {
    std::array<double, size> c{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((c[I] = std::get<I>(entries_).precision.at(t, T) *
               (std::get<I>(entries_).task.value(d) - std::get<I>(entries_).target.at(t, T))
                   .squaredNorm()),
       ...);
    }(std::make_index_sequence<size>{});
    return c;
  }

  /// Sets the start of every interpolated target to the task's value at the configuration in
  /// \p d (the initial configuration), so that its targets run from where the robot is to the
  /// goal. Requires forward_kinematics(d, q0) first.
  void start_from(const Kinematics& d) noexcept {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((std::get<I>(entries_).target.start = std::get<I>(entries_).task.value(d)), ...);
    }(std::make_index_sequence<size>{});
  }

  /// Entry \p I (task, target, precision), to read or retune between plans.
  template <std::size_t I>
  [[nodiscard]] auto& get() noexcept {
    return std::get<I>(entries_);
  }
  template <std::size_t I>
  [[nodiscard]] const auto& get() const noexcept {
    return std::get<I>(entries_);
  }

  /// The offset of task \p I's rows in e and J.
  template <std::size_t I>
  static constexpr int offset = [] {
    constexpr std::array<int, size> dims{Tasks::dim...};
    int o = 0;
    for (std::size_t k = 0; k < I; ++k) o += dims[k];
    return o;
  }();

 private:
  template <std::size_t I>
  void residual_of(const Kinematics& d, int t, int T, Vec<dim>& e, Mat<dim, nq>& J) const noexcept {
    const auto& entry = std::get<I>(entries_);
    using Task = std::remove_cvref_t<decltype(entry.task)>;
    constexpr int n = Task::dim;
    Vec<n> phi;
    Mat<n, nq> Ji;
    entry.task.evaluate(d, phi, Ji);
    const double w = std::sqrt(entry.precision.at(t, T));
    e.template segment<n>(offset<I>) = w * (phi - entry.target.at(t, T));
    J.template middleRows<n>(offset<I>) = w * Ji;
  }

  std::tuple<Scheduled<Tasks>...> entries_;
};

/// A TaskSet of the given scheduled tasks (the template arguments are deduced).
template <TaskVariable... Tasks>
[[nodiscard]] TaskSet<Tasks...> make_task_set(Scheduled<Tasks>... entries) {
  return TaskSet<Tasks...>(std::move(entries)...);
}

}  // namespace topograsp

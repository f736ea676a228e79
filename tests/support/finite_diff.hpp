// SPDX-License-Identifier: BSD-3-Clause
// Central finite differences of kinematic quantities and of task variables: the oracle for every
// analytic Jacobian.
#pragma once

#include <algorithm>

#include <topograsp/kinematics/forward.hpp>

namespace topograsp::test {

/// Central differences of a vector function f(q) -> Vec<R> with step h.
template <int R, int N, class F>
Mat<R, N> central_difference(const Vec<N>& q, F&& f, double h = 1e-6) {
  Mat<R, N> J;
  for (int i = 0; i < q.size(); ++i) {
    Vec<N> qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    J.col(i) = (f(qp) - f(qm)) / (2.0 * h);
  }
  return J;
}

/// The angular velocity per unit q-dot of a rotation R(q), by central differences:
/// column i is vee((R(q + h e_i) - R(q - h e_i)) / 2h * R(q)^T).
template <int N, class F>
Mat<3, N> rotation_difference(const Vec<N>& q, F&& rotation, double h = 1e-6) {
  Mat<3, N> J;
  const Mat3 R0 = rotation(q);
  for (int i = 0; i < q.size(); ++i) {
    Vec<N> qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    const Mat3 S = (rotation(qp) - rotation(qm)) / (2.0 * h) * R0.transpose();
    J.col(i) << S(2, 1), S(0, 2), S(1, 0);
  }
  return J;
}

/// The central-difference Jacobian of task.value() at q (step h).
template <class Task>
Mat<Task::dim, Task::Kinematics::nq> numeric_jacobian(const Task& task,
                                                      const Vec<Task::Kinematics::nq>& q,
                                                      double h = 1e-6) {
  using D = typename Task::Kinematics;
  D d;
  return central_difference<Task::dim, D::nq>(
      q,
      [&](const Vec<D::nq>& x) -> Vec<Task::dim> {
        forward_kinematics(d, x);
        return task.value(d);
      },
      h);
}

/// The largest entry-wise difference between the analytic and numeric Jacobians of task at q,
/// relative to max(1, largest analytic entry); also checks that value() agrees with evaluate().
template <class Task>
double jacobian_error(const Task& task, const Vec<Task::Kinematics::nq>& q, double h = 1e-6) {
  using D = typename Task::Kinematics;
  D d;
  forward_kinematics(d, q);
  Vec<Task::dim> phi;
  Mat<Task::dim, D::nq> J;
  task.evaluate(d, phi, J);
  const Vec<Task::dim> v = task.value(d);
  const double value_error = (phi - v).cwiseAbs().maxCoeff();
  const Mat<Task::dim, D::nq> Jn = numeric_jacobian(task, q, h);
  const double scale = std::max(1.0, J.cwiseAbs().maxCoeff());
  return std::max(value_error, (J - Jn).cwiseAbs().maxCoeff() / scale);
}

/// Like jacobian_error(), for piecewise-smooth maps (a minimum over pairs, a penetration depth
/// whose exit direction switches): each column may match the central, the forward or the backward
/// difference, since at a kink the analytic Jacobian is that of one of the two sides.
template <class Task>
double piecewise_jacobian_error(const Task& task, const Vec<Task::Kinematics::nq>& q,
                                double h = 1e-6) {
  using D = typename Task::Kinematics;
  D d;
  forward_kinematics(d, q);
  Vec<Task::dim> phi;
  Mat<Task::dim, D::nq> J;
  task.evaluate(d, phi, J);
  const Vec<Task::dim> f0 = task.value(d);
  double worst = (phi - f0).cwiseAbs().maxCoeff();
  const double scale = std::max(1.0, J.cwiseAbs().maxCoeff());
  for (int i = 0; i < D::nq; ++i) {
    Vec<D::nq> qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    forward_kinematics(d, qp);
    const Vec<Task::dim> fp = task.value(d);
    forward_kinematics(d, qm);
    const Vec<Task::dim> fm = task.value(d);
    const double central = (J.col(i) - (fp - fm) / (2.0 * h)).cwiseAbs().maxCoeff();
    const double forward = (J.col(i) - (fp - f0) / h).cwiseAbs().maxCoeff();
    const double backward = (J.col(i) - (f0 - fm) / h).cwiseAbs().maxCoeff();
    worst = std::max(worst, std::min({central, forward, backward}) / scale);
  }
  return worst;
}

}  // namespace topograsp::test

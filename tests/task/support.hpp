// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the task and geometry tests: random configurations and central differences.
#pragma once

#include <algorithm>
#include <random>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>

namespace topograsp::test {

/// A random configuration of M inside its joint limits (free-base translations within +-0.3 m).
template <const auto& M>
Vec<M.nq> random_configuration(std::mt19937& rng) {
  Vec<M.nq> q;
  for (int i = 0; i < M.nq; ++i) {
    const LinkSpec& s = M.joint_spec(i);
    double lo = s.lower, hi = s.upper;
    if (s.type == JointType::prismatic) {
      lo = std::max(lo, -0.3);
      hi = std::min(hi, 0.3);
    }
    std::uniform_real_distribution<double> u(lo, hi);
    q[i] = u(rng);
  }
  return q;
}

/// The central-difference Jacobian of task.value() at q (step h).
template <class Task>
Mat<Task::dim, Task::Kinematics::nq> numeric_jacobian(const Task& task,
                                                      const Vec<Task::Kinematics::nq>& q,
                                                      double h = 1e-6) {
  using D = typename Task::Kinematics;
  Mat<Task::dim, D::nq> J;
  D d;
  for (int i = 0; i < D::nq; ++i) {
    Vec<D::nq> qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    forward_kinematics(d, qp);
    const Vec<Task::dim> fp = task.value(d);
    forward_kinematics(d, qm);
    const Vec<Task::dim> fm = task.value(d);
    J.col(i) = (fp - fm) / (2.0 * h);
  }
  return J;
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

}  // namespace topograsp::test

namespace topograsp::test {

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

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// balance_hold(): the joint torques with which a closed hand holds its object so that the
/// contact forces balance on it (grasp force optimisation over the contacts when closing ends).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include <topograsp/core/nonnegative_least_squares.hpp>
#include <topograsp/evaluation/hand_scene.hpp>
#include <topograsp/kinematics/jacobian.hpp>

namespace topograsp {

/// The holding torques balance_hold() found.
template <int NQ>
struct HoldBalance {
  /// Whether any contact of a link that a joint moves carries force (else torque is 0 and the
  /// caller holds some other way).
  bool found = false;
  Vec<NQ> torque = Vec<NQ>::Zero();  ///< each motor's holding torque (N m, or N)
  double squeeze = 0.0;              ///< the total normal force of the balanced contact forces (N)
  /// |net wrench| / squeeze of the balanced forces (the torque divided by the contacts' largest
  /// distance from the object's centre of mass): 0 when they balance exactly, near 1 when they
  /// all push one way.
  double imbalance = 0.0;
  int contacts = 0;  ///< the contact points the forces were distributed over
  /// The total normal force (N) that the object's weight asks of these contacts in the most
  /// demanding of the six directions they can hold it in (load_squeeze()); 0 when the grip does
  /// not follow the load (GripLoad::max_grip 1 or no weight) or they hold it in none.
  double load_squeeze = 0.0;
  /// The grip held with, as a multiple of hold_fraction's (1: the fixed grip; up to
  /// GripLoad::max_grip when the load asks for more).
  double grip = 1.0;
};

/// How balance_hold()'s grip follows the object's load (grip-load coupling: a person grips an
/// object with what its load asks plus a safety margin, Westling and Johansson 1984). With
/// max_grip 1 (the default) the grip is hold_fraction's alone.
struct GripLoad {
  double weight = 0.0;    ///< the object's weight (N), m |g|; 0: the grip does not follow it
  double margin = 0.4;    ///< the safety margin over what the load asks (0.4: 40 %)
  double max_grip = 1.0;  ///< the strongest grip, as a multiple of hold_fraction's (>= 1)
};

/// The cone edges, the weight of the torques' evenness against the balance, and the rounds of
/// reweighting of balance_hold().
inline constexpr int k_hold_cone_edges = 8;
inline constexpr double k_hold_evenness_weight = 0.01;
inline constexpr int k_hold_rounds = 8;

/// The torques with which the hand of \p scene, closed on its object, holds it with forces that
/// balance on it, as a person adjusts the fingers' forces to hold an object still (grasp force
/// optimisation: the classic force distribution problem of grasp analysis).
/// Over the hand-object contacts of the last step (HandScene::hand_contact_list()), each a point
/// contact with its pair's friction cone in k_hold_cone_edges edges, the contact forces f_i are
/// the non-negative least-squares minimiser (nonnegative_least_squares()) of
///   |sum f_i|^2 + |sum (p_i - c) x f_i / L|^2 + 100 (sum n_i.f_i - 1)^2
///     + k_hold_evenness_weight sum_j w_j (tau_j / effort_j)^2,   tau = sum J_i' f_i,
/// c the object's centre of mass, L the contacts' largest distance from it, J_i the point
/// Jacobian of contact i's link, effort_j the joint's torque limit: forces of unit total
/// squeeze, balanced as nearly as the contacts allow, spread over the joints in proportion to
/// their strength (the palm, moved by no joint, carries what it is given for free). The torques
/// are then scaled so that the most loaded joint gives \p hold_fraction of its limit. The weights
/// w_j of the evenness term start at 1 and are reweighted k_hold_rounds times towards the joints
/// that carry the most (Lawson's minimax iteration), which raises the squeeze the limits allow.
/// A pair without friction has a cone of one edge, its normal.
/// With \p grip (GripLoad::max_grip above 1 and a weight), the grip then follows the load: the
/// same forces are scaled to (1 + margin) times load_squeeze(), the total normal force the
/// object's weight asks of these contacts, when that is more than hold_fraction's grip, up to
/// max_grip times it (the most loaded joint then above hold_fraction of its limit, up to
/// max_grip x hold_fraction).
/// \throws topograsp::invalid_argument naming "hold_fraction" unless it is in (0, 1], or
/// "grip.weight", "grip.margin", "grip.max_grip" unless finite and >= 0, >= 0 and in
/// [1, k_max_grip].
namespace detail {

// What solve_hold_balance() found: per unit of total normal force, the joints' torques, and the
// net wrench's norm; ok false when no force could be found.
struct UnitHoldBalance {
  bool ok = false;
  Eigen::VectorXd torque;  // per joint, for a total normal force of 1 N
  double imbalance = 0.0;
};

// The model-independent part of balance_hold() (compiled once per translation unit, whatever the
// hands): wrench (6 x edges: each cone edge's force and torque / L on the object), torque_of
// (joints x edges: the joint torques per unit of each edge) and effort (the joints' limits).
template <class = void>
UnitHoldBalance solve_hold_balance(const Eigen::MatrixXd& wrench, const Eigen::MatrixXd& torque_of,
                                   const Eigen::VectorXd& effort) {
  constexpr double squeeze_weight = 10.0;
  const Eigen::Index nq = torque_of.rows(), cols = wrench.cols();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(7 + nq, cols);
  A.topRows(6) = wrench;
  A.row(6).setConstant(squeeze_weight);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(7 + nq);
  b[6] = squeeze_weight;
  // Lawson's reweighting towards the least largest load: each round weighs a joint's load by
  // how near the largest it came in the last.
  Eigen::VectorXd weight = Eigen::VectorXd::Ones(nq);
  NonnegativeLeastSquares solved;
  for (int round = 0; round < k_hold_rounds; ++round) {
    for (Eigen::Index j = 0; j < nq; ++j)
      A.row(7 + j) = std::sqrt(k_hold_evenness_weight * weight[j]) * torque_of.row(j) / effort[j];
    solved = nonnegative_least_squares(A, b);
    Eigen::VectorXd load(nq);
    for (Eigen::Index j = 0; j < nq; ++j)
      load[j] = std::abs(torque_of.row(j).dot(solved.x)) / effort[j];
    const double total = weight.dot(load);
    if (!(total > 0.0)) break;
    weight = (weight.cwiseProduct(load) * (static_cast<double>(nq) / total)).cwiseMax(1e-6);
  }
  UnitHoldBalance out;
  const double squeeze = solved.x.sum();
  if (!(squeeze > 0.0)) return out;
  const Eigen::VectorXd x = solved.x / squeeze;  // unit total normal force
  out.ok = true;
  out.torque = torque_of.lazyProduct(x);
  out.imbalance = wrench.lazyProduct(x).norm();
  return out;
}

// The total normal force (N) with which the contacts of `wrench` (6 x edges: each cone edge's
// force and its torque / length about the object's centre of mass) hold a weight of `weight`
// (N) along each of the six directions of `frame`'s axes, the largest over the directions they
// can hold it in (a residual below 5 % of the weight), 0 when none: per direction the
// non-negative least-squares edge forces that balance the weight, with a small cost on their
// total normal force (each edge's normal component is 1), so that of the forces that balance it
// the least squeeze is taken.
template <class = void>
double load_squeeze(const Eigen::MatrixXd& wrench, const Mat3& frame, double weight) {
  constexpr double squeeze_cost = 1e-3, tolerance = 0.05;
  const Eigen::Index cols = wrench.cols();
  Eigen::MatrixXd A(7, cols);
  A.topRows(6) = wrench;
  A.row(6).setConstant(squeeze_cost);
  double most = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {1.0, -1.0}) {
      Eigen::VectorXd b = Eigen::VectorXd::Zero(7);
      b.head<3>() = -sign * weight * frame.col(axis);  // the contacts hold the weight
      const NonnegativeLeastSquares solved = nonnegative_least_squares(A, b);
      if ((wrench * solved.x - b.head<6>()).norm() <= tolerance * weight)
        most = std::max(most, solved.x.sum());
    }
  return most;
}

}  // namespace detail

/// The largest multiple of hold_fraction's grip that GripLoad::max_grip may give (with
/// hold_fraction 1, the motors' largest effort fraction).
inline constexpr double k_max_grip = k_max_effort_fraction;

template <const auto& M, class S>
[[nodiscard]] HoldBalance<M.nq> balance_hold(const HandScene<M, S>& scene, double hold_fraction,
                                             const GripLoad& grip = {}) {
  constexpr int nq = M.nq;
  if (!(hold_fraction > 0.0 && hold_fraction <= 1.0))
    detail::throw_invalid_argument("hold_fraction", "expected a value in (0, 1]");
  if (!(std::isfinite(grip.weight) && grip.weight >= 0.0))
    detail::throw_invalid_argument("grip.weight", "expected a finite value >= 0 (N)");
  if (!(std::isfinite(grip.margin) && grip.margin >= 0.0))
    detail::throw_invalid_argument("grip.margin", "expected a finite value >= 0");
  if (!(grip.max_grip >= 1.0 && grip.max_grip <= k_max_grip))
    detail::throw_invalid_argument(
        "grip.max_grip", "expected a value in [1, " + detail::number_text(k_max_grip) + "]");
  HoldBalance<nq> out;
  const std::vector<HandContact> contacts = scene.hand_contact_list();
  if (contacts.empty()) return out;
  KinematicsData<M> kin;
  forward_kinematics(kin, scene.joint_positions());
  const Eigen::Isometry3d hand = scene.hand_pose();
  const Mat3 R = hand.linear();
  const Vec3 c = scene.object_com();
  double length = 0.01;
  for (const HandContact& k : contacts) length = std::max(length, (k.point - c).norm());
  const auto m = static_cast<Eigen::Index>(contacts.size());
  Eigen::MatrixXd wrench(6, m * k_hold_cone_edges), torque_of(nq, m * k_hold_cone_edges);
  for (Eigen::Index i = 0; i < m; ++i) {
    const HandContact& k = contacts[static_cast<std::size_t>(i)];
    const Vec3 n = k.normal.normalized();
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    const int link = M.find_link(k.link);
    Mat<3, nq> J = Mat<3, nq>::Zero();
    if (link >= 0) J = point_jacobian(kin, link, hand.inverse() * k.point);
    for (int e = 0; e < k_hold_cone_edges; ++e) {
      const double a = 2.0 * std::numbers::pi * e / k_hold_cone_edges;
      const Vec3 f = n + k.friction * (std::cos(a) * t1 + std::sin(a) * t2);
      const Eigen::Index col = i * k_hold_cone_edges + e;
      wrench.block<3, 1>(0, col) = f;
      wrench.block<3, 1>(3, col) = (k.point - c).cross(f) / length;
      torque_of.col(col) = J.transpose() * (R.transpose() * f);
    }
  }
  Eigen::VectorXd effort(nq);
  for (int j = 0; j < nq; ++j) effort[j] = M.joint_spec(j).effort;
  const detail::UnitHoldBalance unit = detail::solve_hold_balance(wrench, torque_of, effort);
  if (!unit.ok) return out;
  double load = 0.0;  // the largest fraction of a joint's limit per newton of squeeze
  for (int j = 0; j < nq; ++j) load = std::max(load, std::abs(unit.torque[j]) / effort[j]);
  if (!(load > 0.0)) return out;
  double scale = hold_fraction / load;
  if (grip.max_grip > 1.0 && grip.weight > 0.0) {
    out.load_squeeze = detail::load_squeeze(wrench, R, grip.weight);
    out.grip = std::clamp((1.0 + grip.margin) * out.load_squeeze / scale, 1.0, grip.max_grip);
    scale *= out.grip;
  }
  out.found = true;
  out.torque = scale * Vec<nq>(unit.torque);
  out.squeeze = scale;
  out.imbalance = unit.imbalance;
  out.contacts = static_cast<int>(m);
  return out;
}

}  // namespace topograsp

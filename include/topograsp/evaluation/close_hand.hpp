// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// close_hand(): close a hand's fingers with their motors until each stalls on the object or
/// reaches its limit, holding at a stated fraction of the torque limits.
#pragma once

#include <algorithm>
#include <array>
#include <cstdio>
#include <type_traits>
#include <vector>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/parameters.hpp>
#include <topograsp/evaluation/hand_scene.hpp>
#include <topograsp/evaluation/hold_balance.hpp>

namespace topograsp {

/// The parameters of close_hand().
struct CloseOptions {
  /// Joint increment per iteration of the geometric search for first contact (rad for revolute,
  /// m for prismatic joints). At least the model's largest joint range / k_max_close_increments,
  /// so that the search takes at most that many increments per joint (0.5 degrees gives 720
  /// over a full turn). Default 0.5 degrees.
  double step = deg(0.5);
  /// Bisections that refine each contact value between two increments (each halves the
  /// bracket: 8 give 0.002 degrees), in [0, 64] (a double has 53 bits; more change nothing).
  /// Default 8.
  int bisections = 8;
  /// A link touches the object when a contact's separation is at most this (m). Default 0.
  double touch_distance = 0.0;
  /// The grip: the fraction of each joint's torque limit (LinkSpec::effort) its motor closes and
  /// holds with, in (0, 1]. Default 0.5: a holding grasp, not a maximal one.
  double hold_fraction = 0.5;
  /// Physics steps, gravity off (the object is not dropped before it is held), over which the
  /// motors, commanded closed, take the fingers from first contact to where they stall on the
  /// object or reach their limits; in [1, 1000000]. Default 60 (1 s at 60 Hz: a finger joint
  /// crosses 100 degrees at the SDH's 100 degrees/s).
  int closing_steps = 60;
  /// Whether the object is held still while the motors close the fingers (World::set_held()) and
  /// released after, as grasp-synthesis pipelines close on a static object (GraspIt's auto-grasp,
  /// DexGraspNet's validation; docs/evaluation.md, "The closing protocol"). Unheld, an object that
  /// only one finger reaches first is pushed away before the others arrive. Default false (the
  /// protocol of the published results; grasp_transfer --closing held sets it).
  bool hold_object = false;
  /// Physics steps after the release, gravity still off and the motors still closing the fingers,
  /// in which the object settles into the grasp (a grasp whose forces do not balance moves it here,
  /// and CloseResult::object_shift says how far); in [0, 1000000]. Default 0 (--closing held: 15,
  /// 0.25 s).
  int release_steps = 0;
  /// Whether the search for first contact closes each finger from its base out: a joint moves only
  /// once every closing joint before it on its chain has stopped (a person's power grasp: the
  /// knuckle closes until the finger meets the object, then the middle joint, then the last, so
  /// the finger wraps the object instead of meeting it with its tip alone). False: every joint
  /// moves at once and the first link to touch stops its whole chain. Default false (--closing
  /// held: true).
  bool proximal_first = false;
  /// Whether the hand holds with torques whose contact forces balance on the object
  /// (balance_hold(): the most loaded joint at hold_fraction of its limit, the others as the
  /// balance needs), set when the fingers have closed, before the object's release, as a person
  /// adjusts the fingers' forces to hold an object still. False: every closing joint presses with
  /// hold_fraction of its limit, whether or not the forces balance. Default false (--closing
  /// balanced: true).
  bool balanced_hold = false;
  /// With balanced_hold, how much harder than hold_fraction's grip the hand may grip where the
  /// object's load asks for it (grip-load coupling, balance_hold() with GripLoad: the balanced
  /// forces scaled to (1 + grip_margin) times the squeeze the object's weight asks of the
  /// contacts, never below hold_fraction's grip), in [1, k_max_grip]. The motors may then give
  /// up to that multiple of hold_fraction of their limits, above the limits where it exceeds 1
  /// (the human hand's efforts are holding torques, about a fifth of its strength:
  /// GraspSimOptions::human_max_grip). Default 1: the grip is hold_fraction's alone.
  double max_grip = 1.0;
  /// The safety margin of that grip over what the load asks, >= 0. Default 0.4 (people grip
  /// 10 to 40 % above the force at which the object would slip: Westling and Johansson 1984).
  double grip_margin = 0.4;
};

/// The numeric fields of CloseOptions with their valid ranges (close_hand() checks them).
inline constexpr ParameterTable<CloseOptions, 8> close_parameters{{
    {"step", &CloseOptions::step, 0.0, unbounded, "rad or m: the search's joint increment", true},
    {"bisections", &CloseOptions::bisections, 0, 64, "bisections of each contact value"},
    {"touch_distance", &CloseOptions::touch_distance, 0.0, unbounded,
     "m: a link touches within this separation"},
    {"hold_fraction", &CloseOptions::hold_fraction, 0.0, 1.0,
     "the motors' fraction of their torque limits", true},
    {"closing_steps", &CloseOptions::closing_steps, 1, 1000000,
     "physics steps from first contact to the stall"},
    {"release_steps", &CloseOptions::release_steps, 0, 1000000,
     "physics steps after the object's release"},
    {"max_grip", &CloseOptions::max_grip, 1.0, k_max_grip,
     "the strongest grip the load may ask, a multiple of hold_fraction's"},
    {"grip_margin", &CloseOptions::grip_margin, 0.0, 10.0,
     "the grip's safety margin over what the load asks"},
}};

/// The most increments close_hand() takes per joint: CloseOptions::step must be at least the
/// largest joint range of the model divided by this.
inline constexpr double k_max_close_increments = 100000.0;

/// The outcome of close_hand().
template <int NQ>
struct CloseResult {
  Status status = Status::success;      ///< of the physics steps of the closing
  Vec<NQ> q_contact = Vec<NQ>::Zero();  ///< each closing joint where its links first touch
  Vec<NQ> q_closed = Vec<NQ>::Zero();   ///< the joints' positions when closing ends
  std::array<bool, static_cast<std::size_t>(NQ)> touched{};  ///< joints stopped by contact
  int touching_joints = 0;                                   ///< how many joints touched
  int contacts = 0;  ///< hand-object contact points when closing ends
  /// How far the object's centre of mass moved from the start of closing to its end (m),
  /// release included.
  double object_shift = 0.0;
  /// How far the object turned over the same time (rad).
  double object_turn = 0.0;
  /// The hand-object contact points when closing ends (HandScene::hand_contact_list()), point
  /// and normal in the object's frame.
  std::vector<HandContact> contact_points;
  /// Each motor's holding torque (N m, or N) when closing ends: hold_fraction of its limit in
  /// its closing direction, or balance_hold()'s (CloseOptions::balanced_hold).
  Vec<NQ> hold_torque = Vec<NQ>::Zero();
  /// Whether hold_torque is balance_hold()'s (false: uniform, asked for or because no finger
  /// touched the object when the fingers had closed).
  bool balanced = false;
  /// balance_hold()'s imbalance of the forces it balanced (0 when not balanced).
  double hold_imbalance = 0.0;
  /// The total normal force of the balanced hold (N; 0 when not balanced).
  double hold_squeeze = 0.0;
  /// The total normal force the object's weight asks of the contacts (balance_hold()'s
  /// load_squeeze, N; 0 when the grip does not follow the load).
  double load_squeeze = 0.0;
  /// The grip held with, as a multiple of hold_fraction's (1 unless the load asked for more).
  double grip = 1.0;
};

/// What a closing did, as a grasp's record keeps it (HumanGrasp, HandTransfer).
struct ClosingRecord {
  int touching_joints = 0;    ///< joints stopped by the object in the search for first contact
  int contacts = 0;           ///< hand-object contact points when closing ended
  double object_shift = 0.0;  ///< how far the object's centre of mass moved while closing (m)
  double object_turn = 0.0;   ///< how far the object turned while closing (rad)
  /// The contact points when closing ended: link, point and normal in the object's frame, force.
  std::vector<HandContact> contact_points;
  /// Each motor's holding torque (N m, or N), in configuration order (CloseResult::hold_torque).
  std::vector<double> hold_torque;
  bool balanced = false;        ///< whether the hold is balance_hold()'s
  double hold_imbalance = 0.0;  ///< its imbalance (0 when not balanced)
  double hold_squeeze = 0.0;    ///< its total normal force (N; 0 when not balanced)
  double load_squeeze = 0.0;    ///< what the object's weight asks of the contacts (N)
  double grip = 1.0;            ///< the grip, a multiple of hold_fraction's
};

/// The record of closing \p c.
template <int NQ>
[[nodiscard]] ClosingRecord closing_record(const CloseResult<NQ>& c) {
  return {c.touching_joints,
          c.contacts,
          c.object_shift,
          c.object_turn,
          c.contact_points,
          std::vector<double>(c.hold_torque.data(), c.hold_torque.data() + NQ),
          c.balanced,
          c.hold_imbalance,
          c.hold_squeeze,
          c.load_squeeze,
          c.grip};
}

/// The targets a closed hand holds with: each joint with a closing direction at its closed
/// limit (the upper for +1, the lower for -1), every other joint at its value in \p q.
template <const auto& M>
[[nodiscard]] Vec<M.nq> closed_targets(const Vec<M.nq>& q) noexcept {
  const Vec<M.nq> lo = lower_limits<M>(), hi = upper_limits<M>(), dir = closing_directions<M>();
  Vec<M.nq> out = q;
  for (int i = 0; i < M.nq; ++i) {
    if (dir[i] > 0.0) out[i] = hi[i];
    if (dir[i] < 0.0) out[i] = lo[i];
  }
  return out;
}

/// The uniform holding loads: each joint with a closing direction \p hold_fraction of its torque
/// limit (LinkSpec::effort) in that direction, every other joint 0 (the loads hold_targets()
/// takes, signed fractions of each joint's limit).
template <const auto& M>
[[nodiscard]] Vec<M.nq> uniform_hold_loads(double hold_fraction) noexcept {
  return closing_directions<M>() * hold_fraction;
}

/// The holding loads of the torques \p torque (N m, or N; CloseResult::hold_torque): each joint's
/// torque as a signed fraction of its limit (LinkSpec::effort), the loads hold_targets() takes.
template <const auto& M>
[[nodiscard]] Vec<M.nq> hold_loads(const Vec<M.nq>& torque) noexcept {
  Vec<M.nq> load;
  for (int i = 0; i < M.nq; ++i) load[i] = torque[i] / M.joint_spec(i).effort;
  return load;
}

/// The targets with which a hand at \p q holds with \p load (per joint, the signed fraction of
/// its effort, LinkSpec::effort, it presses with): each joint's servo target as far from where
/// it stands as its servo's stiffness now (HandScene::servo_stiffness()) needs to give that
/// torque there (load x servo_reach() with an effort fraction of at most 1), so that it stiffens
/// against a load up to its limit now (HandScene::effort_limit()).
template <const auto& M, class S>
[[nodiscard]] Vec<M.nq> hold_targets(const HandScene<M, S>& scene, const Vec<M.nq>& q,
                                     const Vec<M.nq>& load) noexcept {
  Vec<M.nq> out = q;
  for (int i = 0; i < M.nq; ++i)
    out[i] += load[i] * scene.servo_reach(i) / std::max(1.0, scene.effort_fraction());
  return out;
}

namespace detail {

// Links moved by configuration entry i: those with a joint driven by entry i in their support.
template <const auto& M>
std::array<bool, std::remove_cvref_t<decltype(M)>::n_links> links_after_joint(int i) {
  std::array<bool, std::remove_cvref_t<decltype(M)>::n_links> mask{};
  for (std::size_t l = 0; l < mask.size(); ++l)
    for (const SupportJoint& j : M.support(static_cast<int>(l)))
      if (j.q == i) {
        mask[l] = true;
        break;
      }
  return mask;
}

}  // namespace detail

/// Closes the hand of \p scene on its object with its motors. First a geometric search (the
/// object held still at its pose): every joint with a closing direction (LinkSpec::closing)
/// moves that way in increments, all joints in turn, until one of the links after it touches
/// the object (refined by bisection) or it reaches its limit (options.proximal_first: a joint
/// waits until every closing joint before it on its chain has stopped). The hand is placed there;
/// then every closing joint's motor is commanded to its closed limit and every other joint's to
/// stay, all at options.hold_fraction of their torque limits, and the scene is stepped
/// options.closing_steps times with gravity off, the object held still (options.hold_object):
/// each finger closes until it stalls on the object, pressing with what its motor gives, or
/// reaches its limit. With options.balanced_hold the motors then hold with balance_hold()'s
/// torques (forces that balance on the object, the most loaded joint at hold_fraction of its
/// limit) as position servos with their full limits (hold_targets()). Then the object is
/// released and the scene stepped options.release_steps times, gravity still off, the motors
/// still closing the fingers (or holding with the balanced torques). The scene is left holding,
/// gravity restored: each joint's servo targets hold_targets() of CloseResult::hold_torque
/// (uniform_hold_loads() unless balanced: it presses with that torque where it stands, and
/// resists a load stiffly up to its full limit); the moment closing ends, the reference of the
/// stability tests. Works for any model whose joints
/// have motors (HandScene); joints with closing 0 (abduction, a free base) keep their value.
/// \throws topograsp::invalid_argument naming the option for a field outside its range
/// (close_parameters), or a step below the largest joint range / k_max_close_increments (a finer
/// search would take longer than any use warrants).
template <const auto& M, class S>
CloseResult<M.nq> close_hand(HandScene<M, S>& scene, const CloseOptions& options = {}) {
  constexpr int nq = M.nq;
  using ModelType = std::remove_cvref_t<decltype(M)>;
  validate_parameters(options, close_parameters, "options.");
  const World<S>& world = scene.world();
  const RigidBody<S>& object = world.body(scene.object_body());
  const Eigen::Isometry3d hand = scene.hand_pose();
  const Vec<nq> lo = lower_limits<M>(), hi = upper_limits<M>(), dir = closing_directions<M>();
  std::array<std::array<bool, ModelType::n_links>, static_cast<std::size_t>(nq)> after{};
  for (int i = 0; i < nq; ++i) after[static_cast<std::size_t>(i)] = detail::links_after_joint<M>(i);
  KinematicsData<M> kin;
  const S margin = static_cast<S>(options.touch_distance);
  // True if a link after joint i touches the object at configuration q.
  const auto touching = [&](const Vec<nq>& q, int i) {
    forward_kinematics(kin, q);
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      const int b = scene.link_body(static_cast<int>(l));
      if (!after[static_cast<std::size_t>(i)][l] || b < 0) continue;
      const Eigen::Isometry3d Tl = hand * link_pose(kin, static_cast<int>(l));
      const Mat3 Rl = Tl.linear();
      const Vec3 pl = Tl.translation();
      const RigidBody<S>& body = world.body(b);
      for (int c = body.first_collider; c < body.first_collider + body.n_colliders; ++c) {
        ShapeView<S> v = world.shape_view(c);
        const Collider<S>& col = world.collider(c);
        v.R = Rl.template cast<S>() * col.local_R;
        v.p = pl.template cast<S>() + Rl.template cast<S>() * col.local_p;
        for (int oc = object.first_collider; oc < object.first_collider + object.n_colliders;
             ++oc) {
          ContactSet<S> cs;
          collide<S>(v, world.shape_view(oc), margin, cs);
          for (int k = 0; k < cs.count; ++k)
            if (cs.points[static_cast<std::size_t>(k)].separation <= margin) return true;
        }
      }
    }
    return false;
  };
  CloseResult<nq> result;
  Vec<nq> q = scene.joint_targets();
  std::array<bool, static_cast<std::size_t>(nq)> moving{};
  for (int i = 0; i < nq; ++i) {
    const auto u = static_cast<std::size_t>(i);
    moving[u] = dir[i] != 0.0;
    if (moving[u] && touching(q, i)) {
      moving[u] = false;
      result.touched[u] = true;
    }
  }
  const double range = (hi - lo).cwiseAbs().maxCoeff();
  const double increments = range / options.step;
  if (!(increments <= k_max_close_increments)) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "expected at least %.6g (the largest joint range %.6g / %.0f), got %.6g",
                  range / k_max_close_increments, range, k_max_close_increments, options.step);
    detail::throw_invalid_argument("options.step", buf);
  }
  // before[i][j]: closing joint j comes before joint i on its chain (every link joint i moves,
  // joint j moves too; of two joints that move the same links, the first in the configuration).
  std::array<std::array<bool, static_cast<std::size_t>(nq)>, static_cast<std::size_t>(nq)> before{};
  for (int i = 0; i < nq && options.proximal_first; ++i)
    for (int j = 0; j < nq; ++j) {
      if (j == i || dir[j] == 0.0) continue;
      bool all = true, some = false;
      for (std::size_t l = 0; l < ModelType::n_links; ++l)
        if (after[static_cast<std::size_t>(i)][l]) {
          some = true;
          all = all && after[static_cast<std::size_t>(j)][l];
        }
      const bool same = after[static_cast<std::size_t>(i)] == after[static_cast<std::size_t>(j)];
      before[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          some && all && (!same || j < i);
    }
  // Proximal first, a chain's joints move one after another: nq phases at most.
  const int max_iterations = (static_cast<int>(increments) + 2) * (options.proximal_first ? nq : 1);
  for (int it = 0; it < max_iterations; ++it) {
    bool any = false;
    for (int i = 0; i < nq; ++i) {
      const auto u = static_cast<std::size_t>(i);
      if (!moving[u]) continue;
      any = true;
      if (options.proximal_first) {
        bool waiting = false;
        for (int j = 0; j < nq; ++j)
          waiting = waiting ||
                    (before[u][static_cast<std::size_t>(j)] && moving[static_cast<std::size_t>(j)]);
        if (waiting) continue;
      }
      Vec<nq> trial = q;
      trial[i] = std::clamp(q[i] + dir[i] * options.step, lo[i], hi[i]);
      if (touching(trial, i)) {
        double free_value = q[i], touch_value = trial[i];
        for (int b = 0; b < options.bisections; ++b) {
          trial[i] = 0.5 * (free_value + touch_value);
          if (touching(trial, i))
            touch_value = trial[i];
          else
            free_value = trial[i];
        }
        q[i] = touch_value;
        moving[u] = false;
        result.touched[u] = true;
      } else {
        q[i] = trial[i];
        if (q[i] == lo[i] || q[i] == hi[i]) moving[u] = false;
      }
    }
    if (!any) break;
  }
  result.q_contact = q;
  for (int i = 0; i < nq; ++i)
    if (result.touched[static_cast<std::size_t>(i)]) ++result.touching_joints;
  // Close with the motors, gravity off, the object held still if asked.
  scene.place_hand(hand, result.q_contact);
  scene.set_effort_fraction(options.hold_fraction);
  scene.set_joint_targets(closed_targets<M>(q));
  World<S>& w = scene.world();
  const Eigen::Isometry3d object_start = scene.object_pose();
  const Vec3 com_start = scene.object_com();
  const Vec<3, S> gravity = w.gravity();
  w.set_gravity(Eigen::Vector3d::Zero());
  if (options.hold_object) w.set_held(scene.object_body(), true);
  for (int k = 0; k < options.closing_steps && result.status == Status::success; ++k)
    result.status = scene.step();
  // The holding torques: uniform, or balanced over the contacts the fingers closed to, from now
  // as position servos with their full limits.
  Vec<nq> load = uniform_hold_loads<M>(options.hold_fraction);
  double servo_fraction = 1.0;  // the motors' limits while holding: above 1 for a stronger grip
  if (options.balanced_hold && result.status == Status::success) {
    const GripLoad grip{scene.object_mass() * gravity.template cast<double>().norm(),
                        options.grip_margin, options.max_grip};
    const HoldBalance<nq> balance = balance_hold(scene, options.hold_fraction, grip);
    if (balance.found) {
      load = hold_loads<M>(balance.torque);
      result.balanced = true;
      result.hold_imbalance = balance.imbalance;
      result.hold_squeeze = balance.squeeze;
      result.load_squeeze = balance.load_squeeze;
      result.grip = balance.grip;
      servo_fraction = std::max(1.0, load.cwiseAbs().maxCoeff());
      scene.set_effort_fraction(servo_fraction);
      scene.set_joint_targets(hold_targets(scene, scene.joint_positions(), load));
    }
  }
  for (int i = 0; i < nq; ++i) result.hold_torque[i] = load[i] * M.joint_spec(i).effort;
  // Released, the object settles into the grasp, the motors still closing the fingers after it
  // (or holding with balanced torques).
  if (options.hold_object) w.set_held(scene.object_body(), false);
  for (int k = 0; k < options.release_steps && result.status == Status::success; ++k)
    result.status = scene.step();
  w.set_gravity(gravity.template cast<double>());
  result.q_closed = scene.joint_positions();
  // Hold: the same torques where the fingers stand, as position servos with their full limits.
  scene.set_joint_targets(hold_targets(scene, result.q_closed, load));
  scene.set_effort_fraction(servo_fraction);
  result.contacts = scene.hand_contacts();
  const Eigen::Isometry3d to_object = scene.object_pose().inverse();
  result.contact_points = scene.hand_contact_list();
  for (HandContact& c : result.contact_points) {
    c.point = to_object * c.point;
    c.normal = to_object.linear() * c.normal;
  }
  result.object_shift = (scene.object_com() - com_start).norm();
  result.object_turn =
      Eigen::AngleAxisd(object_start.linear().transpose() * scene.object_pose().linear()).angle();
  return result;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// check_hand(): the self-check of a hand model before any transfer to it (a user's imported hand
/// above all): the conventions the transfer relies on (the palm centre frame's axes, each joint's
/// closing direction, motors, masses), then the hand closed on a ball and on a cylinder at its
/// palm and judged by the stability suite. docs/models.md, "Check a hand before transferring".
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <topograsp/core/number_text.hpp>
#include <topograsp/evaluation/close_hand.hpp>
#include <topograsp/evaluation/hand_scene.hpp>
#include <topograsp/evaluation/stability_suite.hpp>
#include <topograsp/grasp/hand_grasp.hpp>
#include <topograsp/kinematics/forward.hpp>

namespace topograsp {

/// How check_hand() tries the hand.
struct HandCheckOptions {
  /// The trial objects' radius as a fraction of the open hand's aperture (the distance from the
  /// thumb tip to the centroid of the other fingertips).
  double size_fraction = 0.3;
  double mass = 0.1;  ///< kg, of each trial object
  /// A closing joint that moves its fingertip away from the opposing tips (the thumb's, or the
  /// other fingertips' centroid for the thumb) by more than this over a 0.05 rad (or m) step is
  /// reported (m).
  double away_tolerance = 1e-4;
  /// The scene, the closing and the stability suite. By default the held closing (the object
  /// held still while the fingers close from their base out, then released for 15 steps:
  /// docs/evaluation.md, "The closing protocol"), so that the trial object does not roll off an
  /// open palm before the fingers reach it.
  GraspSimOptions sim = [] {
    GraspSimOptions s;
    s.close.hold_object = true;
    s.close.release_steps = 15;
    s.close.proximal_first = true;
    return s;
  }();
};

/// One trial of check_hand(): the hand closed on an object at its palm and judged.
struct HandTrial {
  std::string object;  ///< "ball" or "cylinder"
  bool stable = false;
  int contacts = 0;    ///< hand-object contacts when closing ended
  std::string reason;  ///< why not stable ("closing ended with no contact ...", the suite's)
};

/// What check_hand() found.
struct HandCheck {
  /// What is wrong with the model, each what it is and what to change; empty if nothing.
  std::vector<std::string> problems;
  std::vector<HandTrial> trials;  ///< the ball, then the cylinder
  /// No problem, and the hand holds at least one of the trial objects. (Not every shipped hand
  /// holds both: docs/models.md lists what each does.)
  [[nodiscard]] bool ok() const {
    bool held = false;
    for (const HandTrial& t : trials) held = held || t.stable;
    return problems.empty() && held;
  }
};

/// Checks hand \p M as the transfer will use it. With the hand open (every joint at 0 within its
/// limits, the thumb turned to oppose: opposed_thumb()), and for a hand placed by its palm centre
/// frame (every hand but the human hand and the SDH, hand_profile()):
/// - the palm centre frame: its +y should point from the thumb tip toward the other fingertips
///   (within 60 degrees) and the fingertips should lie on its +z side (+z the approach, out of the
///   palm toward the object); a frame turned otherwise makes every transfer close on air;
/// - each closing joint: a step in its closing direction should bring its fingertip nearer the
///   opposing tips (the thumb's, or for the thumb the other fingertips' centroid);
/// - every actuated joint has a motor (an effort limit), and every link with a collision shape a
///   mass;
/// then the hand, its root at the identity, closes by its motors on a ball and on a cylinder (its
/// axis along the palm frame's x) of radius options.size_fraction of the aperture, placed on the
/// palm frame's +z axis just clear of the palm, and each is judged by the stability suite; a
/// closing that ends with no contact says so.
/// \throws topograsp::invalid_argument naming the option for a size_fraction or mass that is not
/// positive and finite, and as close_hand() and stability_suite() do for their options.
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] HandCheck check_hand(const HandCheckOptions& options = {}) {
  require_positive(options.size_fraction, "options.size_fraction");
  require_positive(options.mass, "options.mass");
  require_positive(options.away_tolerance, "options.away_tolerance");
  HandCheck out;
  const HandProfile<M> profile = hand_profile<M>();
  const Vec<M.nq> q = opposed_thumb<M>(clamp_to_limits<M>(Vec<M.nq>::Zero()));
  KinematicsData<M> d;
  const auto tips = [&](const Vec<M.nq>& at, Vec3& thumb, Vec3& fingers) {
    forward_kinematics(d, at);
    std::vector<Vec3> p(M.n_fingers);
    fingers.setZero();
    for (std::size_t f = 0; f < M.n_fingers; ++f) {
      p[f] = world_point(d, finger_tip<M>(static_cast<int>(f)));
      if (static_cast<int>(f) != M.thumb) fingers += p[f] / static_cast<double>(M.n_fingers - 1);
    }
    thumb = p[static_cast<std::size_t>(M.thumb)];
    return p;
  };
  Vec3 thumb, fingers;
  (void)tips(q, thumb, fingers);
  forward_kinematics(d, q);
  const Eigen::Matrix3d axes = frame_pose(d, profile.frame).linear();
  const Vec3 approach = (axes * profile.axes.approach).normalized();
  const Vec3 up = (axes * profile.axes.up).normalized();
  const Vec3 palm = world_point(d, M.palm);
  // Where the trial objects are held: on the approach axis, just clear of the palm.
  const double radius = options.size_fraction * (fingers - thumb).norm();
  const Vec3 centre = palm + (radius + 2.0 * options.sim.contact_gap) * approach;
  const std::string_view name = M.name.view();
  if (name != "human_hand" && name != "schunk_sdh") {
    const Vec3 across = fingers - thumb;
    const double angle = std::acos(std::clamp(across.normalized().dot(up), -1.0, 1.0));
    const auto in_frame = [&](const Vec3& v) {
      const Vec3 f = axes.transpose() * v * 1e3;
      return detail::number_text(f.x(), "%.1f") + ", " + detail::number_text(f.y(), "%.1f") + ", " +
             detail::number_text(f.z(), "%.1f") + " mm";
    };
    if (angle > pi / 3)
      out.problems.push_back(
          "the palm centre frame's +y should point from the thumb tip toward the fingertips, but "
          "they lie " +
          detail::number_text(angle * 180.0 / pi, "%.0f") + " degrees from it (" +
          in_frame(across) +
          " in the frame): turn the palm_centre frame (docs/models.md, \"A hand description "
          "file\")");
    // Half closed (every closing joint half way to its closed limit), the fingertips stand in
    // front of the palm, on the +z side (the approach), where the object will be.
    Vec3 thumb_c, fingers_c;
    (void)tips(Vec<M.nq>(0.5 * (q + closed_targets<M>(q))), thumb_c, fingers_c);
    const Vec3 mid = 0.5 * (thumb_c + fingers_c) - palm;
    if (mid.dot(approach) <= 0.0)
      out.problems.push_back(
          "half closed, the fingertips lie behind the palm centre frame's +z (their midpoint at " +
          in_frame(mid) +
          " in the frame): +z should point out of the palm toward the object; turn the "
          "palm_centre frame");
  }
  // Closing directions: a step toward closing brings the fingertip nearer the held object.
  const Vec<M.nq> dir = closing_directions<M>();
  for (int i = 0; i < M.nq; ++i) {
    if (dir[i] == 0.0) continue;
    Vec<M.nq> step = q;
    step[i] += 0.05 * dir[i];
    step = clamp_to_limits<M>(step);
    if (step[i] == q[i]) continue;  // at its closed limit already
    Vec3 t0, f0, t1, f1;
    const std::vector<Vec3> p0 = tips(q, t0, f0);
    const std::vector<Vec3> p1 = tips(step, t1, f1);
    for (std::size_t f = 0; f < M.n_fingers; ++f) {
      if ((p1[f] - p0[f]).norm() < 1e-9) continue;
      const double away = (p1[f] - centre).norm() - (p0[f] - centre).norm();
      if (away > options.away_tolerance)
        out.problems.push_back("closing the joint " + std::string(M.joint_name(i)) +
                               " (direction " + detail::number_text(dir[i], "%+.0f") +
                               ") moves the tip of " + std::string(M.fingers[f].spec.name.view()) +
                               " away from the palm's front (" +
                               detail::number_text(away * 1e3, "%.1f") +
                               " mm over 0.05): its closing direction is probably the opposite");
    }
  }
  for (int i = 0; i < M.nq; ++i)
    if (M.joint_spec(i).effort <= 0.0)
      out.problems.push_back("the joint " + std::string(M.joint_name(i)) +
                             " has no motor (no effort limit): the simulation cannot drive it; "
                             "give it one (joints.NAME.effort or defaults.effort)");
  for (const auto& l : M.links) {
    bool shaped = false;
    for (const auto& s : M.shapes) shaped = shaped || s.spec.link == l.spec.name;
    if (shaped && l.spec.mass <= 0.0)
      out.problems.push_back("the link " + std::string(l.spec.name.view()) +
                             " has collision shapes but no mass: give it one (defaults.density)");
  }
  // The trials: a ball and a cylinder held at the palm, the hand turned palm up so that gravity
  // keeps the object on the palm while the fingers close; each judged.
  const Eigen::Isometry3d root(Eigen::Quaterniond::FromTwoVectors(approach, Vec3::UnitZ()));
  for (const char* object : {"ball", "cylinder"}) {
    ObjectSpec spec;
    spec.mass = options.mass;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = centre;
    if (std::string_view(object) == "ball") {
      spec.shapes = {sphere("", {0.0, 0.0, 0.0}, radius)};
    } else {
      // Its axis (z) along the palm frame's x: across the thumb-to-fingers line.
      const Vec3 axis = up.cross(approach).normalized();
      pose.linear().col(2) = axis;
      pose.linear().col(0) = approach;
      pose.linear().col(1) = axis.cross(approach);
      spec.shapes = {cylinder("", Pose{}, radius, 2.0 * radius)};
    }
    spec.pose = to_pose(root * pose);
    HandScene<M> scene(root, q, spec, options.sim.scene);
    const auto closed = close_hand(scene, options.sim.close);
    HandTrial t;
    t.object = object;
    t.contacts = closed.contacts;
    if (closed.contacts == 0) {
      t.reason =
          "closing ended with no contact: the fingers close beside the object (is the "
          "palm centre frame turned? are the closing directions right?)";
    } else {
      const StabilityResult judged = stability_suite(scene, options.sim.stability);
      t.stable = judged.stable;
      t.reason = judged.reason;
    }
    out.trials.push_back(std::move(t));
  }
  return out;
}

}  // namespace topograsp

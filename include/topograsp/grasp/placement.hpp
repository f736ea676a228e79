// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Placing a hand on a free base: the base configuration that puts a frame at a pose, the
/// distance between a hand and an object, and moving a hand along a direction until it touches.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/composite.hpp>
#include <topograsp/geometry/model_shapes.hpp>
#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/kinematics/data.hpp>
#include <topograsp/kinematics/forward.hpp>

namespace topograsp {

/// The angles (rz, ry, rx) with R = Rz(rz) Ry(ry) Rx(rx), the order of a free base's joints.
/// At the singularity (ry = +-pi/2) rx is 0.
[[nodiscard]] inline Vec3 zyx_angles(const Mat3& R) noexcept {
  const double ry = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  if (std::abs(R(2, 0)) > 1.0 - 1e-12) return {std::atan2(-R(0, 1), R(1, 1)), ry, 0.0};
  return {std::atan2(R(1, 0), R(0, 0)), ry, std::atan2(R(2, 1), R(2, 2))};
}

/// The configuration of the free-base model \p M (built by on_free_base(), so its first six
/// entries are x, y, z, rz, ry, rx) that puts its frame \p frame at \p T_world_frame, with the
/// hand's own joints at \p q_hand (dim M.nq - 6).
template <const auto& M, EigenDense D>
[[nodiscard]] Vec<M.nq> place_frame(const Eigen::Isometry3d& T_world_frame, int frame,
                                    const D& q_hand) {
  static_assert(M.nq >= 6, "M must be a model on a free base");
  Vec<M.nq> q = Vec<M.nq>::Zero();
  q.template tail<M.nq - 6>() = q_hand;
  KinematicsData<M> d;
  forward_kinematics(d, q);
  const Eigen::Isometry3d base = T_world_frame * frame_pose(d, frame).inverse();
  q.template head<3>() = base.translation();
  q.template segment<3>(3) = zyx_angles(base.linear());
  return q;
}

/// The smallest signed distance (m) between any shape of the model and any part of \p object;
/// +infinity if either has no shapes. Requires forward_kinematics(d, q) first.
template <const auto& M>
[[nodiscard]] double hand_object_distance(const KinematicsData<M>& d, const Composite& object) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < M.n_shapes; ++i) {
    const Primitive s = world_shape(d, i);
    for (const Primitive& part : object.parts())
      best = std::min(best, signed_distance(s, part).distance);
  }
  return best;
}

/// Moves the free-base model \p M from configuration \p q along the world direction \p direction
/// (translating its base) until its shapes are \p gap from \p object, by conservative advancement:
/// each step moves by the current distance, which cannot overshoot. Returns the moved
/// configuration, or nothing if the hand travels \p max_travel without coming within gap (it
/// misses), or starts closer than gap.
template <const auto& M>
[[nodiscard]] std::optional<Vec<M.nq>> approach_until_contact(Vec<M.nq> q, const Vec3& direction,
                                                              const Composite& object,
                                                              double gap = 0.001,
                                                              double max_travel = 0.5) {
  const Vec3 u = direction.normalized();
  KinematicsData<M> d;
  double travelled = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    forward_kinematics(d, q);
    const double dist = hand_object_distance(d, object);
    if (!(dist >= gap)) return iteration == 0 ? std::nullopt : std::optional<Vec<M.nq>>(q);
    if (dist - gap < 1e-5) return q;
    const double step = dist - gap;
    if (travelled + step > max_travel) return std::nullopt;
    q.template head<3>() += step * u;
    travelled += step;
  }
  return q;
}

/// The parameters of approach_palm_first().
struct PalmApproachOptions {
  /// The fingers come no closer to the object than this (m). Default 0.002.
  double gap = 0.002;
  /// The palm comes this close (m); 0, the default, brings it to touch the object, as a person's
  /// palm meets what the hand closes on.
  double palm_gap = 0.0;
  /// The farthest the hand moves along the approach (m); it misses beyond. Default 0.5.
  double max_travel = 0.5;
  /// How far a closing joint opens at a time where its link comes too close (rad or m). Default
  /// 0.02.
  double open_step = 0.02;
  /// The farthest the hand slides sideways in all (m). Default 0.04.
  double max_slide = 0.04;
  /// How far it slides at a time (m). Default 0.002.
  double slide_step = 0.002;
};

/// The approach a human demonstrator makes with the free-base hand \p M: from configuration \p q
/// the base moves along the world direction \p direction until link \p palm (the palm) is
/// options.palm_gap from \p object, the fingers opening on the way wherever they would come closer
/// than options.gap (each closing joint that carries such a link moved back toward its open limit
/// by options.open_step at a time, LinkSpec::closing). Where a link can open no further (the base
/// of an opposed thumb, a finger at its open limit) the hand slides sideways, square to
/// \p direction and away from the object along that link's contact normal, by options.slide_step
/// at a time and options.max_slide in all, as a person shifts the hand until the object fits
/// between thumb and fingers (a slide that would take the palm farther from the object, off its
/// edge, is not made); where it can neither open nor slide it stops short of the palm's
/// contact, a blocked link within 0.1 mm of gap. First the whole hand moves in until it is gap
/// away (approach_until_contact()); then the palm advances by at most 5 mm at a time, in halved
/// steps where it is blocked. Returns the configuration, or nothing if the hand misses the object
/// within options.max_travel or starts closer than gap.
/// \throws topograsp::invalid_argument naming the field of \p options for a negative or
/// non-finite gap, palm_gap or max_slide, or a max_travel, open_step or slide_step that is not
/// positive and finite; naming "palm" for a link index outside the model.
template <const auto& M>
[[nodiscard]] std::optional<Vec<M.nq>> approach_palm_first(
    Vec<M.nq> q, const Vec3& direction, const Composite& object, int palm,
    const PalmApproachOptions& options = {}) {
  require_non_negative(options.gap, "options.gap");
  require_non_negative(options.palm_gap, "options.palm_gap");
  require_non_negative(options.max_slide, "options.max_slide");
  require_positive(options.max_travel, "options.max_travel");
  require_positive(options.open_step, "options.open_step");
  require_positive(options.slide_step, "options.slide_step");
  if (palm < 0 || palm >= static_cast<int>(M.n_links))
    detail::throw_invalid_argument("palm", "expected a link index in [0, " +
                                               std::to_string(M.n_links) + "), got " +
                                               std::to_string(palm));
  const double gap = options.gap, max_travel = options.max_travel;
  const auto first = approach_until_contact<M>(q, direction, object, gap, max_travel);
  if (!first) return std::nullopt;
  q = *first;
  const Vec3 u = direction.normalized();
  const Vec<M.nq> lo = lower_limits<M>(), hi = upper_limits<M>(), dir = closing_directions<M>();
  KinematicsData<M> d;
  // The distance of each link to the object (+infinity for a link without shapes), and the
  // normal of that nearest pair (unit, from the link toward the object).
  constexpr std::size_t n_links = std::remove_cvref_t<decltype(M)>::n_links;
  std::array<double, n_links> link_distance{};
  std::array<Vec3, n_links> link_normal{};
  const auto distances = [&](const Vec<M.nq>& c) {
    forward_kinematics(d, c);
    link_distance.fill(std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < M.n_shapes; ++i) {
      const Primitive s = world_shape(d, i);
      const auto l = static_cast<std::size_t>(M.shapes[i].link);
      for (const Primitive& part : object.parts()) {
        const Contact pair = signed_distance(s, part);
        if (pair.distance < link_distance[l]) {
          link_distance[l] = pair.distance;
          link_normal[l] = pair.normal;
        }
      }
    }
  };
  // Opens the joints that carry the links of c closer than gap (other than the palm) until none
  // is; false if one is at its open limits and still too close.
  const auto open_fingers = [&](Vec<M.nq>& c) {
    for (int round = 0; round < 1000; ++round) {
      distances(c);
      bool clear = true, opened = false;
      for (std::size_t l = 0; l < link_distance.size(); ++l) {
        if (static_cast<int>(l) == palm || link_distance[l] >= gap) continue;
        clear = false;
        for (const SupportJoint& j : M.support(static_cast<int>(l))) {
          if (dir[j.q] == 0.0) continue;
          const double open = std::clamp(c[j.q] - dir[j.q] * options.open_step, lo[j.q], hi[j.q]);
          opened = opened || open != c[j.q];
          c[j.q] = open;
        }
      }
      if (clear) return true;
      if (!opened) return false;
    }
    return false;
  };
  double travelled = 0.0, slid = 0.0, max_step = 0.005;
  for (int iteration = 0; iteration < 2000; ++iteration) {
    distances(q);
    const double to_palm = link_distance[static_cast<std::size_t>(palm)] - options.palm_gap;
    if (to_palm < 1e-5) return q;
    const double step = std::min(to_palm, max_step);
    if (travelled + step > max_travel) return q;
    Vec<M.nq> trial = q;
    trial.template head<3>() += step * u;
    if (!open_fingers(trial)) {
      // Blocked by links that cannot open (their distances are trial's): slide away from them,
      // square to the approach, if that leaves the hand clear.
      Vec3 away = Vec3::Zero();
      for (std::size_t l = 0; l < n_links; ++l)
        if (static_cast<int>(l) != palm && link_distance[l] < gap) away -= link_normal[l];
      away -= away.dot(u) * u;
      if (slid + options.slide_step <= options.max_slide && away.norm() > 1e-6) {
        Vec<M.nq> moved = q;
        moved.template head<3>() += options.slide_step * away.normalized();
        // Kept if the hand is clear there and the palm still faces the object (no farther).
        if (open_fingers(moved) &&
            link_distance[static_cast<std::size_t>(palm)] <= to_palm + options.palm_gap + 1e-6) {
          q = moved;
          slid += options.slide_step;
          max_step = 0.005;
          continue;
        }
      }
      // Blocked: go on in halved steps, down to 0.1 mm.
      max_step *= 0.5;
      if (max_step < 1e-4) return q;
      continue;
    }
    q = trial;
    travelled += step;
  }
  return q;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Box-based grasp hypotheses (BADGr, Huebner 2012): for every face of an object's boxes that a
/// hand can reach, four approaches along the inward face normal, the hand turned in 90-degree
/// steps about the approach axis.
#pragma once

#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/random.hpp>
#include <topograsp/grasp/object.hpp>

namespace topograsp {

/// One grasp hypothesis, in the object frame.
struct GraspHypothesis {
  int box = 0;                    ///< index into GraspObject::boxes
  int face = 0;                   ///< 0..5: the box's +x, -x, +y, -y, +z, -z face
  int turn = 0;                   ///< 0..3: turned turn * 90 degrees about the approach; -1: roll
  Vec3 centre = Vec3::Zero();     ///< the centre of the face (m)
  Vec3 approach = Vec3::UnitX();  ///< unit: the direction the hand moves, into the face
  Vec3 up = Vec3::UnitZ();        ///< unit, orthogonal to approach: where the fingers point
  double face_half_width = 0.0;   ///< half the face's extent across `up` (m)
  /// demonstrator_hypotheses() only: the roll about the approach in 45-degree steps (0..7), and
  /// the seed of this hypothesis's jitter (0: the nominal hypothesis, not jittered).
  int roll = 0;
  std::uint64_t jitter_seed = 0;
};

namespace detail {
// True if the point x (object frame) lies inside box b, grown by margin.
inline bool inside_box(const GraspBox& b, const Vec3& x, double margin) {
  const Vec3 local = b.pose.rotation().transpose() * (x - b.pose.translation());
  for (int k = 0; k < 3; ++k)
    if (std::abs(local[k]) > b.half[static_cast<std::size_t>(k)] + margin) return false;
  return true;
}
}  // namespace detail

/// The hypotheses of \p object: 4 per reachable box face. A face is reachable unless the point
/// 1 cm out from its centre lies inside another box of the decomposition (the face is covered by
/// another part). Deterministic order: box, face, turn.
[[nodiscard]] inline std::vector<GraspHypothesis> box_hypotheses(const GraspObject& object) {
  std::vector<GraspHypothesis> out;
  const double probe = 0.01;
  for (std::size_t b = 0; b < object.boxes.size(); ++b) {
    const GraspBox& box = object.boxes[b];
    const Mat3 R = box.pose.rotation();
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2;
      const double sign = face % 2 == 0 ? 1.0 : -1.0;
      const Vec3 normal = sign * R.col(axis);
      const Vec3 centre =
          box.pose.translation() + box.half[static_cast<std::size_t>(axis)] * normal;
      bool covered = false;
      for (std::size_t other = 0; other < object.boxes.size(); ++other)
        if (other != b && detail::inside_box(object.boxes[other], centre + probe * normal, 0.0))
          covered = true;
      if (covered) continue;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int turn = 0; turn < 4; ++turn) {
        GraspHypothesis h;
        h.box = static_cast<int>(b);
        h.face = face;
        h.turn = turn;
        h.centre = centre;
        h.approach = -normal;
        const int along = turn % 2 == 0 ? u : v;
        h.up = (turn < 2 ? 1.0 : -1.0) * R.col(along);
        h.face_half_width = box.half[static_cast<std::size_t>(turn % 2 == 0 ? v : u)];
        out.push_back(h);
      }
    }
  }
  return out;
}

/// The parameters of demonstrator_hypotheses(): how a human demonstrator varies a grasp.
struct DemonstratorVariation {
  int rolls = 8;                ///< rolls about the approach per face, evenly spaced
  int jittered = 1;             ///< jittered copies of each (face, roll), beside the nominal
  double max_shift = 0.015;     ///< largest move of the centre along each face axis (m)
  double max_tilt = deg(10.0);  ///< largest tilt of the approach (rad)
  double max_roll = deg(10.0);  ///< largest change of the roll (rad)
};

/// The grasp hypotheses a human demonstrator makes of \p object, by a rule fixed before any
/// result was seen: for every face that box_hypotheses() reaches, `rolls` rolls about the face's
/// inward normal (the first with `up` along the face's first axis, as box_hypotheses()' turn 0),
/// each once as is and `jittered` times varied as a person varies a grasp: the centre moved by a
/// uniform amount in [-s, s] along each face axis (s the smaller of max_shift and half the face's
/// half-extent along that axis), the approach tilted by a uniform angle in [0, max_tilt] toward a
/// uniform direction, the roll changed by a uniform angle in [-max_roll, max_roll]. Each jittered
/// hypothesis draws from its own seed, mixed from \p seed, the object's name and its (box, face,
/// roll, copy), so a hypothesis is the same whatever else is generated. Deterministic order:
/// box, face, roll, copy (nominal first). Throws topograsp::invalid_argument naming the field of
/// \p variation for rolls outside [1, 360], jittered outside [0, 100], or a negative or
/// non-finite amplitude.
[[nodiscard]] inline std::vector<GraspHypothesis> demonstrator_hypotheses(
    const GraspObject& object, std::uint64_t seed = 1,
    const DemonstratorVariation& variation = {}) {
  if (variation.rolls < 1 || variation.rolls > 360)
    detail::throw_invalid_argument("variation.rolls",
                                   "expected 1 to 360, got " + std::to_string(variation.rolls));
  if (variation.jittered < 0 || variation.jittered > 100)
    detail::throw_invalid_argument("variation.jittered",
                                   "expected 0 to 100, got " + std::to_string(variation.jittered));
  require_non_negative(variation.max_shift, "variation.max_shift");
  require_non_negative(variation.max_tilt, "variation.max_tilt");
  require_non_negative(variation.max_roll, "variation.max_roll");
  std::vector<GraspHypothesis> out;
  const std::uint64_t name_hash = detail::splitmix64_mix(detail::fnv1a_64(object.name));
  for (const GraspHypothesis& face : box_hypotheses(object)) {
    if (face.turn != 0) continue;  // one per face: its rolls are made here
    const GraspBox& box = object.boxes[static_cast<std::size_t>(face.box)];
    const Mat3 R = box.pose.rotation();
    const int axis = face.face / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    const double half_u = box.half[static_cast<std::size_t>(u)],
                 half_v = box.half[static_cast<std::size_t>(v)];
    for (int roll = 0; roll < variation.rolls; ++roll)
      for (int copy = 0; copy <= variation.jittered; ++copy) {
        GraspHypothesis h = face;
        h.roll = roll;
        double angle = 2.0 * pi * roll / variation.rolls;
        if (copy > 0) {
          const auto key =
              static_cast<std::uint64_t>(((face.box * 6 + face.face) * 1024 + roll) * 128 + copy);
          h.jitter_seed =
              detail::splitmix64_mix(seed ^ name_hash ^ (0x94d049bb133111ebull * (key + 1)));
          detail::SplitMix64 rng{h.jitter_seed};
          const auto unit = [](detail::SplitMix64& r) { return 2.0 * r.uniform() - 1.0; };
          const auto turn = [](detail::SplitMix64& r) { return 2.0 * pi * r.uniform(); };
          const double su = std::min(variation.max_shift, 0.5 * half_u),
                       sv = std::min(variation.max_shift, 0.5 * half_v);
          const double du = unit(rng) * su;  // one draw per statement: a fixed order
          const double dv = unit(rng) * sv;
          h.centre += du * R.col(u) + dv * R.col(v);
          const double tilt = 0.5 * (unit(rng) + 1.0) * variation.max_tilt, toward = turn(rng);
          const Vec3 side = std::cos(toward) * R.col(u) + std::sin(toward) * R.col(v);
          h.approach = (std::cos(tilt) * face.approach + std::sin(tilt) * side).normalized();
          angle += unit(rng) * variation.max_roll;
        }
        // Up: the face's first axis turned by the roll about the approach, made orthogonal.
        const Vec3 up0 = std::cos(angle) * R.col(u) + std::sin(angle) * R.col(v);
        h.up = (up0 - up0.dot(h.approach) * h.approach).normalized();
        h.turn = -1;
        h.face_half_width = std::abs(std::sin(angle)) * half_u + std::abs(std::cos(angle)) * half_v;
        out.push_back(h);
      }
  }
  return out;
}

}  // namespace topograsp

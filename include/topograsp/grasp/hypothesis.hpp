// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Box-based grasp hypotheses (BADGr, Huebner 2012): for every face of an object's boxes that a
/// hand can reach, four approaches along the inward face normal, the hand turned in 90-degree
/// steps about the approach axis; and two rules of a human demonstrator on the same faces: rolls
/// all round, jittered (demonstrator_hypotheses), and the power grip (power_grip_hypotheses).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Eigenvalues>
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
  /// demonstrator_hypotheses() and power_grip_hypotheses() only: the roll's index on its face
  /// (the demonstrator's: 45-degree steps, 0..7; the power grip's: end * rolls + k), and the
  /// seed of this hypothesis's jitter (0: the nominal hypothesis, not jittered).
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

namespace detail {

inline void check_variation(const DemonstratorVariation& variation) {
  if (variation.rolls < 1 || variation.rolls > 360)
    detail::throw_invalid_argument("variation.rolls",
                                   "expected 1 to 360, got " + std::to_string(variation.rolls));
  if (variation.jittered < 0 || variation.jittered > 100)
    detail::throw_invalid_argument("variation.jittered",
                                   "expected 0 to 100, got " + std::to_string(variation.jittered));
  require_non_negative(variation.max_shift, "variation.max_shift");
  require_non_negative(variation.max_tilt, "variation.max_tilt");
  require_non_negative(variation.max_roll, "variation.max_roll");
}

// The plane of a box_hypotheses() face: its first and second axes (object frame) and the box's
// half-extents along them; a roll angle is measured from u toward v.
struct FacePlane {
  Vec3 u, v;
  double half_u, half_v;
};

inline FacePlane face_plane(const GraspObject& object, const GraspHypothesis& face) {
  const GraspBox& box = object.boxes[static_cast<std::size_t>(face.box)];
  const Mat3 R = box.pose.rotation();
  const int axis = face.face / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
  return {R.col(u), R.col(v), box.half[static_cast<std::size_t>(u)],
          box.half[static_cast<std::size_t>(v)]};
}

// The hypothesis on \p face (a box_hypotheses() face, turn 0) rolled by \p angle about its
// inward normal from the face's first axis (roll index \p roll), and, for copy > 0, jittered by
// \p variation's amplitudes from its own seed (demonstrator_hypotheses() says how).
inline GraspHypothesis rolled_hypothesis(const GraspObject& object, const GraspHypothesis& face,
                                         int roll, double angle, int copy, std::uint64_t seed,
                                         std::uint64_t name_hash,
                                         const DemonstratorVariation& variation) {
  const auto [u, v, half_u, half_v] = face_plane(object, face);
  GraspHypothesis h = face;
  h.roll = roll;
  if (copy > 0) {
    const auto key =
        static_cast<std::uint64_t>(((face.box * 6 + face.face) * 1024 + roll) * 128 + copy);
    h.jitter_seed = splitmix64_mix(seed ^ name_hash ^ (0x94d049bb133111ebull * (key + 1)));
    SplitMix64 rng{h.jitter_seed};
    const auto unit = [](SplitMix64& r) { return 2.0 * r.uniform() - 1.0; };
    const auto turn = [](SplitMix64& r) { return 2.0 * pi * r.uniform(); };
    const double su = std::min(variation.max_shift, 0.5 * half_u),
                 sv = std::min(variation.max_shift, 0.5 * half_v);
    const double du = unit(rng) * su;  // one draw per statement: a fixed order
    const double dv = unit(rng) * sv;
    h.centre += du * u + dv * v;
    const double tilt = 0.5 * (unit(rng) + 1.0) * variation.max_tilt, toward = turn(rng);
    const Vec3 side = std::cos(toward) * u + std::sin(toward) * v;
    h.approach = (std::cos(tilt) * face.approach + std::sin(tilt) * side).normalized();
    angle += unit(rng) * variation.max_roll;
  }
  // Up: the face's first axis turned by the roll about the approach, made orthogonal.
  const Vec3 up0 = std::cos(angle) * u + std::sin(angle) * v;
  h.up = (up0 - up0.dot(h.approach) * h.approach).normalized();
  h.turn = -1;
  h.face_half_width = std::abs(std::sin(angle)) * half_u + std::abs(std::cos(angle)) * half_v;
  return h;
}

}  // namespace detail

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
  detail::check_variation(variation);
  std::vector<GraspHypothesis> out;
  const std::uint64_t name_hash = detail::splitmix64_mix(detail::fnv1a_64(object.name));
  for (const GraspHypothesis& face : box_hypotheses(object)) {
    if (face.turn != 0) continue;  // one per face: its rolls are made here
    for (int roll = 0; roll < variation.rolls; ++roll)
      for (int copy = 0; copy <= variation.jittered; ++copy)
        out.push_back(detail::rolled_hypothesis(object, face, roll,
                                                2.0 * pi * roll / variation.rolls, copy, seed,
                                                name_hash, variation));
  }
  return out;
}

/// The parameters of power_grip_hypotheses(): the band of the palm the part's long axis is laid
/// in, how far from the centre of mass the palm may grip, and the demonstrator's variation
/// (its `rolls` are the angles sampled in the band, each taken with either end of the part
/// toward the thumb).
struct PowerGrip {
  double band_low = deg(15.0);   ///< the band's first angle (rad): 0 lies across the palm
  double band_high = deg(60.0);  ///< its last; 45 degrees is the palm's oblique crease
  double max_offset = 0.08;      ///< largest distance of the centre of mass from the approach (m)
  /// A box has a long axis if its longest side is this many times the next; the object, if its
  /// second principal moment of inertia is this many times its least.
  double long_ratio = 1.1;
  DemonstratorVariation variation{.rolls = 5, .jittered = 3};
};

/// The angle (rad, in (-pi/2, pi/2]) at which the direction \p axis lies in the palm of a hand
/// approaching along \p approach with its fingers along \p up: 0 across the palm (along the
/// thumb's side, `up` x `approach`), pi/2 along the fingers, +pi/4 the right hand's oblique
/// palmar crease (from the hypothenar to the index finger's base); the two ends of \p axis give
/// the same angle. NaN if the component of \p axis (a unit vector) in the palm's plane is under
/// 0.3: the palm meets it end on.
[[nodiscard]] inline double palm_angle(const Vec3& axis, const Vec3& approach, const Vec3& up) {
  const Vec3 thumb = up.cross(approach);
  const double across = axis.dot(thumb), along = axis.dot(up);
  if (std::hypot(across, along) < 0.3) return std::numeric_limits<double>::quiet_NaN();
  double phi = std::atan2(along, across);
  if (phi > 0.5 * pi) phi -= pi;
  if (phi <= -0.5 * pi) phi += pi;
  return phi;
}

namespace detail {

// The long axis of \p box: its longest side's direction (object frame), if that side is at least
// \p ratio times the next.
inline std::optional<Vec3> long_axis(const GraspBox& box, double ratio) {
  std::array<double, 3> sorted = box.half;
  std::sort(sorted.begin(), sorted.end());
  if (!(sorted[2] >= ratio * sorted[1])) return std::nullopt;
  const auto k = std::max_element(box.half.begin(), box.half.end()) - box.half.begin();
  return Vec3(box.pose.rotation().col(k));
}

// The long axis of \p object: its principal axis of least inertia through the centre of mass, if
// the next moment is at least \p ratio times it (a ball, a cube have none).
inline std::optional<Vec3> long_axis(const GraspObject& object, double ratio) {
  const Mat3 inertia =
      object.inertial
          ? object.inertial->inertia
          : body_mass_properties<double>(object.parts, 0.0, 0.0, object.densities).inertia;
  Eigen::SelfAdjointEigenSolver<Mat3> eig;
  eig.computeDirect(inertia);  // ascending moments
  if (!(eig.eigenvalues()[1] >= ratio * eig.eigenvalues()[0])) return std::nullopt;
  return Vec3(eig.eigenvectors().col(0).normalized());
}

}  // namespace detail

/// The power grasps a human demonstrator makes of \p object (Napier's power grip: the part held
/// against the palm by the fingers and thumb, lying obliquely across the palm from the
/// hypothenar to the index finger's base), by a rule fixed on the development objects (the
/// hammer and the bottle; docs/evaluation.md, "The power grip"). For every face that
/// box_hypotheses() reaches, unless
/// - the object's centre of mass lies farther than `max_offset` from the line of approach
///   through the face's centre (a person grips near the centre of mass), or
/// - the face's long axis (below) meets it end on (palm_angle() NaN: the palm on a part's end),
/// `variation.rolls` angles evenly spaced in [band_low, band_high] (palm_angle() of the long
/// axis laid in the face's plane), each with either end of the axis toward the thumb, each once
/// as is and `variation.jittered` times varied as demonstrator_hypotheses() varies them. The
/// long axis is the face's box's longest side if it is `long_ratio` times its next, else the
/// object's principal axis of least inertia if the next moment is `long_ratio` times it (the
/// bottle's neck, a near cube, takes the bottle's axis); with neither (a ball) the face's rolls
/// are 2 * `variation.rolls` angles evenly spaced about the approach, as
/// demonstrator_hypotheses() spaces them. Roll index: end * rolls + k (the k-th angle of the
/// band; end 1 with the axis's negative end toward the thumb). Deterministic order: box, face,
/// roll, copy (nominal first); the seeds as demonstrator_hypotheses(). Throws
/// topograsp::invalid_argument naming the field of \p rule for an invalid variation (as
/// demonstrator_hypotheses()), a band outside
/// [-pi/2, pi/2] or with band_low > band_high, a negative or non-finite max_offset, or a
/// long_ratio below 1 or not finite.
[[nodiscard]] inline std::vector<GraspHypothesis> power_grip_hypotheses(
    const GraspObject& object, std::uint64_t seed = 1, const PowerGrip& rule = {}) {
  detail::check_variation(rule.variation);
  require_finite(rule.band_low, "rule.band_low");
  require_finite(rule.band_high, "rule.band_high");
  if (rule.band_low < -0.5 * pi || rule.band_high > 0.5 * pi || rule.band_low > rule.band_high)
    detail::throw_invalid_argument("rule.band_low",
                                   "expected -pi/2 <= band_low <= band_high <= pi/2, got " +
                                       std::to_string(rule.band_low) + " and " +
                                       std::to_string(rule.band_high));
  require_non_negative(rule.max_offset, "rule.max_offset");
  if (!(rule.long_ratio >= 1.0) || !std::isfinite(rule.long_ratio))
    detail::throw_invalid_argument(
        "rule.long_ratio", "expected a number >= 1, got " + std::to_string(rule.long_ratio));
  const int n = rule.variation.rolls;
  std::vector<GraspHypothesis> out;
  const std::uint64_t name_hash = detail::splitmix64_mix(detail::fnv1a_64(object.name));
  const Vec3 com = object.centre_of_mass();
  const std::optional<Vec3> object_axis = detail::long_axis(object, rule.long_ratio);
  for (const GraspHypothesis& face : box_hypotheses(object)) {
    if (face.turn != 0) continue;
    const Vec3 off = com - face.centre;
    if ((off - off.dot(face.approach) * face.approach).norm() > rule.max_offset) continue;
    const GraspBox& box = object.boxes[static_cast<std::size_t>(face.box)];
    const detail::FacePlane plane = detail::face_plane(object, face);
    std::optional<Vec3> long_axis = detail::long_axis(box, rule.long_ratio);
    if (!long_axis) long_axis = object_axis;
    if (long_axis) {  // laid in the face's plane; a face it meets end on is left out
      const Vec3 in_plane = *long_axis - long_axis->dot(face.approach) * face.approach;
      if (in_plane.norm() < 0.3) continue;
      long_axis = in_plane.normalized();
    }
    for (int roll = 0; roll < 2 * n; ++roll) {
      double angle = 2.0 * pi * roll / (2 * n);  // from the face's first axis, as rolled_hypothesis
      if (long_axis) {
        // Up for palm angle phi: sin(phi) L + cos(phi) (approach x L), L the long axis (or its
        // negative end); as an angle from the face's first axis u toward v.
        const int k = roll % n, end = roll / n;
        const double phi = n == 1 ? 0.5 * (rule.band_low + rule.band_high)
                                  : rule.band_low + (rule.band_high - rule.band_low) * k / (n - 1);
        const Vec3 L = (end == 0 ? 1.0 : -1.0) * *long_axis;
        const Vec3 up = std::sin(phi) * L + std::cos(phi) * face.approach.cross(L);
        angle = std::atan2(up.dot(plane.v), up.dot(plane.u));
      }
      for (int copy = 0; copy <= rule.variation.jittered; ++copy)
        out.push_back(detail::rolled_hypothesis(object, face, roll, angle, copy, seed, name_hash,
                                                rule.variation));
    }
  }
  return out;
}

}  // namespace topograsp

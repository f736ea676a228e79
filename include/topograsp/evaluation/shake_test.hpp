// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// shake_test(): the library's stability protocol for a grasp: settle under gravity, rotate the
/// hand randomly (seeded) for 100 steps, check the object is still held.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/random.hpp>
#include <topograsp/evaluation/hand_scene.hpp>

namespace topograsp {

/// Where the shake rotations are centred.
enum class ShakePivot : std::uint8_t {
  palm,    ///< the model's palm centre (the root link's origin for a model without a hand)
  object,  ///< the object's centre of mass at the start of the shake
};

/// The most settle or shake steps (and shakes) shake_test() and gravity_test() accept: 1e6 steps,
/// 4.6 hours simulated at 60 Hz, far beyond any test, and their sum far from INT_MAX.
inline constexpr int k_max_shake_steps = 1000000;

/// The parameters of shake_test() and gravity_test(); defaults as in docs/evaluation.md.
struct ShakeOptions {
  /// Steps of settling under gravity, hand still, before the measurement starts. Default 30
  /// (0.5 s at 60 Hz).
  int settle_steps = 30;
  /// Steps of shaking. Default 100 (1.67 s at 60 Hz), as in the paper.
  int shake_steps = 100;
  /// Random rotations in the shake, one after the other, each out and back along
  /// angle(t) = A (1 - cos(2 pi t / T)) / 2 so velocity is zero at both ends. Default 2.
  int shakes = 2;
  /// The amplitude A of each rotation is uniform in [min_angle, max_angle] (rad). Default 20 to
  /// 60 degrees.
  double min_angle = deg(20.0);
  double max_angle = deg(60.0);
  /// Seed of the axes (uniform on the sphere) and amplitudes; equal seeds give equal shakes.
  std::uint64_t seed = 1;
  /// Stable only if the object moved less than this in the hand frame (m). Default 2 cm.
  double max_translation = 0.02;
  /// Stable only if the object turned less than this in the hand frame (rad). Default 15 degrees.
  double max_rotation = deg(15.0);
  /// The object touches the hand when a contact's separation is at most this (m). Default 1 mm.
  double touch_distance = 0.001;
  /// Centre of the rotations. Default the palm.
  ShakePivot pivot = ShakePivot::palm;
};

/// The verdict and measurements of shake_test().
struct ShakeResult {
  bool stable = false;              ///< touching, finite, within both thresholds, status success
  Status status = Status::success;  ///< Status::numerical_issue if the stepper failed
  std::string_view reason = "";     ///< why not stable ("" when stable)
  double translation = 0.0;         ///< object displacement in the hand frame (m)
  double rotation = 0.0;            ///< object rotation in the hand frame (rad)
  int contacts = 0;                 ///< hand-object contact points at the end
  double force = 0.0;               ///< total hand-object normal force at the end (N)
  bool finite = true;               ///< every measured number finite
  double simulated_time = 0.0;      ///< seconds simulated (settle plus shake)
  int steps = 0;                    ///< steps taken
};

namespace detail {

// Displacement and rotation of the object in the hand frame since `reference`.
inline void object_motion(const Eigen::Isometry3d& reference, const Eigen::Isometry3d& now,
                          double& translation, double& rotation) noexcept {
  translation = (now.translation() - reference.translation()).norm();
  rotation = rotation_angle<double>(Mat3(reference.linear().transpose() * now.linear()));
}

inline void require_shake_options(const ShakeOptions& options) {
  if (options.settle_steps < 0 || options.settle_steps > k_max_shake_steps)
    throw_invalid_argument("options.settle_steps",
                           "expected 0 to 1000000, got " + std::to_string(options.settle_steps));
  if (options.shake_steps < 0 || options.shake_steps > k_max_shake_steps)
    throw_invalid_argument("options.shake_steps",
                           "expected 0 to 1000000, got " + std::to_string(options.shake_steps));
  if (options.shakes < 1 || options.shakes > k_max_shake_steps)
    throw_invalid_argument("options.shakes",
                           "expected 1 to 1000000, got " + std::to_string(options.shakes));
  require_finite(options.min_angle, "options.min_angle");
  require_finite(options.max_angle, "options.max_angle");
  if (std::abs(options.min_angle) > two_pi)
    throw_invalid_argument("options.min_angle", "expected at most a full turn (2 pi rad)");
  if (std::abs(options.max_angle) > two_pi)
    throw_invalid_argument("options.max_angle", "expected at most a full turn (2 pi rad)");
}

template <class Result>
void judge(Result& r, int contacts, double translation, double rotation,
           const ShakeOptions& o) noexcept {
  r.finite = std::isfinite(translation) && std::isfinite(rotation);
  if (r.status != Status::success)
    r.reason = "the simulation failed (non-finite or exploding state)";
  else if (!r.finite)
    r.reason = "a measurement is not finite";
  else if (contacts == 0)
    r.reason = "the object no longer touches the hand";
  else if (!(translation < o.max_translation))
    r.reason = "the object moved too far in the hand";
  else if (!(rotation < o.max_rotation))
    r.reason = "the object turned too far in the hand";
  else
    r.reason = "";
  r.stable = r.reason.empty();
}

}  // namespace detail

/// Runs the shake test on \p scene (which it advances; copy the scene first to keep it), after
/// close_hand(): (1) options.settle_steps steps under gravity with the hand still; the object's
/// pose in the hand frame is the reference; (2) options.shake_steps steps of options.shakes
/// seeded random rotations of the hand about an axis through the pivot, each smooth and out and
/// back, amplitude in [min_angle, max_angle]; (3) stable iff the status is success, the object
/// still touches the hand, every number is finite, and the object moved less than
/// max_translation and turned less than max_rotation in the hand frame. Allocates nothing.
/// Throws topograsp::invalid_argument for step counts outside [0, k_max_shake_steps], shakes
/// outside [1, k_max_shake_steps], angles that are not finite or beyond a full turn (2 pi), or
/// non-finite or non-positive thresholds.
template <const auto& M, class S>
ShakeResult shake_test(HandScene<M, S>& scene, const ShakeOptions& options = {}) {
  detail::require_shake_options(options);
  if (options.max_angle < options.min_angle)
    detail::throw_invalid_argument("options.max_angle", "expected >= options.min_angle");
  require_positive(options.max_translation, "options.max_translation");
  require_positive(options.max_rotation, "options.max_rotation");
  require_finite(options.touch_distance, "options.touch_distance");
  ShakeResult r;
  const double dt = scene.world().options().time_step;
  for (int i = 0; i < options.settle_steps && r.status == Status::success; ++i) {
    r.status = scene.step();
    ++r.steps;
  }
  const Eigen::Isometry3d reference = scene.object_in_hand();
  const Eigen::Isometry3d start = scene.hand_pose();
  Vec3 pivot;
  if (options.pivot == ShakePivot::object) {
    pivot = scene.world().body(scene.object_body()).x.template cast<double>();
  } else if constexpr (M.is_hand()) {
    pivot = start * world_point(scene.kinematics(), M.palm);
  } else {
    pivot = start.translation();
  }
  detail::SplitMix64 rng{options.seed};
  const int length = std::max(1, options.shake_steps / options.shakes);
  Vec3 axis = Vec3::UnitZ();
  double amplitude = 0.0;
  for (int k = 0; k < options.shake_steps && r.status == Status::success; ++k) {
    const int j = std::min(k / length, options.shakes - 1);
    const int begin = j * length;
    const int end = j == options.shakes - 1 ? options.shake_steps : begin + length;
    if (k == begin) {
      // A new rotation: axis uniform on the sphere, amplitude uniform in the range.
      const double z = 2.0 * rng.uniform() - 1.0, phi = two_pi * rng.uniform();
      const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
      axis = Vec3(s * std::cos(phi), s * std::sin(phi), z);
      amplitude = options.min_angle + (options.max_angle - options.min_angle) * rng.uniform();
    }
    const double t = static_cast<double>(k + 1 - begin) / static_cast<double>(end - begin);
    const double angle = amplitude * 0.5 * (1.0 - std::cos(two_pi * t));
    Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
    turn.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    turn.translation() = pivot - turn.linear() * pivot;
    scene.set_hand_pose(turn * start);
    r.status = scene.step();
    ++r.steps;
  }
  r.simulated_time = r.steps * dt;
  detail::object_motion(reference, scene.object_in_hand(), r.translation, r.rotation);
  r.contacts = scene.hand_contacts(options.touch_distance);
  r.force = scene.hand_force();
  detail::judge(r, r.contacts, r.translation, r.rotation, options);
  if (!std::isfinite(r.force)) {
    r.finite = false;
    r.stable = false;
    r.reason = "a measurement is not finite";
  }
  return r;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// stability_suite(): the library's stability protocol for a grasp, one implementation for every
/// engine (any GraspScene): from the state in which closing ended, the paper's shake, gravity
/// along the six axis directions of the hand frame, and a hard shake reported as a stress.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/parameters.hpp>
#include <topograsp/core/random.hpp>
#include <topograsp/core/status.hpp>
#include <topograsp/evaluation/grasp_scene.hpp>
#include <topograsp/evaluation/statistics.hpp>
#include <topograsp/physics/detail/math.hpp>

namespace topograsp {

/// Where the shake rotations are centred.
enum class ShakePivot : std::uint8_t {
  palm,    ///< the scene's palm centre (GraspScene::palm_centre()) when closing ended
  object,  ///< the object's centre of mass when closing ended
};

/// The most steps (and rotations) of one test that stability_suite() accepts: 1e6 steps, 4.6
/// hours simulated at 60 Hz, far beyond any test and far from INT_MAX.
inline constexpr int k_max_suite_steps = 1000000;

/// One shake: `rotations` seeded random rotations of the hand one after the other over `steps`
/// steps, each about an axis uniform on the sphere through the pivot, out and back along
/// angle(t) = A (1 - cos(2 pi t / T)) / 2 (zero velocity at both ends), the amplitude A uniform
/// in [min_angle, max_angle] (rad).
struct ShakeMotion {
  int steps = 100;               ///< steps of the whole shake
  int rotations = 2;             ///< rotations in it, each steps / rotations long
  double min_angle = deg(20.0);  ///< rad
  double max_angle = deg(60.0);  ///< rad
};

/// The parameters of stability_suite(); defaults as in docs/evaluation.md.
struct StabilityOptions {
  /// The paper's shake: 2 rotations of 20 to 60 degrees over 100 steps (1.67 s at 60 Hz).
  ShakeMotion shake{};
  /// Steps of each of the six gravity directions: 120 (2 s at 60 Hz, as DexGraspBench/BODex;
  /// DexGraspNet uses 100 steps of 1/60 s).
  int direction_steps = 120;
  /// The hard shake, a stress reported apart from `stable`: 4 rotations of 90 to 180 degrees over
  /// 400 steps. steps = 0 skips it (its record then says "not run").
  ShakeMotion hard_shake{400, 4, deg(90.0), deg(180.0)};
  /// Seed of the shakes' axes and amplitudes (the hard shake uses a stream mixed from it); equal
  /// seeds give equal shakes.
  std::uint64_t seed = 1;
  /// A test passes only if the object moved less than this in the hand frame (m). Default 2 cm.
  double max_translation = 0.02;
  /// A test passes only if the object turned less than this in the hand frame (rad). Default 15
  /// degrees.
  double max_rotation = deg(15.0);
  /// The object touches the hand when a contact's separation is at most this (m). Default 1 mm.
  double touch_distance = 0.001;
  /// A grasp whose hand overlaps the object deeper than this when closing ended fails every test
  /// it runs (the shake, and so the suite, unless every_test) (m). Default 1 cm, as
  /// DexGraspBench/BODex.
  double max_penetration = 0.01;
  /// Centre of the shakes' rotations. Default the palm.
  ShakePivot pivot = ShakePivot::palm;
  /// false (default): the suite stops at the first failed test among those that count (the shake,
  /// then the six directions in order): the tests after it are not run, and the hard shake runs
  /// only on a stable grasp. `stable` and `reason` are the same as with true (every test starts
  /// afresh from the closing state), for about half the steps over a run where most
  /// grasps fail. true: every test runs on every grasp, so an unstable grasp has all its records
  /// (which directions it fails, how far the object went in each).
  bool every_test = false;
};

/// The numeric fields of StabilityOptions but the shakes, with their valid ranges
/// (validate_stability_options checks them).
inline constexpr ParameterTable<StabilityOptions, 5> stability_parameters{{
    {"direction_steps", &StabilityOptions::direction_steps, 1, k_max_suite_steps,
     "steps of each gravity direction"},
    {"max_translation", &StabilityOptions::max_translation, 0.0, unbounded,
     "m: the object's largest slip in the hand", true},
    {"max_rotation", &StabilityOptions::max_rotation, 0.0, unbounded,
     "rad: the object's largest turn in the hand", true},
    {"touch_distance", &StabilityOptions::touch_distance, 0.0, unbounded,
     "m: the object touches the hand within this separation"},
    {"max_penetration", &StabilityOptions::max_penetration, 0.0, unbounded,
     "m: the deepest overlap when closing ended", true},
}};

/// The tests of the suite, in the order of StabilityResult::tests.
enum class StabilityTest : std::uint8_t {
  shake,       ///< the paper's shake
  gravity_px,  ///< gravity along +x of the hand frame
  gravity_nx,  ///< -x
  gravity_py,  ///< +y
  gravity_ny,  ///< -y
  gravity_pz,  ///< +z
  gravity_nz,  ///< -z
  hard_shake,  ///< the stress test, not part of `stable`
};

/// The number of tests in the suite.
inline constexpr std::size_t k_stability_tests = 8;

/// The name of test \p t as results.json writes it: "shake", "gravity_+x", "gravity_-x",
/// "gravity_+y", "gravity_-y", "gravity_+z", "gravity_-z", "hard_shake".
[[nodiscard]] constexpr std::string_view to_string(StabilityTest t) noexcept {
  constexpr std::array<std::string_view, k_stability_tests> names{
      "shake",      "gravity_+x", "gravity_-x", "gravity_+y",
      "gravity_-y", "gravity_+z", "gravity_-z", "hard_shake"};
  const auto i = static_cast<std::size_t>(t);
  return i < names.size() ? names[i] : "unknown";
}

/// The record of one test of the suite.
struct StabilityRecord {
  StabilityTest test = StabilityTest::shake;
  std::string_view name = "";       ///< to_string(test)
  bool passed = false;              ///< see stability_suite()
  std::string_view reason = "";     ///< why not passed, a sentence ("" when passed)
  double translation = 0.0;         ///< object displacement in the hand frame since closing (m)
  double rotation = 0.0;            ///< object rotation in the hand frame since closing (rad)
  int contacts = 0;                 ///< hand-object contacts within touch_distance at the end
  double force_median = 0.0;        ///< median over the steps of the total normal force (N)
  double force_end = 0.0;           ///< total normal force at the end (N)
  double force_ratio = 0.0;         ///< force_median / (m |g|)
  double penetration = 0.0;         ///< deepest hand-object overlap over the steps (m)
  int steps = 0;                    ///< steps taken (0: the test was not run)
  Status status = Status::success;  ///< the first failed step's status, else success
};

/// A judge whose collider reports the deepest hand-object contact more than this (m) deeper
/// than it is (StabilityResult::collider_error) judged a different grasp from the one closed:
/// results.json gives the engines' agreement with and without such verdicts.
inline constexpr double k_collider_tolerance = 0.001;

/// The verdict of stability_suite() and a record per test.
struct StabilityResult {
  /// The paper's shake and all six gravity directions passed (the hard shake does not count).
  bool stable = false;
  /// Why not stable: "<test>: <its reason>" of the first failed test among those that count
  /// ("" if stable), e.g. "gravity_-z: the object no longer touches the hand".
  std::string reason;
  double weight = 0.0;               ///< m |g| of the object (N)
  double closing_penetration = 0.0;  ///< deepest overlap when closing ended (m)
  /// How much deeper than the exact overlap (geometry's signed_distance) the engine's collider
  /// reports its deepest hand-object contact when closing ended (m, >= 0): the scene's
  /// collider_error() where it has one (MujocoScene), 0 for a scene whose contacts are exact (the
  /// built-in HandScene).
  double collider_error = 0.0;
  /// shake, gravity +x, -x, +y, -y, +z, -z (hand frame), hard_shake.
  std::array<StabilityRecord, k_stability_tests> tests{};
  [[nodiscard]] const StabilityRecord& operator[](StabilityTest t) const noexcept {
    return tests[static_cast<std::size_t>(t)];
  }
  [[nodiscard]] const StabilityRecord& shake() const noexcept {
    return (*this)[StabilityTest::shake];
  }
  [[nodiscard]] const StabilityRecord& hard_shake() const noexcept {
    return (*this)[StabilityTest::hard_shake];
  }
};

namespace detail {

// Displacement and rotation of the object in the hand frame since `reference`.
inline void object_motion(const Eigen::Isometry3d& reference, const Eigen::Isometry3d& now,
                          double& translation, double& rotation) noexcept {
  translation = (now.translation() - reference.translation()).norm();
  rotation = rotation_angle<double>(Mat3(reference.linear().transpose() * now.linear()));
}

inline void require_steps(int steps, int min, std::string_view name) {
  if (steps < min || steps > k_max_suite_steps)
    throw_invalid_argument(
        name, "expected " + std::to_string(min) + " to 1000000, got " + std::to_string(steps));
}

inline void require_shake_motion(const ShakeMotion& m, int min_steps, std::string_view name) {
  const std::string n(name);
  require_steps(m.steps, min_steps, n + ".steps");
  if (m.rotations < 1 || m.rotations > k_max_suite_steps)
    throw_invalid_argument(n + ".rotations",
                           "expected 1 to 1000000, got " + std::to_string(m.rotations));
  require_finite(m.min_angle, n + ".min_angle");
  require_finite(m.max_angle, n + ".max_angle");
  if (std::abs(m.min_angle) > two_pi)
    throw_invalid_argument(n + ".min_angle", "expected at most a full turn (2 pi rad)");
  if (std::abs(m.max_angle) > two_pi)
    throw_invalid_argument(n + ".max_angle", "expected at most a full turn (2 pi rad)");
  if (m.max_angle < m.min_angle)
    throw_invalid_argument(n + ".max_angle", "expected >= " + n + ".min_angle");
}

// Runs one test on `scene` (a copy of the closing-end state): `steps` steps, the hand at
// `motion(k)` before step k (or still if the motion is null), then the verdict.
template <GraspScene Scene, class Motion>
void run_test(Scene& scene, int steps, const Motion& motion, const Eigen::Isometry3d& reference,
              const StabilityOptions& o, double weight, bool too_deep, std::vector<double>& forces,
              StabilityRecord& r) {
  double deepest = 0.0;
  for (int k = 0; k < steps && r.status == Status::success; ++k) {
    motion(scene, k);
    r.status = scene.step();
    ++r.steps;
    forces[static_cast<std::size_t>(k)] = scene.hand_force();
    deepest = std::max(deepest, static_cast<double>(scene.deepest_penetration()));
  }
  object_motion(reference, scene.object_in_hand(), r.translation, r.rotation);
  r.contacts = scene.hand_contacts(o.touch_distance);
  r.force_end = scene.hand_force();
  r.force_median =
      r.steps > 0 ? median(std::span(forces).first(static_cast<std::size_t>(r.steps))) : 0.0;
  r.force_ratio = r.force_median / weight;
  r.penetration = deepest;
  const bool finite = std::isfinite(r.translation) && std::isfinite(r.rotation) &&
                      std::isfinite(r.force_end) && std::isfinite(r.force_median) &&
                      std::isfinite(r.penetration);
  if (too_deep)
    r.reason = "the hand penetrated the object deeper than max_penetration when closing ended";
  else if (r.status != Status::success)
    r.reason = "the simulation failed (non-finite or exploding state)";
  else if (!finite)
    r.reason = "a measurement is not finite";
  else if (r.contacts == 0)
    r.reason = "the object no longer touches the hand";
  else if (!(r.translation < o.max_translation))
    r.reason = "the object moved too far in the hand";
  else if (!(r.rotation < o.max_rotation))
    r.reason = "the object turned too far in the hand";
  else
    r.reason = "";
  r.passed = r.reason.empty();
}

// The hand pose of step k of a shake: each rotation out and back about a seeded axis through the
// pivot, applied to the closing-end hand pose `start`.
class ShakePath {
 public:
  ShakePath(const ShakeMotion& m, std::uint64_t seed, const Eigen::Isometry3d& start,
            const Vec3& pivot) noexcept
      : m_(m),
        rng_{seed},
        start_(start),
        pivot_(pivot),
        length_(std::max(1, m.steps / m.rotations)) {}

  [[nodiscard]] Eigen::Isometry3d pose(int k) noexcept {
    const int j = std::min(k / length_, m_.rotations - 1);
    const int begin = j * length_;
    const int end = j == m_.rotations - 1 ? m_.steps : begin + length_;
    if (k == begin) {
      // A new rotation: axis uniform on the sphere, amplitude uniform in the range.
      const double z = 2.0 * rng_.uniform() - 1.0, phi = two_pi * rng_.uniform();
      const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
      axis_ = Vec3(s * std::cos(phi), s * std::sin(phi), z);
      amplitude_ = m_.min_angle + (m_.max_angle - m_.min_angle) * rng_.uniform();
    }
    const double t = static_cast<double>(k + 1 - begin) / static_cast<double>(end - begin);
    const double angle = amplitude_ * 0.5 * (1.0 - std::cos(two_pi * t));
    Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
    turn.linear() = Eigen::AngleAxisd(angle, axis_).toRotationMatrix();
    turn.translation() = pivot_ - turn.linear() * pivot_;
    return turn * start_;
  }

 private:
  ShakeMotion m_;
  SplitMix64 rng_;
  Eigen::Isometry3d start_;
  Vec3 pivot_;
  int length_;
  Vec3 axis_ = Vec3::UnitZ();
  double amplitude_ = 0.0;
};

}  // namespace detail

/// Checks \p options as stability_suite() does; error messages name the option after \p name
/// ("options.shake.steps", or "transfer.sim.stability.shake.steps" with that \p name).
/// \throws topograsp::invalid_argument naming the option for a field of stability_parameters
/// outside its range, shake steps outside [1, k_max_suite_steps] (the hard shake's
/// [0, k_max_suite_steps]), rotations outside [1, k_max_suite_steps], angles not finite, beyond a
/// full turn (2 pi) or with max_angle < min_angle, or a pivot that is not a ShakePivot.
inline void validate_stability_options(const StabilityOptions& options,
                                       std::string_view name = "options") {
  const std::string n(name);
  detail::require_shake_motion(options.shake, 1, n + ".shake");
  detail::require_shake_motion(options.hard_shake, 0, n + ".hard_shake");
  validate_parameters(options, stability_parameters, n + ".");
  if (options.pivot != ShakePivot::palm && options.pivot != ShakePivot::object)
    detail::throw_invalid_argument(n + ".pivot", "expected palm or object");
}

/// Runs the stability suite on one copy of \p closed, the scene at the moment closing ended (its
/// gravity is the scene's), which it leaves as it is. The object's pose in the hand frame in
/// \p closed is the reference of every test (no settling first: slip while settling counts).
/// Each test starts from the state of \p closed, assigned afresh to one working scene, and takes
/// its steps at closed.time_step():
///  1. shake: options.shake (2 seeded random rotations of 20 to 60 degrees, 100 steps) about the
///     pivot, gravity as in the scene;
///  2. gravity_+x .. gravity_-z: the hand still, gravity of the scene's magnitude along +x, -x,
///     +y, -y, +z, -z of the hand frame in turn, options.direction_steps steps each (120);
///  3. hard_shake: options.hard_shake (4 rotations of 90 to 180 degrees, 400 steps; a stream
///     mixed from the seed), a stress reported apart.
/// Unless options.every_test, the first of tests 1 and 2 that fails ends the suite: the records
/// of the tests not run have steps 0, passed false and a reason "not run (...)", and the hard
/// shake is run only on a stable grasp; `stable` and `reason` do not depend on every_test.
/// A test passes iff the closing-end overlap is at most max_penetration, every step succeeded,
/// every measurement is finite, the object still touches the hand (a contact within
/// touch_distance) and it moved less than max_translation and turned less than max_rotation in
/// the hand frame. Stable iff the shake and all six directions pass. Allocates one scene copy and
/// one force buffer per call, nothing inside the step loops. Deterministic for equal inputs.
/// \throws topograsp::invalid_argument as validate_stability_options(), and naming
/// "closed.gravity()" when the scene's gravity is zero or not finite (the directions use its
/// magnitude) or "closed.object_mass()" when the mass is not positive; nothing is stepped then.
template <GraspScene Scene>
[[nodiscard]] StabilityResult stability_suite(const Scene& closed,
                                              const StabilityOptions& options = {}) {
  validate_stability_options(options);
  const Vec3 g = closed.gravity();
  const double magnitude = g.norm();
  if (!std::isfinite(magnitude) || !(magnitude > 0.0))
    detail::throw_invalid_argument("closed.gravity()",
                                   "expected a finite non-zero gravity (the six directions use "
                                   "its magnitude)");
  const double mass = closed.object_mass();
  if (!std::isfinite(mass) || !(mass > 0.0))
    detail::throw_invalid_argument("closed.object_mass()", "expected a positive finite mass");
  StabilityResult out;
  out.weight = mass * magnitude;
  out.closing_penetration = closed.deepest_penetration();
  if constexpr (requires { closed.collider_error(); }) out.collider_error = closed.collider_error();
  const bool too_deep = !(out.closing_penetration <= options.max_penetration);
  const Eigen::Isometry3d reference = closed.object_in_hand();
  const Eigen::Isometry3d start = closed.hand_pose();
  const Vec3 pivot =
      options.pivot == ShakePivot::object ? Vec3(closed.object_com()) : Vec3(closed.palm_centre());
  const int most =
      std::max({options.shake.steps, options.direction_steps, options.hard_shake.steps, 1});
  std::vector<double> forces(static_cast<std::size_t>(most));
  for (std::size_t i = 0; i < k_stability_tests; ++i) {
    out.tests[i].test = static_cast<StabilityTest>(i);
    out.tests[i].name = to_string(out.tests[i].test);
  }
  // One working scene, reset to the closing state before each test: copy assignment reuses
  // its buffers (a MujocoScene's mjData), so a suite allocates one scene, not one per test.
  Scene scene = closed;
  const auto shake = [&](const ShakeMotion& m, std::uint64_t seed, StabilityRecord& r) {
    scene = closed;
    detail::ShakePath path(m, seed, start, pivot);
    detail::run_test(
        scene, m.steps, [&](Scene& s, int k) { s.set_hand_pose(path.pose(k)); }, reference, options,
        out.weight, too_deep, forces, r);
  };
  // The tests that count, in order; without every_test, the first failure ends the suite.
  const auto failed = [&](std::size_t i) {
    if (out.tests[i].passed) return false;
    if (out.stable)
      out.reason = std::string(out.tests[i].name) + ": " + std::string(out.tests[i].reason);
    out.stable = false;
    return !options.every_test;
  };
  out.stable = true;
  shake(options.shake, options.seed, out.tests[0]);
  bool stopped = failed(0);
  for (int d = 0; d < 6 && !stopped; ++d) {
    const auto i = static_cast<std::size_t>(1 + d);
    scene = closed;
    Vec3 local = Vec3::Zero();
    local[d / 2] = d % 2 == 0 ? 1.0 : -1.0;
    scene.set_gravity(magnitude * (start.linear() * local));
    detail::run_test(
        scene, options.direction_steps, [](Scene&, int) {}, reference, options, out.weight,
        too_deep, forces, out.tests[i]);
    stopped = failed(i);
  }
  StabilityRecord& hard = out.tests[k_stability_tests - 1];
  if (options.hard_shake.steps == 0)
    hard.reason = "not run (options.hard_shake.steps is 0)";
  else if (stopped)
    hard.reason = "not run (the grasp is not stable)";
  else
    shake(options.hard_shake, detail::splitmix64_mix(options.seed ^ 0x68617264ull), hard);
  if (stopped)
    for (std::size_t i = 1; i + 1 < k_stability_tests; ++i)
      if (out.tests[i].steps == 0 && out.tests[i].reason.empty())
        out.tests[i].reason = "not run (an earlier test failed)";
  return out;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// gravity_test(): DexGraspNet's check of a grasp: gravity along each of the six axis directions
/// of the hand frame in turn; the grasp must hold in all six.
#pragma once

#include <array>
#include <string>

#include <topograsp/evaluation/shake_test.hpp>

namespace topograsp {

/// The verdict and measurements of gravity_test(), one entry per direction in the order
/// +x, -x, +y, -y, +z, -z of the hand frame.
struct GravityTestResult {
  bool stable = false;                  ///< held in all six directions
  Status status = Status::success;      ///< the first failure of the stepper, if any
  std::array<bool, 6> held{};           ///< touching, finite, within the thresholds
  std::array<double, 6> translation{};  ///< object displacement in the hand frame (m)
  std::array<double, 6> rotation{};     ///< object rotation in the hand frame (rad)
  std::array<int, 6> contacts{};        ///< hand-object contact points at the end
};

/// Runs the six-gravity-direction test on copies of \p scene (which is left as it is): for each
/// direction, the hand still, gravity of the scene's magnitude along that axis of the hand frame,
/// options.shake_steps steps (100 by default); held iff the object still touches the hand, moved
/// less than options.max_translation and turned less than options.max_rotation in the hand frame
/// and all numbers are finite. Copies the scene (allocates) once per direction.
template <const auto& M, class S>
GravityTestResult gravity_test(const HandScene<M, S>& scene, const ShakeOptions& options = {}) {
  if (options.shake_steps < 0 || options.shake_steps > k_max_shake_steps)
    detail::throw_invalid_argument(
        "options.shake_steps", "expected 0 to 1000000, got " + std::to_string(options.shake_steps));
  require_positive(options.max_translation, "options.max_translation");
  require_positive(options.max_rotation, "options.max_rotation");
  GravityTestResult out;
  out.stable = true;
  const auto& g = scene.world().options().gravity;
  const double magnitude = Vec3(g[0], g[1], g[2]).norm();
  for (int d = 0; d < 6; ++d) {
    const auto u = static_cast<std::size_t>(d);
    HandScene<M, S> copy = scene;
    Vec3 local = Vec3::Zero();
    local[d / 2] = d % 2 == 0 ? 1.0 : -1.0;
    copy.world().set_gravity(magnitude * (scene.hand_pose().linear() * local));
    const Eigen::Isometry3d reference = copy.object_in_hand();
    ShakeResult r;
    for (int k = 0; k < options.shake_steps && r.status == Status::success; ++k)
      r.status = copy.step();
    detail::object_motion(reference, copy.object_in_hand(), out.translation[u], out.rotation[u]);
    out.contacts[u] = copy.hand_contacts(options.touch_distance);
    detail::judge(r, out.contacts[u], out.translation[u], out.rotation[u], options);
    out.held[u] = r.stable;
    if (r.status != Status::success && out.status == Status::success) out.status = r.status;
    out.stable = out.stable && r.stable;
  }
  return out;
}

}  // namespace topograsp

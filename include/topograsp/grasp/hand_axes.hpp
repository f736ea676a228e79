// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// HandAxes: which way a hand approaches an object and which way is "up" for it, so that grasp
/// hypotheses and the transfer methods can place any hand.
#pragma once

#include <topograsp/core/eigen.hpp>

namespace topograsp {

/// Two orthogonal unit axes in the frame of a hand's palm centre: the approach (the direction the
/// hand moves toward the object) and up (across the grasp: where the fingers lie for a human hand,
/// from the thumb to the fingers for the SDH), which pair hands with each other.
struct HandAxes {
  Vec3 approach = Vec3::UnitZ();
  Vec3 up = Vec3::UnitX();
};

/// The human hand (frame H): the palm faces +x, the fingers point along +z.
inline const HandAxes human_hand_axes{Vec3::UnitX(), Vec3::UnitZ()};
/// The SDH, the Barrett and other hands with fingers along +z of the palm: the fingers point
/// along the approach, and +x runs from the thumb (at -x) to the fingers.
inline const HandAxes gripper_hand_axes{Vec3::UnitZ(), Vec3::UnitX()};

/// The rotation of a hand's palm frame that points its \p axes along the world directions
/// \p approach and \p up (orthonormalised, approach kept).
[[nodiscard]] inline Mat3 palm_rotation(const HandAxes& axes, const Vec3& approach,
                                        const Vec3& up) {
  const Vec3 a = approach.normalized();
  const Vec3 u = (up - up.dot(a) * a).normalized();
  Mat3 world, local;
  world << a, u, a.cross(u);
  local << axes.approach, axes.up, axes.approach.cross(axes.up);
  return world * local.transpose();
}

}  // namespace topograsp

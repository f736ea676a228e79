// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Box-based grasp hypotheses (BADGr, Huebner 2012): for every face of an object's boxes that a
/// hand can reach, four approaches along the inward face normal, the hand turned in 90-degree
/// steps about the approach axis.
#pragma once

#include <vector>

#include <topograsp/grasp/object.hpp>

namespace topograsp {

/// One grasp hypothesis, in the object frame.
struct GraspHypothesis {
  int box = 0;                    ///< index into GraspObject::boxes
  int face = 0;                   ///< 0..5: the box's +x, -x, +y, -y, +z, -z face
  int turn = 0;                   ///< 0..3: the hand turned by turn * 90 degrees about the approach
  Vec3 centre = Vec3::Zero();     ///< the centre of the face (m)
  Vec3 approach = Vec3::UnitX();  ///< unit: the direction the hand moves, into the face
  Vec3 up = Vec3::UnitZ();        ///< unit, orthogonal to approach: where the fingers point
  double face_half_width = 0.0;   ///< half the face's extent across `up` (m)
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

}  // namespace topograsp

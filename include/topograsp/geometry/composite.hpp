// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Composite: a rigid object made of primitives (a bottle, a hammer), in the world frame.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include <topograsp/geometry/primitive.hpp>

namespace topograsp {

/// A rigid object made of convex primitives, all in the world frame. The parts may overlap; the
/// distance to the object is the smallest distance to a part. Built once (it allocates), read by
/// the collision task without allocating.
class Composite {
 public:
  Composite() = default;
  /// An object made of \p parts (world frame).
  /// \throws topograsp::invalid_argument naming "parts" if a part has a non-finite pose or a
  ///         non-positive size.
  explicit Composite(std::vector<Primitive> parts) : parts_(std::move(parts)) {
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const Primitive& s = parts_[i];
      const bool finite = s.R.allFinite() && s.p.allFinite() && s.size.allFinite();
      const bool sized = s.type == ShapeType::box
                             ? (s.size.array() > 0.0).all()
                             : s.size[0] > 0.0 && (s.type == ShapeType::sphere || s.size[1] >= 0.0);
      if (!finite || !sized)
        detail::throw_invalid_argument("parts",
                                       "part " + std::to_string(i) + " is not a valid primitive");
    }
  }

  /// The parts (world frame).
  [[nodiscard]] std::span<const Primitive> parts() const noexcept { return parts_; }
  [[nodiscard]] std::size_t size() const noexcept { return parts_.size(); }

  /// This object moved rigidly by \p T (applied in the world frame).
  [[nodiscard]] Composite transformed(const Eigen::Isometry3d& T) const {
    Composite c = *this;
    for (Primitive& s : c.parts_) s = s.transformed(T);
    return c;
  }

  /// The volume-weighted centre of the parts (m); the centre of mass of a uniform object whose
  /// parts do not overlap. Zero for an empty object.
  [[nodiscard]] Vec3 centroid() const noexcept {
    Vec3 c = Vec3::Zero();
    double v = 0.0;
    for (const Primitive& s : parts_) {
      c += s.volume() * s.p;
      v += s.volume();
    }
    return v > 0.0 ? Vec3(c / v) : c;
  }

 private:
  std::vector<Primitive> parts_;
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The MJCF attributes and elements both exports write (io/mjcf_world.hpp, io/mjcf.hpp; internal):
/// vectors, shapes, poses and geoms.
#pragma once

#include <cmath>
#include <ostream>
#include <string>
#include <string_view>

#include <Eigen/Geometry>

#include <topograsp/core/eigen.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp::detail {

// Writes ` attribute="x y z"`.
inline void write_mjcf_vec3(std::ostream& os, const char* attribute, const Vec3& v) {
  os << ' ' << attribute << "=\"" << v.x() << ' ' << v.y() << ' ' << v.z() << '"';
}

// Writes the type= and size= attributes of shape s.
inline void write_mjcf_shape(std::ostream& os, const ShapeSpec& s) {
  os << " type=\"" << to_string(s.type) << "\" size=\"";
  switch (s.type) {
    case ShapeType::sphere:
      os << s.size[0];
      break;
    case ShapeType::capsule:
    case ShapeType::cylinder:
      os << s.size[0] << ' ' << s.size[1];
      break;
    case ShapeType::box:
      os << s.size[0] << ' ' << s.size[1] << ' ' << s.size[2];
      break;
  }
  os << '"';
}

// The radius of a sphere about the shape's centre that holds it.
inline double mjcf_shape_radius(const ShapeSpec& s) {
  switch (s.type) {
    case ShapeType::sphere:
      return s.size[0];
    case ShapeType::capsule:
      return s.size[0] + s.size[1];
    case ShapeType::cylinder:
      return std::hypot(s.size[0], s.size[1]);
    case ShapeType::box:
      return std::hypot(s.size[0], s.size[1], s.size[2]);
  }
  return 0.0;
}

// Writes the pos= and quat= attributes of T.
inline void write_mjcf_pose(std::ostream& os, const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  os << " pos=\"" << T.translation().x() << ' ' << T.translation().y() << ' ' << T.translation().z()
     << "\" quat=\"" << q.w() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z() << '"';
}

// One geom: the shape at `T` (in the enclosing body's frame).
inline void write_mjcf_geom(std::ostream& os, std::string_view indent, const std::string& name,
                            const ShapeSpec& s, const Eigen::Isometry3d& T, double mu,
                            double torsion) {
  os << indent << "<geom name=\"" << name << '"';
  write_mjcf_shape(os, s);
  write_mjcf_pose(os, T);
  os << " friction=\"" << mu << ' ' << mu * torsion << " 0.0001\" condim=\""
     << (torsion > 0.0 ? 4 : 3) << "\"/>\n";
}

}  // namespace topograsp::detail

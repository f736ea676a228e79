// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Mass, centre of mass and inertia of shapes and of composite bodies made of shapes.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/pose.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {

/// The mass properties of a rigid body in its own frame.
template <class S = double>
struct MassProperties {
  S mass = S(0);                      ///< kg
  Vec<3, S> com = Vec<3, S>::Zero();  ///< centre of mass (m, body frame)
  /// Inertia tensor about the centre of mass, in body-frame axes (kg m^2).
  Mat<3, 3, S> inertia = Mat<3, 3, S>::Zero();
};

/// Throws topograsp::invalid_argument naming \p argument unless \p s has positive, finite sizes
/// (a capsule's half length may be 0) and a finite pose with an orthonormal rotation.
inline void require_valid_shape(const ShapeSpec& s, std::string_view argument) {
  const std::string arg(argument);
  switch (s.type) {
    case ShapeType::sphere:
      require_positive(s.size[0], arg + ".size[0] (sphere radius)");
      break;
    case ShapeType::capsule:
      require_positive(s.size[0], arg + ".size[0] (capsule radius)");
      require_finite(s.size[1], arg + ".size[1] (capsule half length)");
      if (s.size[1] < 0.0)
        detail::throw_invalid_argument(arg + ".size[1] (capsule half length)",
                                       "expected >= 0, got " + std::to_string(s.size[1]));
      break;
    case ShapeType::box:
      for (std::size_t k = 0; k < 3; ++k)
        require_positive(s.size[k], arg + ".size[" + std::to_string(k) + "] (box half extent)");
      break;
    case ShapeType::cylinder:
      require_positive(s.size[0], arg + ".size[0] (cylinder radius)");
      require_positive(s.size[1], arg + ".size[1] (cylinder half height)");
      break;
  }
  for (double v : s.pose.R) require_finite(v, arg + ".pose");
  for (double v : s.pose.p) require_finite(v, arg + ".pose");
  const Mat3 R = s.pose.rotation();
  if (!is_rotation(R))
    detail::throw_invalid_argument(arg + ".pose", "expected a rotation (orthonormal, det +1)");
}

/// The mass properties of one shape of uniform \p density (kg/m^3), in the frame of its link.
/// Capsule: a cylinder plus two hemispheres (each about its own centroid at 3r/8 from the flat
/// face, moved by the parallel-axis theorem). Cylinder and capsule axes are the shape's local z.
template <class S = double>
[[nodiscard]] MassProperties<S> shape_mass_properties(const ShapeSpec& s, double density) {
  const double r = s.size[0];
  double m = 0.0, ixx = 0.0, iyy = 0.0, izz = 0.0;
  switch (s.type) {
    case ShapeType::sphere:
      m = 4.0 / 3.0 * pi * r * r * r * density;
      ixx = iyy = izz = 0.4 * m * r * r;
      break;
    case ShapeType::box: {
      const double x = s.size[0], y = s.size[1], z = s.size[2];
      m = 8.0 * x * y * z * density;
      // A full side of 2h: m (a^2 + b^2) / 12 = m (h_a^2 + h_b^2) / 3.
      ixx = m * (y * y + z * z) / 3.0;
      iyy = m * (x * x + z * z) / 3.0;
      izz = m * (x * x + y * y) / 3.0;
      break;
    }
    case ShapeType::cylinder: {
      const double h = s.size[1];
      m = pi * r * r * 2.0 * h * density;
      izz = 0.5 * m * r * r;
      ixx = iyy = m * (3.0 * r * r + 4.0 * h * h) / 12.0;
      break;
    }
    case ShapeType::capsule: {
      const double h = s.size[1];
      const double mc = pi * r * r * 2.0 * h * density;
      const double ms = 4.0 / 3.0 * pi * r * r * r * density;
      m = mc + ms;
      izz = 0.5 * mc * r * r + 0.4 * ms * r * r;
      // Hemispheres: (83/320) m r^2 about their centroid, which sits h + 3r/8 from the centre;
      // 83/320 + (3/8)^2 = 2/5, hence 2r^2/5 + h^2 + 3hr/4.
      ixx = iyy =
          mc * (3.0 * r * r + 4.0 * h * h) / 12.0 + ms * (0.4 * r * r + h * h + 0.75 * h * r);
      break;
    }
  }
  MassProperties<S> out;
  out.mass = static_cast<S>(m);
  out.com = detail::translation_of<S>(s.pose);
  const Mat<3, 3, S> R = detail::rotation_of<S>(s.pose);
  const Vec<3, S> diag(static_cast<S>(ixx), static_cast<S>(iyy), static_cast<S>(izz));
  out.inertia = R * diag.asDiagonal() * R.transpose();
  return out;
}

/// The mass properties of a body made of \p shapes (all in the body frame). Give either a
/// \p density (kg/m^3, \p mass <= 0) or a total \p mass (kg, then density only sets the ratio
/// between shapes and any positive value gives the same result; for shapes so large or small
/// that density 1 overflows, the computation is done at a size scaled by a power of two).
/// \p shape_density, if not empty, gives each shape its own density (kg/m^3, one per shape, in
/// place of \p density): with a positive \p mass only their ratios matter (they share the mass
/// out), with \p mass 0 they give it. Overlapping shapes count twice. The result may still be out
/// of the range of S (a density of water on a 1e120 m sphere); the World checks it
/// (World::add_body()). Throws topograsp::invalid_argument for an empty shape list, a bad shape,
/// a \p shape_density whose size is not the number of shapes ("shape_density") or with an entry
/// that is not positive and finite ("shape_density[i]"), or when neither a positive finite mass
/// nor a positive finite density (nor shape densities) is given.
template <class S = double>
[[nodiscard]] MassProperties<S> body_mass_properties(std::span<const ShapeSpec> shapes, double mass,
                                                     double density,
                                                     std::span<const double> shape_density = {}) {
  if (shapes.empty()) detail::throw_invalid_argument("shapes", "expected at least one shape");
  for (std::size_t i = 0; i < shapes.size(); ++i)
    require_valid_shape(shapes[i], "shapes[" + std::to_string(i) + "]");
  const bool per_shape = !shape_density.empty();
  if (per_shape) {
    if (shape_density.size() != shapes.size())
      detail::throw_invalid_argument(
          "shape_density", "expected one density per shape (" + std::to_string(shapes.size()) +
                               "), got " + std::to_string(shape_density.size()));
    for (std::size_t i = 0; i < shape_density.size(); ++i)
      require_positive(shape_density[i], "shape_density[" + std::to_string(i) + "]");
  }
  // With a given mass only the ratio of the densities matters: scale them so that the largest
  // is 1, which keeps the sums below in range as a uniform density of 1 does.
  double rho_scale = 1.0;
  if (mass > 0.0 || !std::isfinite(mass)) {
    require_positive(mass, "mass");
    density = 1.0;
    if (per_shape) rho_scale = 1.0 / *std::max_element(shape_density.begin(), shape_density.end());
  } else if (mass == 0.0) {
    if (per_shape)
      density = 1.0;  // the shape densities are the densities
    else
      require_positive(density, "density");
  } else {
    require_positive(mass, "mass");
  }
  const auto sum = [&](std::span<const ShapeSpec> parts, double rho) {
    const auto rho_of = [&](std::size_t i) {
      return per_shape ? shape_density[i] * rho_scale * rho : rho;
    };
    MassProperties<S> t;
    Vec<3, S> moment = Vec<3, S>::Zero();
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const MassProperties<S> p = shape_mass_properties<S>(parts[i], rho_of(i));
      t.mass += p.mass;
      moment += p.mass * p.com;
    }
    t.com = moment / t.mass;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const ShapeSpec& s = parts[i];
      const MassProperties<S> p = shape_mass_properties<S>(s, rho_of(i));
      const Vec<3, S> d = p.com - t.com;
      // Parallel-axis theorem: I_c + m (|d|^2 1 - d d^T).
      t.inertia +=
          p.inertia + p.mass * (d.squaredNorm() * Mat<3, 3, S>::Identity() - d * d.transpose());
    }
    return t;
  };
  MassProperties<S> total = sum(shapes, density);
  const bool representable = std::isfinite(total.mass) &&
                             total.mass >= std::numeric_limits<S>::min() && total.com.allFinite() &&
                             total.inertia.allFinite();
  if (mass > 0.0 && !representable) {
    // With a given mass only the ratios matter. For shapes so large or small that their volumes
    // leave the range of S, compute at a size scaled by the exact power of two 2^-e (e the
    // exponent of the largest size or offset), then scale back: the centre of mass by 2^e, the
    // inertia per unit mass by 2^(2e).
    double largest = 0.0;
    for (const ShapeSpec& s : shapes) {
      for (const double v : s.size) largest = std::max(largest, std::abs(v));
      for (const double v : s.pose.p) largest = std::max(largest, std::abs(v));
    }
    int e = 0;
    (void)std::frexp(largest, &e);
    std::vector<ShapeSpec> scaled(shapes.begin(), shapes.end());
    for (ShapeSpec& s : scaled) {
      for (double& v : s.size) v = std::ldexp(v, -e);
      for (double& v : s.pose.p) v = std::ldexp(v, -e);
    }
    const MassProperties<S> t = sum(scaled, 1.0);
    total.mass = S(1);
    for (int k = 0; k < 3; ++k) total.com[k] = std::ldexp(t.com[k], e);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) total.inertia(r, c) = std::ldexp(t.inertia(r, c) / t.mass, 2 * e);
  }
  if (mass > 0.0) {
    const S scale = static_cast<S>(mass) / total.mass;
    if (std::isfinite(scale) && scale >= std::numeric_limits<S>::min())
      total.inertia *= scale;
    else  // the ratio leaves the range (a 1e300 kg body of 1 mm): per unit mass first
      total.inertia = Mat<3, 3, S>(total.inertia / total.mass) * static_cast<S>(mass);
    total.mass = static_cast<S>(mass);
  }
  return total;
}

}  // namespace topograsp

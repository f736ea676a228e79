// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Every argument check of World (physics/world.hpp) in one place (internal): what the options,
/// add_body(), add_actuator(), set_body_joints() and the setters accept is what the scalar type S
/// represents with margin; anything else throws topograsp::invalid_argument naming the argument.
/// docs/stepper.md lists the ranges.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include <Eigen/Eigenvalues>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/pose.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/physics/actuator.hpp>
#include <topograsp/physics/rigid_body.hpp>
#include <topograsp/physics/stepper_options.hpp>

namespace topograsp::detail {

/// World<S>::max_length(): sqrt(largest S) / 1024.
template <class S>
[[nodiscard]] S max_length() noexcept {
  return std::sqrt(std::numeric_limits<S>::max()) / S(1024);
}
/// World<S>::min_length(): sqrt(smallest normal S) * 1024.
template <class S>
[[nodiscard]] S min_length() noexcept {
  return std::sqrt(std::numeric_limits<S>::min()) * S(1024);
}

/// \p v as the messages print it (%.6g).
template <class T>
[[nodiscard]] std::string number(T v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", static_cast<double>(v));
  return buf;
}

/// Throws naming \p argument unless 0 <= \p i < \p count ("expected a <what> index in [0, n)").
inline void require_index(int i, std::size_t count, std::string_view what,
                          std::string_view argument) {
  if (i < 0 || static_cast<std::size_t>(i) >= count)
    throw_invalid_argument(argument, "expected a " + std::string(what) + " index in [0, " +
                                         std::to_string(count) + "), got " + std::to_string(i));
}

inline void require_pose(const Pose& pose, std::string_view argument) {
  for (double v : pose.R) require_finite(v, argument);
  for (double v : pose.p) require_finite(v, argument);
  if (!is_rotation(pose.rotation()))
    throw_invalid_argument(argument, "expected a rotation (orthonormal, det +1)");
}

template <class S, class D>
void require_coordinates(const Eigen::MatrixBase<D>& p, std::string_view argument) {
  for (Eigen::Index k = 0; k < p.size(); ++k)
    if (!(std::abs(static_cast<double>(p[k])) <= static_cast<double>(max_length<S>())))
      throw_invalid_argument(argument, "expected coordinates of at most " +
                                           number(max_length<S>()) + " m, got " +
                                           number(static_cast<double>(p[k])));
}
template <class S>
void require_coordinates(const std::array<double, 3>& p, std::string_view argument) {
  require_coordinates<S>(Eigen::Map<const Eigen::Vector3d>(p.data()), argument);
}

/// A finite pose whose coordinates are at most max_length() (World::set_pose() and the others).
template <class S>
void require_world_pose(const Eigen::Isometry3d& pose, std::string_view argument) {
  require_finite(pose.matrix(), argument);
  require_coordinates<S>(pose.translation(), argument);
}

template <class S>
void require_actuator_inertia(double inertia, std::string_view argument) {
  require_positive(inertia, argument);
  if (!(inertia >= static_cast<double>(min_length<S>()) &&
        inertia <= static_cast<double>(max_length<S>())))
    throw_invalid_argument(argument, "expected a value in [" + number(min_length<S>()) + ", " +
                                         number(max_length<S>()) + "], got " + number(inertia));
}

/// |g| time_step^2 must not exceed speculative_distance: the contacts must catch a body released
/// at rest in its first step.
inline void require_step_catches_fall(const Eigen::Vector3d& g, const StepperOptions& options,
                                      std::string_view argument) {
  const double dt = options.time_step;
  const double fall = g.norm() * dt * dt;
  if (!(fall <= options.speculative_distance))
    throw_invalid_argument(
        argument, "a body released at rest falls |g| dt^2 = " + number(fall) +
                      " m in one step, more than options.speculative_distance = " +
                      number(options.speculative_distance) +
                      " m, so contacts would miss it (time_step " + number(dt) + " s, |g| " +
                      number(g.norm()) + " m/s^2): use a shorter time step");
}

/// The checks of World's constructor (see World::World()).
template <class S>
void require_stepper_options(const StepperOptions& options) {
  validate_parameters(options, stepper_parameters, "options.");
  if (!std::isfinite(static_cast<S>(options.time_step)))
    throw_invalid_argument("options.time_step", "expected a step the scalar type can hold, got " +
                                                    number(options.time_step) + " s");
  if (!(static_cast<S>(options.time_step) / static_cast<S>(options.substeps) >= min_length<S>()))
    throw_invalid_argument(
        "options.time_step",
        "a sub-step (time_step / substeps) of " + number(options.time_step / options.substeps) +
            " s is below what the scalar type divides by safely (" + number(min_length<S>()) + ")");
  for (std::size_t k = 0; k < 3; ++k) require_finite(options.gravity[k], "options.gravity");
  if (!(static_cast<S>(options.max_speed) <= max_length<S>()))
    throw_invalid_argument("options.max_speed", "expected at most " + number(max_length<S>()) +
                                                    " m/s (its square must stay finite), got " +
                                                    number(options.max_speed));
  const Eigen::Vector3d g(options.gravity[0], options.gravity[1], options.gravity[2]);
  require_step_catches_fall(g, options, "options.time_step");
}

template <class S>
void require_representable_shape(const ShapeSpec& s, const std::string& argument) {
  const int n = s.type == ShapeType::sphere ? 1 : s.type == ShapeType::box ? 3 : 2;
  for (int k = 0; k < n; ++k) {
    const double v = s.size[static_cast<std::size_t>(k)];
    if (v == 0.0 && s.type == ShapeType::capsule && k == 1) continue;  // a capsule may be a sphere
    if (!(v >= static_cast<double>(min_length<S>()) && v <= static_cast<double>(max_length<S>())))
      throw_invalid_argument(argument + ".size[" + std::to_string(k) + "]",
                             "expected a size in [" + number(min_length<S>()) + ", " +
                                 number(max_length<S>()) + "] m, got " + number(v));
  }
  require_coordinates<S>(s.pose.p, argument + ".pose");
}

/// A given inertial must be one a rigid body can have (as MuJoCo's mj_setConst checks).
inline void require_physical_inertial(const MassProperties<double>& m, const std::string& arg) {
  require_positive(m.mass, arg + ".mass");
  if (!m.com.allFinite()) throw_invalid_argument(arg + ".com", "expected finite numbers");
  const Mat3& I = m.inertia;
  if (!I.allFinite() || !I.isApprox(I.transpose(), 1e-9))
    throw_invalid_argument(arg + ".inertia", "expected a finite symmetric matrix");
  const Vec3 e = Eigen::SelfAdjointEigenSolver<Mat3>(I).eigenvalues();
  if (!(e[0] > 0.0) || e[0] + e[1] < e[2] * (1.0 - 1e-9))
    throw_invalid_argument(
        arg + ".inertia", "expected positive principal moments with A + B >= C, got " +
                              number(e[0]) + ", " + number(e[1]) + ", " + number(e[2]) + " kg m^2");
}

/// The checks of World::add_body() made before the body is built: its shapes, pose, friction and
/// densities, and a given inertial.
template <class S>
void require_body_desc(const BodyDesc& desc) {
  if (desc.shapes.empty()) throw_invalid_argument("desc.shapes", "expected at least one shape");
  for (std::size_t i = 0; i < desc.shapes.size(); ++i) {
    const std::string name = "desc.shapes[" + std::to_string(i) + "]";
    require_valid_shape(desc.shapes[i], name);
    require_representable_shape<S>(desc.shapes[i], name);
  }
  require_pose(desc.pose, "desc.pose");
  require_coordinates<S>(desc.pose.p, "desc.pose");
  require_non_negative(desc.friction, "desc.friction");
  if (desc.friction > 1e6)
    throw_invalid_argument("desc.friction", "expected at most 1e6, got " + number(desc.friction));
  if (!desc.shape_density.empty()) {
    if (desc.shape_density.size() != desc.shapes.size())
      throw_invalid_argument("desc.shape_density", "expected one density per shape (" +
                                                       std::to_string(desc.shapes.size()) +
                                                       "), got " +
                                                       std::to_string(desc.shape_density.size()));
    for (std::size_t i = 0; i < desc.shape_density.size(); ++i)
      require_positive(desc.shape_density[i], "desc.shape_density[" + std::to_string(i) + "]");
  }
  if (desc.type == BodyType::dynamic && desc.inertial)
    require_physical_inertial(*desc.inertial, "desc.inertial");
}

/// A dynamic body's mass and inertia as S holds them: normal positive numbers with finite
/// inverses whose kinetic energy at options.max_speed stays finite.
template <class S>
void require_representable_mass(const RigidBody<S>& b, const StepperOptions& options,
                                std::string_view argument) {
  const S smin = std::numeric_limits<S>::min(), smax = std::numeric_limits<S>::max();
  const S v2 = static_cast<S>(options.max_speed) * static_cast<S>(options.max_speed);
  const bool mass_ok = std::isfinite(b.mass) && b.mass >= smin && std::isfinite(b.inv_mass) &&
                       b.mass <= smax / v2 && b.local_com.allFinite();
  if (!mass_ok)
    throw_invalid_argument(argument,
                           "the body's mass " + number(static_cast<double>(b.mass)) +
                               " kg is not representable: expected a normal positive number whose "
                               "kinetic energy at options.max_speed stays finite, within [" +
                               number(static_cast<double>(smin)) + ", " +
                               number(static_cast<double>(smax / v2)) + "] kg");
  bool inertia_ok =
      b.inertia.allFinite() && b.inv_inertia_local.allFinite() && b.inv_inertia.allFinite();
  for (int k = 0; k < 3 && inertia_ok; ++k)
    inertia_ok =
        b.inertia(k, k) >= smin && b.inertia(k, k) <= smax / v2 && b.inv_inertia_local(k, k) > S(0);
  if (!inertia_ok)
    throw_invalid_argument(
        argument, "the body's inertia (diagonal " + number(static_cast<double>(b.inertia(0, 0))) +
                      ", " + number(static_cast<double>(b.inertia(1, 1))) + ", " +
                      number(static_cast<double>(b.inertia(2, 2))) +
                      " kg m^2) is not representable: expected normal positive numbers with a "
                      "finite inverse whose kinetic energy at options.max_speed stays finite, "
                      "within [" +
                      number(static_cast<double>(smin)) + ", " +
                      number(static_cast<double>(smax / v2)) + "] kg m^2");
}

/// The checks of World::add_actuator().
template <class S>
void require_actuator_desc(const ActuatorDesc& desc, const StepperOptions& options) {
  require_finite(desc.position, "desc.position");
  require_finite(desc.lower, "desc.lower");
  require_finite(desc.upper, "desc.upper");
  if (desc.lower > desc.upper)
    throw_invalid_argument("desc.lower", "expected at most desc.upper = " + number(desc.upper) +
                                             ", got " + number(desc.lower));
  if (!(std::abs(desc.lower) <= static_cast<double>(max_length<S>()) &&
        std::abs(desc.upper) <= static_cast<double>(max_length<S>())))
    throw_invalid_argument("desc.lower", "expected limits of at most " + number(max_length<S>()));
  if (desc.position < desc.lower || desc.position > desc.upper)
    throw_invalid_argument("desc.position", "expected a value in [" + number(desc.lower) + ", " +
                                                number(desc.upper) + "], got " +
                                                number(desc.position));
  require_actuator_inertia<S>(desc.inertia, "desc.inertia");
  require_positive(desc.max_effort, "desc.max_effort");
  require_positive(desc.max_velocity, "desc.max_velocity");
  if (!(desc.max_velocity <= options.max_speed))
    throw_invalid_argument("desc.max_velocity",
                           "expected at most options.max_speed = " + number(options.max_speed) +
                               ", got " + number(desc.max_velocity));
  require_positive(desc.stiffness, "desc.stiffness");
  require_non_negative(desc.damping_time, "desc.damping_time");
}

/// The checks of World::set_body_joints() on the joints themselves (allocates only to name one).
template <class S>
void require_body_joints(std::span<const BodyJoint> joints, std::size_t actuators) {
  if (joints.size() > static_cast<std::size_t>(k_max_body_joints))
    throw_invalid_argument("joints", "expected at most " + std::to_string(k_max_body_joints) +
                                         " joints, got " + std::to_string(joints.size()));
  for (std::size_t j = 0; j < joints.size(); ++j) {
    // Checked without building a name first: this runs every step and allocates nothing.
    const BodyJoint& in = joints[j];
    const auto name = [j](std::string_view field) {
      return "joints[" + std::to_string(j) + "]." + std::string(field);
    };
    if (in.actuator < 0 || static_cast<std::size_t>(in.actuator) >= actuators)
      require_index(in.actuator, actuators, "actuator", name("actuator"));
    if (!in.axis.allFinite() || !(std::abs(in.axis.norm() - 1.0) <= 1e-6))
      throw_invalid_argument(name("axis"), "expected a finite unit vector");
    if (!in.origin.allFinite() ||
        !(in.origin.cwiseAbs().maxCoeff() <= static_cast<double>(max_length<S>())))
      throw_invalid_argument(name("origin"), "expected finite coordinates of at most " +
                                                 number(max_length<S>()) + " m");
    if (!std::isfinite(in.gear)) throw_invalid_argument(name("gear"), "expected a finite number");
  }
}

/// The checks of World::set_velocity().
inline void require_velocity(const Eigen::Vector3d& v, const Eigen::Vector3d& w,
                             const StepperOptions& options) {
  require_finite(v, "v");
  require_finite(w, "w");
  if (!(v.norm() <= options.max_speed))
    throw_invalid_argument("v", "expected a speed of at most options.max_speed = " +
                                    number(options.max_speed) + " m/s, got " + number(v.norm()));
  if (!(w.norm() <= options.max_speed))
    throw_invalid_argument("w", "expected a speed of at most options.max_speed = " +
                                    number(options.max_speed) + " rad/s, got " + number(w.norm()));
}

}  // namespace topograsp::detail

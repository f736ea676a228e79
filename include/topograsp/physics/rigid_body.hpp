// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// RigidBody: one body of a World (dynamic, kinematic or static), its constants apart from its
/// state, and BodyDesc, what a body is built from.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include <topograsp/core/pose.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/model/spec.hpp>
#include <topograsp/physics/detail/math.hpp>

namespace topograsp {

/// How a body moves.
enum class BodyType : std::uint8_t {
  fixed,      ///< never moves (the ground); infinite mass
  kinematic,  ///< moved to target poses (hand links); infinite mass, pushes dynamic bodies
  dynamic,    ///< moved by gravity and contacts (the object)
};

/// What World::add_body() builds a body from.
struct BodyDesc {
  BodyType type = BodyType::dynamic;
  /// The body frame in the world; the shapes' poses are in this frame.
  Pose pose{};
  /// The shapes (ShapeSpec::link is ignored); at least one. Copied by add_body().
  std::span<const ShapeSpec> shapes{};
  /// Total mass (kg) of a dynamic body; if 0, the mass comes from density.
  double mass = 0.0;
  /// Density (kg/m^3) of a dynamic body when mass is 0. Default: water.
  double density = 1000.0;
  /// Per-shape densities (kg/m^3), one per shape, for a body of several materials (a hammer's
  /// steel head and wooden handle); empty = every shape has `density`. With a given mass they
  /// set how the mass is shared between the shapes; with mass 0 they give it. Copied by add_body().
  std::span<const double> shape_density{};
  /// The mass, centre of mass (body frame) and inertia about it of a dynamic body whose shapes
  /// only approximate it (a mesh object's boxes: the mesh gives its mass properties); when set,
  /// mass, density and shape_density are not used. Must be physical: a positive mass, a finite
  /// centre of mass, a symmetric positive-definite inertia whose principal moments satisfy the
  /// triangle inequality (A + B >= C).
  std::optional<MassProperties<double>> inertial{};
  /// Coulomb friction coefficient; a pair of bodies uses sqrt(mu_a mu_b). Default 0.5.
  double friction = 0.5;
};

/// What a body of a World is made of and never changes as it moves: its type, mass properties
/// (body frame), friction and shapes.
template <class S = double>
struct BodyConstants {
  BodyType type = BodyType::dynamic;
  Vec<3, S> local_com = Vec<3, S>::Zero();      ///< centre of mass in the body frame
  S mass = S(0), inv_mass = S(0);               ///< kg, 1/kg (0 if not dynamic)
  Mat<3, 3, S> inertia = Mat<3, 3, S>::Zero();  ///< about the centre of mass, body axes (kg m^2)
  Mat<3, 3, S> inv_inertia_local = Mat<3, 3, S>::Zero();  ///< its inverse
  S friction = S(0.5);
  int first_collider = 0, n_colliders = 0;  ///< its shapes, World::collider()
};

/// Where a body of a World is and how it moves: position, orientation, velocities, and the inverse
/// inertia in world axes that its orientation gives.
template <class S = double>
struct BodyState {
  Vec<3, S> x = Vec<3, S>::Zero();                  ///< centre of mass, world (m)
  detail::Quat<S> q = detail::Quat<S>::Identity();  ///< orientation
  Mat<3, 3, S> R = Mat<3, 3, S>::Identity();        ///< rotation matrix of q
  Vec<3, S> v = Vec<3, S>::Zero();                  ///< linear velocity of x (m/s)
  Vec<3, S> w = Vec<3, S>::Zero();                  ///< angular velocity, world (rad/s)
  Mat<3, 3, S> inv_inertia = Mat<3, 3, S>::Zero();  ///< inverse inertia in world axes
  /// A dynamic body held still (World::set_held()): at rest, its inverse mass and inertia 0.
  bool held = false;
};

/// One body of a World: its constants and its state. The position x is the centre of mass; the
/// body frame (whose origin the shapes and BodyDesc::pose refer to) is at x - R local_com.
template <class S = double>
struct RigidBody : BodyConstants<S>, BodyState<S> {
  using V3 = Vec<3, S>;
  using M3 = Mat<3, 3, S>;

  /// inv_inertia from the orientation R (a dynamic body's; others have none): R I^-1 R'.
  void update_world_inertia() noexcept {
    if (this->type == BodyType::dynamic)
      this->inv_inertia = this->R * this->inv_inertia_local * this->R.transpose();
  }
  /// The origin of the body frame in the world (m).
  [[nodiscard]] V3 origin() const noexcept { return this->x - this->R * this->local_com; }
  /// The body frame as an isometry (double precision).
  [[nodiscard]] Eigen::Isometry3d pose() const noexcept {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = this->R.template cast<double>();
    T.translation() = origin().template cast<double>();
    return T;
  }
  /// Kinetic energy (J).
  [[nodiscard]] S kinetic_energy() const noexcept {
    if (this->type != BodyType::dynamic) return S(0);
    const M3& rot = this->R;
    return S(0.5) * this->mass * this->v.squaredNorm() +
           S(0.5) * this->w.dot(rot * this->inertia * rot.transpose() * this->w);
  }
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// HandScene: a World holding a hand model's links as kinematic bodies, driven to the forward
/// kinematics of joint targets, and an object made of shapes as a dynamic body.
#pragma once

#include <algorithm>
#include <array>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/evaluation/grasp_wrench.hpp>
#include <topograsp/kinematics/data.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/physics/world.hpp>

namespace topograsp {

/// An object to grasp: shapes in the object frame, its pose, and its mass or density.
struct ObjectSpec {
  std::vector<ShapeSpec> shapes;  ///< in the object frame; ShapeSpec::link is ignored
  Pose pose{};                    ///< the object frame in the world
  double mass = 0.0;              ///< kg; if 0 the mass comes from density
  double density = 0.0;           ///< kg/m^3, used when mass is 0
  /// Density of each shape (kg/m^3), one per shape, for an object of several materials; empty =
  /// uniform (density, or mass spread evenly). With a mass they share it out; without, they give
  /// it.
  std::vector<double> part_density{};
  /// Coulomb friction coefficient of each shape against every hand link, one per shape; empty =
  /// HandSceneOptions::friction for every pair.
  std::vector<double> part_friction{};
};

/// The parameters of a HandScene beyond the stepper's.
struct HandSceneOptions {
  StepperOptions stepper{};  ///< time step, contact stiffness, ... (StepperOptions defaults)
  /// Coulomb friction coefficient between the hand and the object. Default 1 (rubber-covered
  /// fingers on plastic or wood are about 0.8 to 1.2).
  double friction = 1.0;
};

/// A hand of model \p M (a reference to a constexpr Model) holding an object, over scalar \p S.
///
/// Every link with shapes becomes a kinematic body; the hand frame (the model's root link) is
/// placed at hand_pose(). Each step() first moves every link to the forward kinematics of the
/// joint targets at the current hand pose, then advances the World. Requires nothing else.
template <const auto& M, class S = double>
  requires KinematicModel<decltype(M)>
class HandScene {
 public:
  using ModelType = std::remove_cvref_t<decltype(M)>;
  static constexpr int nq = M.nq;
  using Config = Vec<nq>;

  /// Builds the scene: the hand frame at \p hand_pose with joints at \p q (also the targets), and
  /// the object. Throws topograsp::invalid_argument naming the argument for a non-finite or
  /// wrongly sized q, a bad pose (as set_hand_pose()), an object the World refuses (its ranges;
  /// named as the object's field, e.g. "object.mass", "object.shapes[0].size[0]"), an
  /// object without shapes, a bad shape, a non-positive mass (or density when the mass is 0 and
  /// no part densities are given), a part_density or part_friction whose size is not the number
  /// of shapes ("object.part_density", "object.part_friction") or with an entry that is not
  /// positive and finite (part_density) or not in [0, 1e6] (part_friction), named with its index,
  /// or bad options. part_friction is set on every pair of a hand link's shape and that part.
  HandScene(const Eigen::Isometry3d& hand_pose, const Config& q, const ObjectSpec& object,
            const HandSceneOptions& options = {})
      : world_(options.stepper), options_(options) {
    require_configuration<M>(q, "q");
    require_hand_pose(hand_pose, "hand_pose");
    require_positive(options.friction, "options.friction");
    if (object.shapes.empty())
      detail::throw_invalid_argument("object.shapes", "expected at least one shape");
    const std::size_t n_parts = object.shapes.size();
    const auto require_per_part = [n_parts](const std::vector<double>& v, const char* field) {
      if (!v.empty() && v.size() != n_parts)
        detail::throw_invalid_argument(std::string("object.") + field,
                                       "expected one value per shape (" + std::to_string(n_parts) +
                                           "), got " + std::to_string(v.size()));
    };
    require_per_part(object.part_density, "part_density");
    require_per_part(object.part_friction, "part_friction");
    for (std::size_t i = 0; i < object.part_density.size(); ++i)
      require_positive(object.part_density[i], "object.part_density[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < object.part_friction.size(); ++i) {
      const std::string name = "object.part_friction[" + std::to_string(i) + "]";
      require_non_negative(object.part_friction[i], name);
      if (object.part_friction[i] > 1e6)
        detail::throw_invalid_argument(
            name, "expected at most 1e6, got " + std::to_string(object.part_friction[i]));
    }
    if (!(object.mass > 0.0)) {
      if (object.mass != 0.0) require_positive(object.mass, "object.mass");
      if (object.part_density.empty())
        require_positive(object.density, "object.density (the mass is 0)");
    }
    hand_pose_ = hand_pose;
    q_ = q;
    forward_kinematics(kin_, q_);
    link_body_.fill(-1);
    std::vector<ShapeSpec> link_shapes;
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      link_shapes.clear();
      for (const Shape& s : M.shapes)
        if (s.link == static_cast<int>(l)) link_shapes.push_back(s.spec);
      if (link_shapes.empty()) continue;
      BodyDesc d;
      d.type = BodyType::kinematic;
      d.pose = to_pose(link_pose(static_cast<int>(l)));
      d.shapes = link_shapes;
      d.friction = options.friction;
      link_body_[l] = world_.add_body(d);
    }
    BodyDesc o;
    o.type = BodyType::dynamic;
    o.pose = object.pose;
    o.shapes = object.shapes;
    o.mass = object.mass;
    o.density = object.density;
    o.shape_density = object.part_density;
    o.friction = options.friction;
    try {
      object_ = world_.add_body(o);
    } catch (const invalid_argument& e) {
      // Name this constructor's argument ("object.mass"), not the World's ("desc.mass").
      const std::string_view m = e.what();
      const std::size_t colon = m.find(": ");
      if (m.rfind("desc.", 0) != 0 || colon == std::string_view::npos) throw;
      detail::throw_invalid_argument("object." + std::string(m.substr(5, colon - 5)),
                                     m.substr(colon + 2));
    }
    // Friction per pair of materials: each part against every shape of every hand link.
    if (!object.part_friction.empty()) {
      const RigidBody<S>& ob = world_.body(object_);
      for (const int b : link_body_) {
        if (b < 0) continue;
        const RigidBody<S>& lb = world_.body(b);
        for (int c = lb.first_collider; c < lb.first_collider + lb.n_colliders; ++c)
          for (int k = 0; k < ob.n_colliders; ++k)
            world_.set_pair_friction(c, ob.first_collider + k,
                                     object.part_friction[static_cast<std::size_t>(k)]);
      }
    }
  }

  /// Sets the joint targets (dim nq, rad or m) that the next step() drives the links to.
  /// Throws topograsp::invalid_argument for non-finite entries.
  void set_joint_targets(const Config& q) {
    require_configuration<M>(q, "q");
    q_ = q;
  }
  /// The largest coordinate (m) of a hand pose: 1e6 m. Far beyond any workspace, and small
  /// enough that every link pose (the hand pose times a link's offset) stays within the World's
  /// max_length() for both double and float.
  static constexpr double k_max_hand_coordinate = 1e6;

  /// Sets the hand frame pose that the next step() drives the hand to. Throws
  /// topograsp::invalid_argument naming "pose" for a non-finite pose, a linear part that is not a
  /// rotation, or a coordinate above k_max_hand_coordinate.
  void set_hand_pose(const Eigen::Isometry3d& pose) {
    require_hand_pose(pose, "pose");
    hand_pose_ = pose;
  }
  /// Puts the hand at \p pose with joints \p q at once (no motion, no contact impulses), and makes
  /// them the targets.
  void place_hand(const Eigen::Isometry3d& pose, const Config& q) {
    set_hand_pose(pose);
    set_joint_targets(q);
    forward_kinematics(kin_, q_);
    for (std::size_t l = 0; l < ModelType::n_links; ++l)
      if (link_body_[l] >= 0) world_.set_pose(link_body_[l], link_pose(static_cast<int>(l)));
  }

  /// Drives the links to the targets and advances the world by one step; allocates nothing.
  /// Returns the World's status (Status::numerical_issue ends the run). If a link pose at the
  /// targets is not one the World accepts (World::target_in_range(): non-finite, or beyond
  /// World::max_length(), e.g. a prismatic joint target of 1e300 m), nothing moves and the step
  /// returns Status::invalid_input; the scene stays usable with other targets.
  Status step() noexcept {
    forward_kinematics(kin_, q_);
    std::array<Eigen::Isometry3d, ModelType::n_links> poses;
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      poses[l] = link_pose(static_cast<int>(l));
      if (link_body_[l] >= 0 && !World<S>::target_in_range(poses[l])) return Status::invalid_input;
    }
    for (std::size_t l = 0; l < ModelType::n_links; ++l)
      if (link_body_[l] >= 0) world_.set_target(link_body_[l], poses[l]);
    return world_.step();
  }

  /// The world pose of link \p l at the current targets and hand pose (after forward kinematics).
  [[nodiscard]] Eigen::Isometry3d link_pose(int l) const noexcept {
    return hand_pose_ * topograsp::link_pose(kin_, l);
  }

  /// The number of hand-object contact points with a separation of at most \p max_separation (m).
  [[nodiscard]] int hand_contacts(double max_separation = 0.0) const noexcept {
    int n = 0;
    for (const Manifold<S>& m : world_.manifolds())
      if (m.body_b == object_ || m.body_a == object_)
        for (int k = 0; k < m.count; ++k)
          if (static_cast<double>(m.points[static_cast<std::size_t>(k)].separation) <=
              max_separation)
            ++n;
    return n;
  }
  /// The total normal force (N) of the hand on the object over the last step.
  [[nodiscard]] double hand_force() const noexcept {
    double sum = 0.0;
    for (const Manifold<S>& m : world_.manifolds())
      if (m.body_b == object_ || m.body_a == object_)
        for (int k = 0; k < m.count; ++k)
          sum += static_cast<double>(m.points[static_cast<std::size_t>(k)].step_impulse);
    return sum / world_.options().time_step;
  }

  /// The deepest hand-object overlap at the last step (m, >= 0; 0 when nothing overlaps).
  [[nodiscard]] double deepest_penetration() const noexcept {
    double deepest = 0.0;
    for (const Manifold<S>& m : world_.manifolds())
      if (m.body_b == object_ || m.body_a == object_)
        for (int k = 0; k < m.count; ++k)
          deepest = std::max(
              deepest, -static_cast<double>(m.points[static_cast<std::size_t>(k)].separation));
    return deepest;
  }
  /// Gravity in the world frame (m/s^2).
  [[nodiscard]] Vec3 gravity() const noexcept { return world_.gravity().template cast<double>(); }
  /// Sets gravity in the world frame (m/s^2); throws as World::set_gravity().
  void set_gravity(const Vec3& g) { world_.set_gravity(g); }
  /// The object's mass (kg).
  [[nodiscard]] double object_mass() const noexcept {
    return static_cast<double>(world_.body(object_).mass);
  }
  /// The object's centre of mass in the world (m).
  [[nodiscard]] Vec3 object_com() const noexcept {
    return world_.body(object_).x.template cast<double>();
  }
  /// The palm centre in the world (m): the model's palm point, or the hand frame's origin for a
  /// model without a hand.
  [[nodiscard]] Vec3 palm_centre() const noexcept {
    if constexpr (M.is_hand())
      return hand_pose_ * world_point(kin_, M.palm);
    else
      return hand_pose_.translation();
  }
  /// The time step (s).
  [[nodiscard]] double time_step() const noexcept { return world_.options().time_step; }

  /// The object frame in the world.
  [[nodiscard]] Eigen::Isometry3d object_pose() const noexcept {
    return world_.body(object_).pose();
  }
  /// The object frame in the hand frame.
  [[nodiscard]] Eigen::Isometry3d object_in_hand() const noexcept {
    return hand_pose_.inverse() * object_pose();
  }
  [[nodiscard]] const Eigen::Isometry3d& hand_pose() const noexcept { return hand_pose_; }
  [[nodiscard]] const Config& joint_targets() const noexcept { return q_; }
  [[nodiscard]] const World<S>& world() const noexcept { return world_; }
  [[nodiscard]] World<S>& world() noexcept { return world_; }
  [[nodiscard]] int object_body() const noexcept { return object_; }
  /// The World body of link \p l, or -1 if the link has no shapes.
  [[nodiscard]] int link_body(int l) const noexcept {
    return link_body_[static_cast<std::size_t>(l)];
  }
  [[nodiscard]] const HandSceneOptions& options() const noexcept { return options_; }
  /// Forward kinematics at the current targets (hand frame).
  [[nodiscard]] const KinematicsData<M>& kinematics() const noexcept { return kin_; }

  /// What is wrong with \p pose as a hand pose ("" if nothing): not finite, not a rotation
  /// (orthonormal, det +1, to 1e-6), or a coordinate above k_max_hand_coordinate. The one check
  /// behind the constructor and set_hand_pose, for callers that report instead of throwing.
  [[nodiscard]] static std::string hand_pose_problem(const Eigen::Isometry3d& pose) {
    if (!pose.matrix().allFinite()) return "expected a finite number";
    const Mat3 R = pose.linear();
    if (!(R.transpose() * R).isApprox(Mat3::Identity(), 1e-6) || R.determinant() < 0.0)
      return "expected a rotation (orthonormal, det +1)";
    const double m = pose.translation().cwiseAbs().maxCoeff();
    if (!(m <= k_max_hand_coordinate)) {
      char buf[96];
      static_assert(k_max_hand_coordinate == 1e6, "the message below says 1e6");
      std::snprintf(buf, sizeof buf, "expected coordinates of at most 1e6 m, got %.6g m", m);
      return buf;
    }
    return {};
  }

  /// The hand-object contact points of the last step with a separation of at most
  /// \p max_separation (m), as the Ferrari-Canny epsilon takes them (ferrari_canny_epsilon() in
  /// evaluation/grasp_quality.hpp): the world point, the unit normal pointing into the object and
  /// the pair's friction coefficient. Empty before the first step. Allocates the returned vector.
  [[nodiscard]] std::vector<ContactForQuality> hand_contact_points(
      double max_separation = 0.0) const {
    std::vector<ContactForQuality> out;
    for (const Manifold<S>& m : world_.manifolds()) {
      if (m.body_a != object_ && m.body_b != object_) continue;
      // A manifold's normal points from body A into body B.
      const double into_object = m.body_b == object_ ? 1.0 : -1.0;
      for (int k = 0; k < m.count; ++k) {
        const ContactPoint<S>& p = m.points[static_cast<std::size_t>(k)];
        if (!(static_cast<double>(p.separation) <= max_separation)) continue;
        out.push_back({p.point.template cast<double>(),
                       into_object * p.normal.template cast<double>(),
                       static_cast<double>(m.friction)});
      }
    }
    return out;
  }

 private:
  static void require_hand_pose(const Eigen::Isometry3d& pose, std::string_view argument) {
    const std::string problem = hand_pose_problem(pose);
    if (!problem.empty()) detail::throw_invalid_argument(argument, problem);
  }

  World<S> world_;
  HandSceneOptions options_;
  KinematicsData<M> kin_;
  Eigen::Isometry3d hand_pose_ = Eigen::Isometry3d::Identity();
  Config q_ = Config::Zero();
  std::array<int, ModelType::n_links> link_body_{};
  int object_ = -1;
};

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// MujocoScene: a grasp simulated in MuJoCo 2.2, a GraspScene like HandScene, so that the same
/// stability tests judge a grasp in both engines. Only for programs linked with MuJoCo (CMake
/// target topograsp_mujoco, which defines TOPOGRASP_HAVE_MUJOCO); the rest of the library does
/// not include it and stays Eigen-only.
#pragma once

#if !__has_include(<mujoco/mujoco.h>)
#error \
    "topograsp/mujoco/mujoco_scene.hpp needs MuJoCo 2.2 (<mujoco/mujoco.h>): link topograsp_mujoco"
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <mujoco/mujoco.h>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/status.hpp>
#include <topograsp/evaluation/grasp_scene.hpp>
#include <topograsp/evaluation/hand_scene.hpp>
#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/io/mjcf.hpp>

namespace topograsp {

namespace detail {

struct MujocoModelDeleter {
  void operator()(mjModel* m) const noexcept { mj_deleteModel(m); }
};
struct MujocoDataDeleter {
  void operator()(mjData* d) const noexcept { mj_deleteData(d); }
};
struct MujocoVfsDeleter {
  void operator()(mjVFS* v) const noexcept {
    mj_deleteVFS(v);
    delete v;
  }
};

// Loads MJCF text through a virtual file system (nothing is written to disk). Throws
// topograsp::invalid_argument naming "mjcf" with MuJoCo's error text if it does not load.
inline std::shared_ptr<const mjModel> load_mjcf(std::string_view mjcf) {
  if (mjcf.size() > static_cast<std::size_t>(1) << 30)
    throw_invalid_argument("mjcf", "expected at most 1 GiB of text");
  // mjVFS holds its file table inline (about 2 MB): on the heap, not the stack.
  std::unique_ptr<mjVFS, MujocoVfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const char* name = "topograsp_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(mjcf.size())) != 0)
    throw_invalid_argument("mjcf", "MuJoCo's virtual file system refused the text");
  const int file = mj_findFileVFS(vfs.get(), name);
  if (file < 0) throw_invalid_argument("mjcf", "MuJoCo's virtual file system lost the text");
  std::memcpy(vfs->filedata[file], mjcf.data(), mjcf.size());
  char error[1024] = "";
  mjModel* m = mj_loadXML(name, vfs.get(), error, sizeof error);
  if (m == nullptr)
    throw_invalid_argument("mjcf", std::string("MuJoCo did not load it: ") +
                                       (error[0] != '\0' ? error : "(no message)"));
  return std::shared_ptr<const mjModel>(m, MujocoModelDeleter{});
}

inline Eigen::Isometry3d mujoco_pose(const mjtNum* pos, const mjtNum* quat) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() =
      Eigen::Quaterniond(quat[0], quat[1], quat[2], quat[3]).normalized().toRotationMatrix();
  T.translation() = Vec3(pos[0], pos[1], pos[2]);
  return T;
}

}  // namespace detail

/// A grasp simulated in MuJoCo 2.2 from an MJCF scene that keeps the contract of the articulated
/// export (write_mjcf(os, HandScene, MjcfOptions), docs/evaluation.md): a mocap body named `hand`
/// (the hand frame), which either carries the hand itself or is the target of a body named
/// `hand_base` that carries it (welded to `hand`, as the export writes it), a body named `object`
/// with a free joint, and optionally a keyframe named `grasp` (the start state) and a site named
/// `palm` (the palm centre).
///
/// One step() is one step of the built-in scene: `substeps` MuJoCo steps, while the mocap body
/// moves from its pose to the one set by set_hand_pose() (positions interpolated linearly,
/// rotations by slerp). The model is loaded once and shared, read-only, by copies; each copy has
/// its own mjData (mj_copyData), so copies are independent and may run on different threads.
/// Gravity is per scene: the model keeps the gravity it was written with and a different one is
/// applied as the force m (g - g_model) at every body's centre of mass (mjData::xfrc_applied),
/// which is the same dynamics.
class MujocoScene {
 public:
  /// Loads \p mjcf (MJCF text, read from memory) and starts from its `grasp` keyframe if it has
  /// one (else from the model's reference pose); one step() is \p substeps MuJoCo steps. Throws
  /// topograsp::invalid_argument naming "mjcf" with MuJoCo's error text for a model that does not
  /// load, or saying what is missing (no mocap body `hand`, no body `object` with a free joint
  /// as its only joint); naming "substeps" unless 1 <= substeps <= 1000000.
  explicit MujocoScene(std::string_view mjcf, int substeps = 1) {
    if (substeps < 1 || substeps > 1000000)
      detail::throw_invalid_argument("substeps",
                                     "expected 1 to 1000000, got " + std::to_string(substeps));
    model_ = detail::load_mjcf(mjcf);
    substeps_ = substeps;
    const mjModel* m = model_.get();
    hand_ = mj_name2id(m, mjOBJ_BODY, "hand");
    if (hand_ < 0 || m->body_mocapid[hand_] < 0)
      detail::throw_invalid_argument("mjcf", "expected a mocap body named \"hand\"");
    mocap_ = m->body_mocapid[hand_];
    base_ = mj_name2id(m, mjOBJ_BODY, "hand_base");
    if (base_ < 0) base_ = hand_;
    object_ = mj_name2id(m, mjOBJ_BODY, "object");
    if (object_ < 0 || m->body_jntnum[object_] != 1 ||
        m->jnt_type[m->body_jntadr[object_]] != mjJNT_FREE)
      detail::throw_invalid_argument("mjcf",
                                     "expected a body named \"object\" with one free joint");
    palm_ = mj_name2id(m, mjOBJ_SITE, "palm");
    data_.reset(mj_makeData(m));
    if (!data_) detail::throw_invalid_argument("mjcf", "MuJoCo could not allocate its data");
    const int key = mj_name2id(m, mjOBJ_KEY, "grasp");
    if (key >= 0) mj_resetDataKeyframe(m, data_.get(), key);
    mj_forward(m, data_.get());
    hand_pose_ = detail::mujoco_pose(data_->mocap_pos + 3 * mocap_, data_->mocap_quat + 4 * mocap_);
    gravity_ = Vec3(m->opt.gravity[0], m->opt.gravity[1], m->opt.gravity[2]);
  }

  /// The scene \p scene in MuJoCo: its articulated MJCF (write_mjcf with \p options), loaded from
  /// memory and started from the `grasp` keyframe, stepped in mjcf_substeps(scene.time_step(),
  /// options.max_time_step) MuJoCo steps per step. Throws topograsp::invalid_argument as
  /// write_mjcf for bad options, and naming "scene" for an actuated joint without an effort
  /// limit (LinkSpec::effort 0 and no options.effort): a judge needs the motors' real limits.
  template <const auto& M, class S>
  explicit MujocoScene(const HandScene<M, S>& scene, const MjcfOptions& options = {})
      : MujocoScene(checked_mjcf(scene, options),
                    mjcf_substeps(scene.time_step(), options.max_time_step)) {}

  MujocoScene(const MujocoScene& o)
      : model_(o.model_),
        data_(mj_makeData(o.model_.get())),
        substeps_(o.substeps_),
        hand_(o.hand_),
        mocap_(o.mocap_),
        base_(o.base_),
        object_(o.object_),
        palm_(o.palm_),
        hand_pose_(o.hand_pose_),
        gravity_(o.gravity_) {
    mj_copyData(data_.get(), model_.get(), o.data_.get());
  }
  MujocoScene& operator=(const MujocoScene& o) {
    if (this == &o) return *this;
    if (model_ != o.model_) {
      data_.reset(mj_makeData(o.model_.get()));
      model_ = o.model_;
    }
    mj_copyData(data_.get(), model_.get(), o.data_.get());
    substeps_ = o.substeps_;
    hand_ = o.hand_;
    mocap_ = o.mocap_;
    base_ = o.base_;
    object_ = o.object_;
    palm_ = o.palm_;
    hand_pose_ = o.hand_pose_;
    gravity_ = o.gravity_;
    return *this;
  }
  MujocoScene(MujocoScene&&) noexcept = default;
  MujocoScene& operator=(MujocoScene&&) noexcept = default;
  ~MujocoScene() = default;

  /// Advances one scene step (substeps() MuJoCo steps), moving the hand to the pose set by
  /// set_hand_pose(). Returns Status::numerical_issue if MuJoCo met a bad number (it then resets
  /// its state, as it does) or the object's state is not finite; else Status::success.
  Status step() noexcept {
    const mjModel* m = model_.get();
    mjData* d = data_.get();
    const Vec3 p0(d->mocap_pos[3 * mocap_], d->mocap_pos[3 * mocap_ + 1],
                  d->mocap_pos[3 * mocap_ + 2]);
    const Eigen::Quaterniond q0(d->mocap_quat[4 * mocap_], d->mocap_quat[4 * mocap_ + 1],
                                d->mocap_quat[4 * mocap_ + 2], d->mocap_quat[4 * mocap_ + 3]);
    const Vec3 p1 = hand_pose_.translation();
    const Eigen::Quaterniond q1(hand_pose_.linear());
    const int bad_before = bad_number_warnings();
    apply_gravity();
    for (int k = 1; k <= substeps_; ++k) {
      const double a = static_cast<double>(k) / substeps_;
      const Vec3 p = (1.0 - a) * p0 + a * p1;
      const Eigen::Quaterniond q = q0.slerp(a, q1).normalized();
      for (int i = 0; i < 3; ++i) d->mocap_pos[3 * mocap_ + i] = p[i];
      d->mocap_quat[4 * mocap_] = q.w();
      d->mocap_quat[4 * mocap_ + 1] = q.x();
      d->mocap_quat[4 * mocap_ + 2] = q.y();
      d->mocap_quat[4 * mocap_ + 3] = q.z();
      mj_step(m, d);
    }
    const int qadr = m->jnt_qposadr[m->body_jntadr[object_]];
    for (int i = 0; i < 7; ++i)
      if (!std::isfinite(d->qpos[qadr + i])) return Status::numerical_issue;
    return bad_number_warnings() != bad_before ? Status::numerical_issue : Status::success;
  }

  /// Sets the hand frame pose (world) that the next step() moves the hand to. Throws
  /// topograsp::invalid_argument naming "pose" for a non-finite pose or a linear part that is not
  /// a rotation (orthonormal, det +1, to 1e-6).
  void set_hand_pose(const Eigen::Isometry3d& pose) {
    if (!pose.matrix().allFinite())
      detail::throw_invalid_argument("pose", "expected a finite number");
    const Mat3 R = pose.linear();
    if (!is_rotation(R))
      detail::throw_invalid_argument("pose", "expected a rotation (orthonormal, det +1)");
    hand_pose_ = pose;
  }
  /// The hand frame pose (world) set last: where the hand is after the next step().
  [[nodiscard]] const Eigen::Isometry3d& hand_pose() const noexcept { return hand_pose_; }

  /// Sets gravity (world, m/s^2). Throws topograsp::invalid_argument naming "g" for a
  /// non-finite entry.
  void set_gravity(const Vec3& g) {
    require_finite(g, "g");
    gravity_ = g;
  }
  /// Gravity (world, m/s^2).
  [[nodiscard]] Vec3 gravity() const noexcept { return gravity_; }

  /// The object frame (world).
  [[nodiscard]] Eigen::Isometry3d object_pose() const noexcept {
    return detail::mujoco_pose(data_->xpos + 3 * object_, data_->xquat + 4 * object_);
  }
  /// The object frame in the hand frame: the frame of the body that carries the hand
  /// (`hand_base` where the hand follows the mocap body through a weld, else `hand`).
  [[nodiscard]] Eigen::Isometry3d object_in_hand() const noexcept {
    return detail::mujoco_pose(data_->xpos + 3 * base_, data_->xquat + 4 * base_).inverse() *
           object_pose();
  }
  /// The object's centre of mass (world, m).
  [[nodiscard]] Vec3 object_com() const noexcept {
    return Vec3(data_->xipos[3 * object_], data_->xipos[3 * object_ + 1],
                data_->xipos[3 * object_ + 2]);
  }
  /// The palm centre (world, m): the site `palm`, or the origin of the body that carries the
  /// hand without one.
  [[nodiscard]] Vec3 palm_centre() const noexcept {
    if (palm_ < 0)
      return Vec3(data_->xpos[3 * base_], data_->xpos[3 * base_ + 1], data_->xpos[3 * base_ + 2]);
    return Vec3(data_->site_xpos[3 * palm_], data_->site_xpos[3 * palm_ + 1],
                data_->site_xpos[3 * palm_ + 2]);
  }
  /// The number of hand-object contacts that MuJoCo reports with a distance of at most
  /// \p max_separation (m). MuJoCo reports contacts out to each pair's margin (the export's
  /// MjcfOptions::report_distance), so a larger \p max_separation counts no more than those.
  [[nodiscard]] int hand_contacts(double max_separation = 0.0) const noexcept {
    int n = 0;
    for (int i = 0; i < data_->ncon; ++i)
      if (is_hand_object(data_->contact[i]) && data_->contact[i].dist <= max_separation) ++n;
    return n;
  }
  /// The total normal force (N) of the active hand-object contacts (mj_contactForce) at the last
  /// MuJoCo step.
  [[nodiscard]] double hand_force() const noexcept {
    double sum = 0.0;
    mjtNum f[6];
    for (int i = 0; i < data_->ncon; ++i) {
      const mjContact& c = data_->contact[i];
      if (c.exclude != 0 || c.efc_address < 0 || !is_hand_object(c)) continue;
      mj_contactForce(model_.get(), data_.get(), i, f);
      sum += f[0];
    }
    return sum;
  }
  /// The deepest hand-object overlap (m, >= 0; 0 when nothing overlaps).
  [[nodiscard]] double deepest_penetration() const noexcept {
    double deepest = 0.0;
    for (int i = 0; i < data_->ncon; ++i)
      if (is_hand_object(data_->contact[i])) deepest = std::max(deepest, -data_->contact[i].dist);
    return deepest;
  }
  /// How much deeper than the exact overlap MuJoCo's collider reports its hand-object contacts
  /// now (m, >= 0): the largest d_exact - d_mujoco over the hand-object contacts, d_exact the
  /// signed distance of the two geoms (geometry's signed_distance, exact to rounding for these
  /// shapes) and d_mujoco mjContact::dist. MuJoCo 2.2 measures a pair with a cylinder by its
  /// general convex collider (MPR), whose depth is taken along the line between the shapes'
  /// centres rather than the shortest way out: a capsule that overlaps the end of a long
  /// cylinder by 1.5 mm is reported 23 mm deep, and pushed out by the force of that depth.
  /// Geoms of other types than sphere, capsule, cylinder and box are skipped.
  [[nodiscard]] double collider_error() const noexcept {
    double worst = 0.0;
    for (int i = 0; i < data_->ncon; ++i) {
      const mjContact& c = data_->contact[i];
      if (!is_hand_object(c)) continue;
      const auto a = primitive(c.geom1);
      const auto b = primitive(c.geom2);
      if (!a || !b) continue;
      worst = std::max(worst, signed_distance(*a, *b).distance - c.dist);
    }
    return worst;
  }
  /// The object's mass (kg).
  [[nodiscard]] double object_mass() const noexcept { return model_->body_mass[object_]; }
  /// One step() (s): substeps() MuJoCo time steps.
  [[nodiscard]] double time_step() const noexcept { return substeps_ * model_->opt.timestep; }
  /// MuJoCo steps per step().
  [[nodiscard]] int substeps() const noexcept { return substeps_; }

  /// The MuJoCo model (shared by copies; read-only).
  [[nodiscard]] const mjModel& model() const noexcept { return *model_; }
  /// The MuJoCo state of this scene.
  [[nodiscard]] const mjData& data() const noexcept { return *data_; }
  /// The value of the joint named \p name (rad or m). Throws topograsp::invalid_argument naming
  /// "name" if the model has no hinge or slide joint of that name.
  [[nodiscard]] double joint_value(std::string_view name) const {
    const int j = mj_name2id(model_.get(), mjOBJ_JOINT, std::string(name).c_str());
    if (j < 0 || (model_->jnt_type[j] != mjJNT_HINGE && model_->jnt_type[j] != mjJNT_SLIDE))
      detail::throw_invalid_argument(
          "name", "no hinge or slide joint \"" + std::string(name) + "\" in the model");
    return data_->qpos[model_->jnt_qposadr[j]];
  }

 private:
  template <const auto& M, class S>
  static std::string checked_mjcf(const HandScene<M, S>& scene, const MjcfOptions& options) {
    if (options.effort.empty())
      for (int i = 0; i < M.nq; ++i)
        if (!(M.joint_spec(i).effort > 0.0))
          detail::throw_invalid_argument(
              "scene", "joint \"" + std::string(M.joint_name(i)) + "\" of " +
                           std::string(M.name.view()) +
                           " has no effort limit (LinkSpec::effort is 0): MuJoCo can only judge "
                           "a grasp held by motors with known torque limits");
    return to_mjcf(scene, options);
  }

  // Geom g as a primitive at its current pose; nullopt for a type it has no primitive of.
  [[nodiscard]] std::optional<Primitive> primitive(int g) const noexcept {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    for (int i = 0; i < 9; ++i) T.linear()(i / 3, i % 3) = data_->geom_xmat[9 * g + i];
    T.translation() =
        Vec3(data_->geom_xpos[3 * g], data_->geom_xpos[3 * g + 1], data_->geom_xpos[3 * g + 2]);
    const mjtNum* s = model_->geom_size + 3 * g;
    Primitive p;
    p.R = T.linear();
    p.p = T.translation();
    switch (model_->geom_type[g]) {
      case mjGEOM_SPHERE:
        p.type = ShapeType::sphere;
        p.size = Vec3(s[0], 0.0, 0.0);
        return p;
      case mjGEOM_CAPSULE:
        p.type = ShapeType::capsule;
        p.size = Vec3(s[0], s[1], 0.0);
        return p;
      case mjGEOM_CYLINDER:
        p.type = ShapeType::cylinder;
        p.size = Vec3(s[0], s[1], 0.0);
        return p;
      case mjGEOM_BOX:
        p.type = ShapeType::box;
        p.size = Vec3(s[0], s[1], s[2]);
        return p;
      default:
        return std::nullopt;
    }
  }

  [[nodiscard]] bool is_hand_object(const mjContact& c) const noexcept {
    const int b1 = model_->geom_bodyid[c.geom1];
    const int b2 = model_->geom_bodyid[c.geom2];
    const int other = b1 == object_ ? b2 : (b2 == object_ ? b1 : -1);
    return other >= 0 && model_->body_rootid[other] == base_;
  }

  [[nodiscard]] int bad_number_warnings() const noexcept {
    return data_->warning[mjWARN_BADQPOS].number + data_->warning[mjWARN_BADQVEL].number +
           data_->warning[mjWARN_BADQACC].number;
  }

  // Gravity beyond the model's, as the force m (g - g_model) at each body's centre of mass.
  void apply_gravity() noexcept {
    const mjModel* m = model_.get();
    const Vec3 g0(m->opt.gravity[0], m->opt.gravity[1], m->opt.gravity[2]);
    const Vec3 dg = gravity_ - g0;
    for (int b = 1; b < m->nbody; ++b)
      for (int i = 0; i < 3; ++i) data_->xfrc_applied[6 * b + i] = m->body_mass[b] * dg[i];
  }

  std::shared_ptr<const mjModel> model_;
  std::unique_ptr<mjData, detail::MujocoDataDeleter> data_;
  int substeps_ = 1;
  int hand_ = -1;
  int mocap_ = -1;
  int base_ = -1;  // the body that carries the hand: `hand_base`, or the mocap `hand` itself
  int object_ = -1;
  int palm_ = -1;
  Eigen::Isometry3d hand_pose_ = Eigen::Isometry3d::Identity();
  Vec3 gravity_ = Vec3::Zero();
};

static_assert(GraspScene<MujocoScene>);

#if defined(TOPOGRASP_EXTERN_HAND_INDEPENDENT) && defined(TOPOGRASP_HAVE_MUJOCO)
// Compiled once, in the one translation unit that includes grasp/hand_independent.hpp (which
// compiles it where TOPOGRASP_HAVE_MUJOCO is defined, as here)
// (docs/benchmarks.md, "Compiling the transfer once per program").
extern template StabilityResult stability_suite<MujocoScene>(const MujocoScene&,
                                                             const StabilityOptions&);
#endif

}  // namespace topograsp

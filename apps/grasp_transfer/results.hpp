// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The results of the grasp-transfer experiment as JSON (results.json, schema in
/// docs/transfer.md) and each tested grasp as an MJCF scene.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/file_name.hpp>
#include <grasp_transfer/output_folder.hpp>
#include <grasp_transfer/source_json.hpp>
#include <grasp_transfer/summaries.hpp>
#include <topograsp/evaluation/statistics.hpp>
#include <topograsp/grasp/grasp_identity.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/io/keypoint_grasp.hpp>
#include <topograsp/io/mjcf.hpp>

namespace topograsp {

/// The file name (relative to the output folder) of the MJCF scene of a grasp:
/// "scenes/<object>_<id>_<method>.xml", method "human" for the demonstration ("source" for a
/// source hand's, grasp_transfer --source). The object and
/// method names are cleaned by file_name_part (any byte but letters, digits, '-', '_' and a
/// non-leading '.' becomes '_', an empty name "_"), so no name ("../../x", "a/b", "", control
/// characters) can put the scene outside DIR/scenes.
[[nodiscard]] inline std::string scene_path(std::string_view object, int id,
                                            std::string_view method) {
  return "scenes/" + file_name_part(object) + "_" + std::to_string(id) + "_" +
         file_name_part(method) + ".xml";
}

/// The MJCF text of a closed grasp: hand model \p M at \p hand_pose with joints \p q, the object
/// where it was after closing, the motors holding with \p hold_torque as closing left them
/// (ClosingRecord::hold_torque, by configuration entry; hold_targets()).
template <const auto& M>
[[nodiscard]] std::string grasp_mjcf(const GraspObject& object, const Eigen::Isometry3d& hand_pose,
                                     const Vec<M.nq>& q, const Eigen::Isometry3d& object_pose,
                                     const std::vector<double>& hold_torque,
                                     const TransferOptions& options) {
  ObjectSpec spec = object_spec(object, hand_surface<M>(), options.sim.friction);
  spec.pose = to_pose(object_pose);
  HandScene<M> scene(hand_pose, q, spec, options.sim.scene);
  if (hold_torque.size() != static_cast<std::size_t>(M.nq))
    detail::throw_invalid_argument(
        "hold_torque",
        "expected " + std::to_string(M.nq) + " torques, got " + std::to_string(hold_torque.size()));
  scene.set_joint_targets(
      hold_targets(scene, q, hold_loads<M>(Eigen::Map<const Vec<M.nq>>(hold_torque.data(), M.nq))));
  return to_mjcf(scene);
}

namespace detail {

// The FNV-1a 64-bit hash of \p text as 16 hex digits (results.json's config records the files a
// run read by it).
inline std::string fnv1a_hex(std::string_view text) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a_64(text)));
  return hash;
}

// One test's record as results.json writes it; a test that was not run (steps 0) has null for
// what it would have measured.
inline Json json_record(const StabilityRecord& t) {
  const bool run = t.steps > 0;
  const auto measured = [run](auto value) { return run ? Json(value) : Json(); };
  Json r = Json::object();
  r.set("name", std::string(t.name));
  r.set("passed", t.passed);
  r.set("reason", std::string(t.reason));
  r.set("translation", measured(t.translation));
  r.set("rotation", measured(t.rotation));
  r.set("contacts", measured(t.contacts));
  r.set("force_median", measured(t.force_median));
  r.set("force_end", measured(t.force_end));
  r.set("force_ratio", measured(t.force_ratio));
  r.set("penetration", measured(t.penetration));
  r.set("steps", t.steps);
  r.set("status", run ? Json(std::string(to_string(t.status))) : Json());
  return r;
}

// The stability fields of a grasp record: the weight, the closing-end overlap and every test's
// record (none when nothing was simulated).
inline void set_stability(Json& rec, const StabilityResult* s) {
  Json tests = Json::array();
  if (s != nullptr)
    for (const StabilityRecord& t : s->tests) tests.push_back(json_record(t));
  rec.set("weight", s != nullptr ? Json(s->weight) : Json());
  rec.set("closing_penetration", s != nullptr ? Json(s->closing_penetration) : Json());
  rec.set("collider_error", s != nullptr ? Json(s->collider_error) : Json());
  rec.set("tests", tests);
}

// A pose as {"position": [x, y, z] (m), "quaternion": [w, x, y, z]} (w first, as MuJoCo).
inline Json json_pose(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  Json j = Json::object();
  j.set("position", json_vector(Vec3(T.translation())));
  j.set("quaternion", json_vector(Eigen::Vector4d(q.w(), q.x(), q.y(), q.z())));
  return j;
}

// The n numbers of a JSON array, or an error naming results.json's `what`.
inline Eigen::VectorXd numbers(const Json& a, int n, const char* what) {
  const Json::Array& v = a.as_array();
  if (static_cast<int>(v.size()) != n)
    detail::throw_invalid_argument(
        what, "expected " + std::to_string(n) + " numbers, got " + std::to_string(v.size()));
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = v[static_cast<std::size_t>(i)].as_number();
  return x;
}

// The pose of a record's json_pose.
inline Eigen::Isometry3d pose_of(const Json& j) {
  const Eigen::VectorXd p = numbers(j.at("position"), 3, "hand_pose.position");
  const Eigen::VectorXd q = numbers(j.at("quaternion"), 4, "hand_pose.quaternion");
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = p;
  T.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  return T;
}

// The joint names of model M, in configuration order.
template <const auto& M>
Json json_joint_names() {
  Json j = Json::array();
  for (int i = 0; i < M.nq; ++i) j.push_back(Json(M.joint_name(i)));
  return j;
}

// The joint values q of model M by joint name (rad; m for a prismatic joint).
template <const auto& M>
Json json_joint_values(const Vec<M.nq>& q) {
  Json j = Json::object();
  for (int i = 0; i < M.nq; ++i) j.set(M.joint_name(i), q[i]);
  return j;
}

// A configuration of hand M: its root link's pose in the object's frame and its joints by name.
template <const auto& M>
Json json_configuration(const Eigen::Isometry3d& root, const Vec<M.nq>& q) {
  Json j = Json::object();
  j.set("hand_pose", json_pose(root));
  j.set("joints", json_joint_values<M>(q));
  return j;
}

// A transfer's configurations: the pre-grasp (where the method put the hand before moving it in
// to contact), the grasp (where closing started) and the closed hand (when closing ended, in the
// object's frame then); null if nothing was placed.
template <const auto& M>
Json json_configurations(const HandTransfer<M>& t) {
  if (!t.planned) return Json();
  Json j = Json::object();
  j.set("pregrasp", t.pregrasp ? json_configuration<M>(t.pregrasp->root, t.pregrasp->q) : Json());
  j.set("grasp", json_configuration<M>(t.hand_pose, t.q_open));
  j.set("closed", json_configuration<M>(t.object_pose.inverse() * t.hand_pose, t.q_closed));
  return j;
}

// A planned motion: its step, the object's pose in its world, the joint names and each step's
// configuration; null without one.
inline Json json_motion(const std::optional<PlannedMotion>& m) {
  if (!m) return Json();
  Json j = Json::object();
  j.set("time_step", m->time_step);
  j.set("object_pose", json_pose(m->world_object));
  Json names = Json::array();
  for (std::string_view n : m->joints) names.push_back(Json(n));
  j.set("joints", names);
  Json q = Json::array();
  for (const Eigen::VectorXd& step : m->q) q.push_back(json_vector(step));
  j.set("q", q);
  return j;
}

// An object's symmetry for results.json's config, and back.
inline Json json_symmetry(const ObjectSymmetry& s) {
  Json j = Json::object();
  j.set("centre", json_vector(s.centre));
  Json rotations = Json::array();
  for (const Mat3& R : s.rotations)
    rotations.push_back(json_vector(Eigen::Map<const Eigen::Matrix<double, 9, 1>>(R.data())));
  j.set("rotations", rotations);
  j.set("axis", s.axis ? json_vector(*s.axis) : Json());
  j.set("isotropic", s.isotropic);
  return j;
}
inline ObjectSymmetry symmetry_of(const Json& j) {
  ObjectSymmetry s;
  s.centre = numbers(j.at("centre"), 3, "config.symmetry");
  s.rotations.clear();
  for (const Json& r : j.at("rotations").as_array())
    s.rotations.push_back(Eigen::Map<const Mat3>(numbers(r, 9, "config.symmetry").data()));
  if (!j.at("axis").is_null()) s.axis = Vec3(numbers(j.at("axis"), 3, "config.symmetry"));
  s.isotropic = j.at("isotropic").as_bool();
  return s;
}

// What closing did, for a grasp record (null when nothing was simulated): the object's motion
// while the hand closed, released and settled (m, rad), the contacts when closing ended (their
// count, and each point: its link, point and normal in the object's frame, force), and the
// motors' holding torques (by configuration entry; balanced or not, and the imbalance).
inline Json json_closing(const ClosingRecord* c) {
  if (c == nullptr) return Json();
  Json j = Json::object();
  j.set("object_shift", c->object_shift);
  j.set("object_turn", c->object_turn);
  j.set("contacts", c->contacts);
  j.set("touching_joints", c->touching_joints);
  Json points = Json::array();
  for (const HandContact& p : c->contact_points) {
    Json q = Json::object();
    q.set("link", p.link);
    q.set("point", json_vector(p.point));
    q.set("normal", json_vector(p.normal));
    q.set("force", p.force);
    points.push_back(q);
  }
  j.set("contact_points", points);
  j.set("hold_torque",
        json_vector(Eigen::Map<const Eigen::VectorXd>(
            c->hold_torque.data(), static_cast<Eigen::Index>(c->hold_torque.size()))));
  j.set("balanced_hold", c->balanced);
  j.set("hold_imbalance", c->hold_imbalance);
  j.set("hold_squeeze", c->hold_squeeze);
  j.set("load_squeeze", c->load_squeeze);
  j.set("grip", c->grip);
  return j;
}

// The second judge's verdict and records, and the grasp's Ferrari-Canny epsilon, of a grasp
// record (null when there is none).
inline void set_second_and_quality(Json& rec, const std::optional<StabilityResult>& second,
                                   const QualityRecord* quality, std::string_view name) {
  if (second) {
    Json j = Json::object();
    j.set("engine", std::string(name));
    j.set("stable", second->stable);
    j.set("reason", second->reason);
    set_stability(j, &*second);
    rec.set("second_judge", j);
  } else {
    rec.set("second_judge", Json());
  }
  if (quality != nullptr && quality->computed) {
    Json q = Json::object();
    q.set("epsilon", quality->epsilon);
    q.set("status", quality->status);
    q.set("reason", quality->reason);
    q.set("torque_scale", quality->torque_scale);
    rec.set("q1", q);
  } else {
    rec.set("q1", Json());
  }
}

// The stability options as results.json's config writes them (angles in degrees).
inline Json json_stability_options(const StabilityOptions& o, double time_step) {
  const auto motion = [](const ShakeMotion& m) {
    Json j = Json::object();
    j.set("steps", m.steps);
    j.set("rotations", m.rotations);
    j.set("min_angle_deg", m.min_angle / deg(1.0));
    j.set("max_angle_deg", m.max_angle / deg(1.0));
    return j;
  };
  Json j = Json::object();
  j.set("time_step", time_step);
  j.set("shake", motion(o.shake));
  j.set("direction_steps", o.direction_steps);
  j.set("hard_shake", motion(o.hard_shake));
  j.set("max_translation", o.max_translation);
  j.set("max_rotation_deg", o.max_rotation / deg(1.0));
  j.set("touch_distance", o.touch_distance);
  j.set("max_penetration", o.max_penetration);
  j.set("pivot", o.pivot == ShakePivot::palm ? "palm" : "object");
  j.set("every_test", o.every_test);
  return j;
}
}  // namespace detail

/// The reason of a simulated grasp's record: empty if \p stability holds it; else the first failed
/// test's ("shake: the object no longer touches the hand"), after "closing ended with no contact; "
/// when \p closing ended touching nothing (the fingers closed beside the object, or the object
/// fell away while they closed).
[[nodiscard]] inline std::string grasp_reason(const StabilityResult& stability,
                                              const ClosingRecord& closing) {
  if (stability.stable || closing.contacts > 0) return stability.reason;
  return "closing ended with no contact; " + stability.reason;
}

/// Checks that the objects of \p options have scene files of their own: distinct names can clean
/// to the same file name part ("a/b" and "a_b", file_name_part).
/// \throws topograsp::invalid_argument naming "objects" and both names if two would share files.
inline void check_scene_names(const ExperimentOptions& options) {
  for (std::size_t i = 0; i < options.objects.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (file_name_part(options.objects[i].name) == file_name_part(options.objects[j].name))
        detail::throw_invalid_argument(
            "objects", "\"" + options.objects[j].name + "\" and \"" + options.objects[i].name +
                           "\" would share the scene files \"" +
                           scene_path(options.objects[i].name, 0, "human") + "\", ...");
}

/// The "config" object of results.json for \p options, the demonstrations transferred to the hand
/// model named \p hand (docs/transfer.md).
[[nodiscard]] inline Json results_config(const ExperimentOptions& options,
                                         std::string_view hand = models::schunk_sdh.name.view()) {
  Json cfg = Json::object();
  cfg.set("hand", std::string(hand));
  Json objects = Json::array(), methods = Json::array();
  for (const GraspObject& o : options.objects) objects.push_back(o.name);
  for (const TransferMethod m : options.methods) methods.push_back(to_string(m));
  cfg.set("objects", objects);
  cfg.set("methods", methods);
  cfg.set("jobs", options.jobs);
  cfg.set("seed", std::to_string(options.seed));
  cfg.set("shard",
          std::to_string(options.shard_index + 1) + "/" + std::to_string(options.shard_count));
  cfg.set("max_hypotheses", options.max_hypotheses);
  if (!options.demonstrations.empty()) {  // recorded grasps in place of the planned ones
    // Each with the FNV-1a hash of its grasp as keypoint_grasp_json() writes it, so that --resume
    // and merge refuse a recording whose file changed in between, not only a renamed one.
    Json sources = Json::array();
    for (const RecordedGrasp& r : options.demonstrations) {
      Json d = Json::object();
      d.set("file", r.source);
      d.set("fnv1a_64", detail::fnv1a_hex(keypoint_grasp_json(r.grasp, r.source)));
      sources.push_back(std::move(d));
    }
    cfg.set("demonstrations", sources);
  }
  if (!options.sources.empty()) {  // a robot hand's grasps in place of the human's
    Json source = Json::object();
    source.set("results", options.source_results);
    source.set("hand", options.source_hand);
    source.set("method", "topological");
    source.set("fnv1a_64", options.source_hash);
    cfg.set("source", source);
  }
  // 0: each pair from the table of materials (docs/objects.md); else --friction's coefficient.
  cfg.set("friction", options.transfer.sim.friction);
  cfg.set("hand_stiffness", options.transfer.sim.scene.stepper.kinematic_stiffness);
  cfg.set("hold_fraction", options.transfer.sim.close.hold_fraction);
  cfg.set("human_hold_fraction", options.transfer.sim.human_hold_fraction);
  cfg.set("human_max_grip", options.transfer.sim.human_max_grip);
  cfg.set("judge", std::string(to_string(options.judge)));
  cfg.set("closing_steps", options.transfer.sim.close.closing_steps);
  cfg.set("hypotheses", std::string(to_string(options.hypotheses)));
  cfg.set("setting", options.arm_setting ? "arm" : "hand");
  cfg.set("palm_first", options.transfer.sim.palm_first);
  cfg.set("hold_object", options.transfer.sim.close.hold_object);
  cfg.set("release_steps", options.transfer.sim.close.release_steps);
  cfg.set("proximal_first", options.transfer.sim.close.proximal_first);
  cfg.set("balanced_hold", options.transfer.sim.close.balanced_hold);
  cfg.set("stability",
          detail::json_stability_options(options.transfer.sim.stability,
                                         options.transfer.sim.scene.stepper.time_step));
  cfg.set("aico_steps", options.transfer.aico.steps);
  // Which demonstrations are the same grasp (the clusters of results_document).
  Json symmetry = Json::object();
  for (const GraspObject& o : options.objects)
    symmetry.set(o.name, detail::json_symmetry(object_symmetry(o)));
  cfg.set("symmetry", symmetry);
  Json tolerance = Json::object();
  tolerance.set("position", options.grasp_tolerance.position);
  tolerance.set("angle", options.grasp_tolerance.angle);
  tolerance.set("joint", options.grasp_tolerance.joint);
  cfg.set("grasp_tolerance", tolerance);
  Json transfer = Json::object();
  for (const TransferParameter& p : transfer_parameters)
    transfer.set(std::string(p.name), p.get(options.transfer));
  transfer.set("winding_reference", std::string(to_string(options.transfer.winding_reference)));
  cfg.set("transfer", transfer);
  return cfg;
}

namespace detail {

// The record of the human demonstration g of object (which reached it).
inline Json human_record(const ExperimentOptions& options, const GraspObject& object,
                         const HumanGrasp& g) {
  const std::string& second_name = options.transfer.sim.second_judge_name;
  const std::string seed = std::to_string(grasp_seed(options.seed, object.name, g.id));
  Json rec = Json::object();
  rec.set("object", object.name);
  rec.set("id", g.id);
  rec.set("method", "human");
  // A recorded demonstration: its file (the object's id-th recording of the run).
  int k = 0;
  for (const RecordedGrasp& r : options.demonstrations)
    if (r.grasp.object == object.name && k++ == g.id) rec.set("demonstration", r.source);
  if (g.fit_error) {  // how far the fitted hand is from the recording's keypoints (m)
    Json e = Json::object();
    e.set("rms", g.fit_error->rms);
    e.set("max", g.fit_error->max);
    rec.set("fit_error", e);
  }
  rec.set("shake_seed", seed);
  if (options.demonstrations.empty()) {  // the hypothesis a planned demonstration comes from
    Json h = Json::object();
    h.set("box", g.hypothesis.box);
    h.set("face", g.hypothesis.face);
    h.set("roll",
          options.hypotheses == HypothesisRule::box ? g.hypothesis.turn * 2 : g.hypothesis.roll);
    h.set("jitter_seed",
          g.hypothesis.jitter_seed == 0 ? Json() : Json(std::to_string(g.hypothesis.jitter_seed)));
    rec.set("hypothesis", h);
  }
  rec.set("stable", g.stable());
  rec.set("scene", scene_path(object.name, g.id, "human"));
  rec.set("winding_human", detail::json_vector(g.windings));
  rec.set("winding_robot", Json::array());
  rec.set("plan_ms", 0.0);
  rec.set("sweeps", 0);
  rec.set("reason", grasp_reason(g.stability, g.closing));
  rec.set("closing", detail::json_closing(&g.closing));
  // The palm (the hand's root link) in the object's frame when closing ended, and the joints.
  rec.set("hand_pose", detail::json_pose(g.object_pose.inverse() * g.hand_pose));
  rec.set("joints", detail::json_vector(g.q));
  rec.set("joint_names", detail::json_joint_names<models::human_hand>());
  detail::set_stability(rec, &g.stability);
  detail::set_second_and_quality(rec, g.second, &g.quality, second_name);
  return rec;
}

}  // namespace detail

/// The grasp records of one hypothesis of \p object: its demonstration \p g (none if the human
/// hand did not reach the object) and each method's transfer of it to hand M, \p transfers in
/// options.methods order (empty when the demonstration was not stable), in the order
/// results_document sorts into.
template <const auto& M>
[[nodiscard]] std::vector<Json> hypothesis_records(
    const ExperimentOptions& options, const GraspObject& object, const HumanGrasp& g,
    const std::vector<const HandTransfer<M>*>& transfers) {
  std::vector<Json> out;
  if (!g.reached) return out;
  const std::string& second_name = options.transfer.sim.second_judge_name;
  const std::string seed = std::to_string(grasp_seed(options.seed, object.name, g.id));
  // A robot hand's grasp as the demonstration: its record in its own run (method "source").
  if (const SourceDemonstration* source = find_source(options.sources, object.name, g.id))
    out.push_back(source->record);
  else
    out.push_back(detail::human_record(options, object, g));
  for (const HandTransfer<M>* tp : transfers) {
    const HandTransfer<M>& t = *tp;
    Json r = Json::object();
    r.set("object", object.name);
    r.set("id", g.id);
    r.set("method", to_string(t.method));
    r.set("shake_seed", seed);
    r.set("stable", t.stable());
    r.set("scene", t.planned ? Json(scene_path(object.name, g.id, to_string(t.method))) : Json());
    // The human's y around the point of winding_robot (topological: its winding reference).
    r.set("winding_human", t.source_winding ? detail::json_vector(*t.source_winding)
                                            : detail::json_vector(g.descriptor.values));
    r.set("winding_robot", detail::json_vector(t.winding));
    r.set("plan_ms", t.plan_ms);
    r.set("sweeps", t.sweeps);
    r.set("reason", t.planned ? grasp_reason(t.stability, t.closing) : t.reason);
    // What the planner said of a planned transfer (AICO's termination, the virtual finger's
    // opposition), null if nothing.
    r.set("planner", t.planned && !t.reason.empty() ? Json(t.reason) : Json());
    r.set("closing", detail::json_closing(t.planned ? &t.closing : nullptr));
    // The arm setting: the arm's joints that reach the hand (the best found when it cannot).
    r.set("arm_joints", t.arm_joints ? detail::json_vector(*t.arm_joints) : Json());
    // What a robot executes: the object's pose in the arm's world (the plan's world, or the arm
    // setting's), the hand's configurations, and the topological plan.
    r.set("object_pose", t.motion              ? detail::json_pose(t.motion->world_object)
                         : options.arm_setting ? detail::json_pose(arm_setting_object_pose(object))
                                               : Json());
    r.set("configurations", detail::json_configurations(t));
    r.set("motion", detail::json_motion(t.motion));
    // The hand when closing ended as a source grasp, for a run that transfers from this hand
    // (grasp_transfer --source).
    r.set("source_grasp", t.planned ? source_grasp_json(describe_source(source_grasp(t))) : Json());
    detail::set_stability(r, t.planned ? &t.stability : nullptr);
    detail::set_second_and_quality(r, t.planned ? t.second : std::nullopt,
                                   t.planned ? &t.quality : nullptr, second_name);
    out.push_back(std::move(r));
  }
  return out;
}

namespace detail {

// Whether \p rec is a demonstration's record: a human hand's ("human") or, with
// grasp_transfer --source, a robot hand's ("source").
inline bool is_demonstration(const Json& rec) {
  const std::string& m = rec.at("method").as_string();
  return m == "human" || m == "source";
}

// Sets "cluster" on the records of one object (\p name): each stable demonstration's is the id of
// the first demonstration of its cluster (grasp_clusters() with the config's symmetry of the
// object and grasp_tolerance), each transfer's that of its demonstration, null for the rest.
inline void set_clusters(const Json& config, const std::string& name, std::vector<Json>& records) {
  const ObjectSymmetry symmetry = symmetry_of(config.at("symmetry").at(name));
  const Json& t = config.at("grasp_tolerance");
  const GraspTolerance tolerance{t.at("position").as_number(), t.at("angle").as_number(),
                                 t.at("joint").as_number()};
  std::vector<Eigen::Isometry3d> poses;
  std::vector<Eigen::VectorXd> joints;
  std::vector<Json*> stable;
  for (Json& rec : records) {
    rec.set("cluster", Json());
    if (!is_demonstration(rec) || !record_stable(rec)) continue;
    stable.push_back(&rec);
    poses.push_back(pose_of(rec.at("hand_pose")));
    const Json& q = rec.at("joints");
    joints.push_back(numbers(q, static_cast<int>(q.as_array().size()), "joints"));
  }
  const std::vector<int> cluster =
      grasp_clusters<Eigen::VectorXd>(poses, joints, symmetry, tolerance);
  std::vector<std::pair<double, double>> id_cluster;  // (id, its cluster's id)
  for (std::size_t i = 0; i < stable.size(); ++i) {
    const double c = stable[static_cast<std::size_t>(cluster[i])]->at("id").as_number();
    id_cluster.emplace_back(stable[i]->at("id").as_number(), c);
  }
  for (Json& rec : records)
    for (const auto& [id, c] : id_cluster)
      if (rec.at("id").as_number() == id) rec.set("cluster", c);
}

// The records that stand for their cluster: those whose cluster is their own id.
inline std::vector<const Json*> representatives(const std::vector<const Json*>& records) {
  std::vector<const Json*> out;
  for (const Json* rec : records) {
    const Json& c = rec->at("cluster");
    if (c.is_number() && c.as_number() == rec->at("id").as_number()) out.push_back(rec);
  }
  return out;
}

// How many of \p records are stable, the rate and its Wilson interval, by the deciding engine
// and by the second judge (null without one).
inline Json rate_summary(const std::vector<const Json*>& records) {
  const int n = static_cast<int>(records.size());
  int first = 0, second = 0;
  bool judged = false;
  for (const Json* rec : records) {
    first += record_stable(*rec) ? 1 : 0;
    second += record_stable_second(*rec) ? 1 : 0;
    judged = judged || !rec->at("second_judge").is_null();
  }
  Json j = Json::object();
  j.set("tested", n);
  j.set("stable", first);
  j.set("rate", n > 0 ? first / static_cast<double>(n) : 0.0);
  j.set("interval", json_interval(first, n));
  j.set("stable_second", judged ? Json(second) : Json());
  j.set("interval_second", judged ? json_interval(second, n) : Json());
  return j;
}

// The demonstrations of one object (\p human: its human records, one per hypothesis that reached
// the object) as docs/evaluation.md counts them: how many reached it and how many touch it when
// closing ends; stable by the deciding engine, by the second judge (null without one) and by
// both; distinct grasps among the stable ones (clusters) and among those both engines hold (the
// clusters with a member both hold); the object's median shift and turn while the hand closed;
// and the engines' agreement and Cohen's kappa over the demonstrations that touch the object (the
// grasps both reject without a contact say nothing about the engines; null without a second
// judge, kappa null where undefined).
inline Json demonstration_summary(int hypotheses, const std::vector<const Json*>& human) {
  int touching = 0, first = 0, both = 0;
  bool judged = false;
  std::vector<double> shift, turn;
  std::vector<std::pair<std::string, double>> clusters_both;  // (object, cluster): pooled objects
  std::vector<bool> first_touching, second_touching;
  for (const Json* rec : human) {
    const bool a = record_stable(*rec), b = record_stable_second(*rec);
    judged = judged || !rec->at("second_judge").is_null();
    first += a ? 1 : 0;
    both += a && b ? 1 : 0;
    if (a && b)
      clusters_both.emplace_back(rec->at("object").as_string(), rec->at("cluster").as_number());
    const Json& c = rec->at("closing");
    if (c.is_null()) continue;
    shift.push_back(c.at("object_shift").as_number());
    turn.push_back(c.at("object_turn").as_number());
    if (!(c.at("contacts").as_number() > 0)) continue;
    ++touching;
    first_touching.push_back(a);
    second_touching.push_back(b);
  }
  std::sort(clusters_both.begin(), clusters_both.end());
  const auto distinct_both = std::unique(clusters_both.begin(), clusters_both.end());
  Json j = Json::object();
  j.set("hypotheses", hypotheses);
  j.set("reached", static_cast<int>(human.size()));
  j.set("touching", touching);
  j.set("stable", first);
  j.set("stable_second", judged ? Json(static_cast<int>(std::count_if(
                                      human.begin(), human.end(),
                                      [](const Json* r) { return record_stable_second(*r); })))
                                : Json());
  j.set("stable_both", judged ? Json(both) : Json());
  j.set("distinct", static_cast<int>(representatives(human).size()));
  j.set("distinct_both",
        judged ? Json(static_cast<int>(distinct_both - clusters_both.begin())) : Json());
  j.set("median_object_shift", json_median(shift));
  j.set("median_object_turn", json_median(turn));
  if (judged && touching > 0) {
    const PairedComparison c = compare_paired(first_touching, second_touching);
    const double kappa = cohen_kappa(c);
    j.set("agreement_touching", (c.both + c.neither) / static_cast<double>(touching));
    j.set("kappa_touching", std::isnan(kappa) ? Json() : Json(kappa));
  } else {
    j.set("agreement_touching", Json());
    j.set("kappa_touching", Json());
  }
  return j;
}

}  // namespace detail

/// One object's part of a results.json: how many hypotheses were run and their grasp records
/// (hypothesis_records), in any order.
/// The name of results.json's "overall" entry: the summaries over every object's grasps.
inline constexpr std::string_view overall_name = "all objects";

struct ObjectRecords {
  std::string name;
  int hypotheses = 0;
  std::vector<Json> grasps;
};

/// results.json from its \p config (results_config) and each object's records: the objects in
/// config order, each object's records sorted (the demonstrations by id, then each method of
/// config["methods"] in turn by id), and every summary computed from the records, per object and
/// over all objects ("overall": the same summaries, name overall_name). So shards'
/// records put together give the document of the whole run (grasp_transfer merge).
/// \throws topograsp::invalid_argument naming "grasps" if a record's method is not in the config,
/// a (method, id) appears twice, or the methods did not transfer the same demonstrations; naming
/// "objects" if an object is not in the config or is given twice.
[[nodiscard]] inline Json results_document(const Json& config, std::vector<ObjectRecords> objects) {
  std::vector<std::string> methods;
  for (const Json& m : config.at("methods").as_array()) methods.push_back(m.as_string());
  std::vector<std::string> names;
  for (const Json& o : config.at("objects").as_array()) names.push_back(o.as_string());
  const auto id_text = [](const Json& rec) {
    return "hypothesis " + std::to_string(static_cast<long long>(rec.at("id").as_number()));
  };
  const auto index_of = [](const std::vector<std::string>& v, const std::string& x) {
    return static_cast<std::size_t>(std::find(v.begin(), v.end(), x) - v.begin());
  };
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (index_of(names, objects[i].name) == names.size())
      detail::throw_invalid_argument("objects",
                                     "\"" + objects[i].name + "\" is not in the config's objects");
    for (std::size_t j = 0; j < i; ++j)
      if (objects[i].name == objects[j].name)
        detail::throw_invalid_argument("objects", "\"" + objects[i].name + "\" is given twice");
  }
  std::sort(objects.begin(), objects.end(), [&](const ObjectRecords& a, const ObjectRecords& b) {
    return index_of(names, a.name) < index_of(names, b.name);
  });
  const std::size_t topological = index_of(methods, "topological") + 1;
  // The summaries of records grouped as `by` (the demonstrations, then each method in config
  // order, each in id order within an object): stable_human, human, methods.
  const auto summarise = [&](Json& obj, const std::vector<std::vector<const Json*>>& by) {
    obj.set("stable_human",
            static_cast<int>(std::count_if(by[0].begin(), by[0].end(), [](const Json* r) {
              return detail::record_stable(*r);
            })));
    obj.set("human", detail::stability_summary(by[0]));
    obj.set("distinct_human", static_cast<int>(detail::representatives(by[0]).size()));
    obj.set("demonstrations", detail::demonstration_summary(
                                  static_cast<int>(obj.at("hypotheses").as_number()), by[0]));
    const bool second = std::any_of(by.begin() + 1, by.end(), [](const auto& records) {
      return std::any_of(records.begin(), records.end(),
                         [](const Json* r) { return !r->at("second_judge").is_null(); });
    });
    Json ms = Json::object();
    for (std::size_t m = 0; m < methods.size(); ++m) {
      Json summary = detail::stability_summary(by[m + 1]);
      // Against the topological method on the same grasps (same shakes): McNemar's exact test.
      const bool paired = topological <= methods.size() && m + 1 != topological;
      summary.set("paired",
                  paired ? detail::paired_summary(by[m + 1], by[topological], false) : Json());
      summary.set("paired_second", paired && second
                                       ? detail::paired_summary(by[m + 1], by[topological], true)
                                       : Json());
      // The same on one demonstration per distinct grasp (its cluster's first).
      const std::vector<const Json*> reps = detail::representatives(by[m + 1]);
      summary.set("distinct", detail::rate_summary(reps));
      const std::vector<const Json*> topo_reps =
          paired ? detail::representatives(by[topological]) : std::vector<const Json*>{};
      summary.set("paired_distinct",
                  paired ? detail::paired_summary(reps, topo_reps, false) : Json());
      summary.set("paired_distinct_second",
                  paired && second ? detail::paired_summary(reps, topo_reps, true) : Json());
      ms.set(methods[m], summary);
    }
    obj.set("methods", ms);
  };
  Json out_objects = Json::array(), grasps = Json::array();
  std::vector<std::vector<const Json*>> all(methods.size() + 1);  // every object's, in order
  int all_hypotheses = 0;
  for (ObjectRecords& o : objects) {
    // The sort key: (method: the demonstration first, then config order; id).
    const auto key = [&](const Json& rec) {
      const std::string& m = rec.at("method").as_string();
      const std::size_t mi = detail::is_demonstration(rec) ? 0 : index_of(methods, m) + 1;
      if (mi == methods.size() + 1)
        detail::throw_invalid_argument("grasps", "method \"" + m + "\" of " + o.name + " " +
                                                     id_text(rec) +
                                                     " is not in the config's methods");
      return std::pair{mi, rec.at("id").as_number()};
    };
    std::sort(o.grasps.begin(), o.grasps.end(),
              [&](const Json& a, const Json& b) { return key(a) < key(b); });
    for (std::size_t i = 1; i < o.grasps.size(); ++i)
      if (key(o.grasps[i - 1]) == key(o.grasps[i]))
        detail::throw_invalid_argument("grasps", o.name + " " + id_text(o.grasps[i]) + " by " +
                                                     o.grasps[i].at("method").as_string() +
                                                     " is given twice");
    detail::set_clusters(config, o.name, o.grasps);
    std::vector<std::vector<const Json*>> by(methods.size() + 1);
    for (const Json& rec : o.grasps) by[key(rec).first].push_back(&rec);
    for (std::size_t m = 0; m < by.size(); ++m)
      all[m].insert(all[m].end(), by[m].begin(), by[m].end());
    all_hypotheses += o.hypotheses;
    Json obj = Json::object();
    obj.set("name", o.name);
    obj.set("hypotheses", o.hypotheses);
    summarise(obj, by);
    out_objects.push_back(obj);
  }
  // Every object's records together (the pairing holds object by object, in the same order).
  Json overall = Json::object();
  overall.set("name", std::string(overall_name));
  overall.set("hypotheses", all_hypotheses);
  summarise(overall, all);
  for (ObjectRecords& o : objects)
    for (Json& rec : o.grasps) grasps.push_back(std::move(rec));
  Json doc = Json::object();
  doc.set("generator", std::string(results_generator));
  doc.set("schema_version", results_schema_version);
  doc.set("config", config);
  doc.set("objects", out_objects);
  doc.set("overall", overall);
  doc.set("grasps", grasps);
  return doc;
}

/// results.json: {"generator": "topograsp grasp_transfer", "config": {...}, "objects": [...],
/// "grasps": [...]}; see docs/transfer.md. \p earlier: records of hypotheses an earlier run did
/// (options.skip; grasp_transfer --resume), by object name, with the number of them.
template <const auto& M>
[[nodiscard]] Json results_json(const ExperimentOptions& options,
                                const std::vector<ObjectResultOf<M>>& results,
                                const std::vector<ObjectRecords>& earlier = {}) {
  std::vector<ObjectRecords> objects;
  for (const ObjectResultOf<M>& r : results) {
    ObjectRecords o{r.object.name, r.hypotheses, {}};
    for (const HumanGrasp& g : r.human) {
      const auto k = std::find(r.transferred_ids.begin(), r.transferred_ids.end(), g.id);
      std::vector<const HandTransfer<M>*> transfers;
      if (k != r.transferred_ids.end())
        for (const std::vector<HandTransfer<M>>& ts : r.transfers)
          transfers.push_back(&ts[static_cast<std::size_t>(k - r.transferred_ids.begin())]);
      for (Json& rec : hypothesis_records<M>(options, r.object, g, transfers))
        o.grasps.push_back(std::move(rec));
    }
    for (const ObjectRecords& e : earlier)
      if (e.name == o.name) {
        o.hypotheses += e.hypotheses;
        o.grasps.insert(o.grasps.end(), e.grasps.begin(), e.grasps.end());
      }
    objects.push_back(std::move(o));
  }
  return results_document(results_config(options, M.name.view()), std::move(objects));
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The results of the grasp-transfer experiment as JSON (results.json, schema in
/// docs/transfer.md) and each tested grasp as an MJCF scene.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <topograsp/grasp/experiment.hpp>
#include <topograsp/io/file_name.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/io/mjcf.hpp>
#include <topograsp/io/output_folder.hpp>

namespace topograsp {

/// The file name (relative to the output folder) of the MJCF scene of a grasp:
/// "scenes/<object>_<id>_<method>.xml", method "human" for the demonstration. The object and
/// method names are cleaned by file_name_part (any byte but letters, digits, '-', '_' and a
/// non-leading '.' becomes '_', an empty name "_"), so no name ("../../x", "a/b", "", control
/// characters) can put the scene outside DIR/scenes.
[[nodiscard]] inline std::string scene_path(std::string_view object, int id,
                                            std::string_view method) {
  return "scenes/" + file_name_part(object) + "_" + std::to_string(id) + "_" +
         file_name_part(method) + ".xml";
}

/// The MJCF text of a closed grasp: hand model \p M at \p hand_pose with joints \p q, the object
/// where it was after closing.
template <const auto& M>
[[nodiscard]] std::string grasp_mjcf(const GraspObject& object, const Eigen::Isometry3d& hand_pose,
                                     const Vec<M.nq>& q, const Eigen::Isometry3d& object_pose,
                                     const TransferOptions& options) {
  HandSceneOptions scene_options = options.sim.scene;
  scene_options.friction = object.friction;
  ObjectSpec spec = object_spec(object);
  spec.pose = to_pose(object_pose);
  const HandScene<M> scene(hand_pose, q, spec, scene_options);
  return to_mjcf(scene);
}

namespace detail {
inline Json json_vector(const auto& v) {
  // Built in place: moving number-holding Json temporaries into a vector trips GCC 12's
  // -Wmaybe-uninitialized on std::variant.
  Json::Array a;
  a.reserve(static_cast<std::size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) a.emplace_back(static_cast<double>(v[i]));
  return Json(std::move(a));
}
}  // namespace detail

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

/// results.json: {"generator": "topograsp grasp_transfer", "config": {...}, "objects": [...],
/// "grasps": [...]}; see docs/transfer.md.
[[nodiscard]] inline Json results_json(const ExperimentOptions& options,
                                       const std::vector<ObjectResult>& results) {
  Json cfg = Json::object();
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
  cfg.set("friction_from_object", true);
  cfg.set("hand_stiffness", options.transfer.sim.scene.stepper.hand_stiffness);
  cfg.set("hold_fraction", options.transfer.sim.close.hold_fraction);
  cfg.set("closing_steps", options.transfer.sim.close.closing_steps);
  cfg.set("shake_steps", options.transfer.sim.shake.shake_steps);
  cfg.set("aico_steps", options.transfer.aico.steps);
  Json transfer = Json::object();
  for (const TransferParameter& p : transfer_parameters)
    transfer.set(std::string(p.name), options.transfer.*(p.field));
  transfer.set("winding_reference", std::string(to_string(options.transfer.winding_reference)));
  cfg.set("transfer", transfer);
  Json out_objects = Json::array();
  Json grasps = Json::array();
  for (const ObjectResult& r : results) {
    Json o = Json::object();
    o.set("name", r.object.name);
    o.set("hypotheses", r.hypotheses);
    o.set("stable_human", r.stable_human());
    Json ms = Json::object();
    for (const MethodSummary& m : r.methods) {
      Json s = Json::object();
      s.set("tested", m.tested);
      s.set("stable", m.stable);
      s.set("rate", m.rate());
      ms.set(to_string(m.method), s);
    }
    o.set("methods", ms);
    out_objects.push_back(o);
    for (const HumanGrasp& g : r.human) {
      if (!g.reached) continue;
      Json rec = Json::object();
      rec.set("object", r.object.name);
      rec.set("id", g.id);
      rec.set("method", "human");
      rec.set("stable", g.stable());
      rec.set("scene", scene_path(r.object.name, g.id, "human"));
      rec.set("winding_human", detail::json_vector(g.windings));
      rec.set("winding_robot", Json::array());
      rec.set("plan_ms", 0.0);
      rec.set("sweeps", 0);
      rec.set("reason", std::string(g.shake.reason));
      grasps.push_back(rec);
    }
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
      for (std::size_t k = 0; k < r.transfers[m].size(); ++k) {
        const RobotGrasp& t = r.transfers[m][k];
        const int id = r.transferred_ids[k];
        const HumanGrasp& g = *std::find_if(r.human.begin(), r.human.end(),
                                            [&](const HumanGrasp& h) { return h.id == id; });
        Json rec = Json::object();
        rec.set("object", r.object.name);
        rec.set("id", id);
        rec.set("method", to_string(r.methods[m].method));
        rec.set("stable", t.stable());
        rec.set("scene",
                t.planned ? Json(scene_path(r.object.name, id, to_string(t.method))) : Json());
        // The human's y as the method used it (topological: around its winding reference).
        rec.set("winding_human",
                detail::json_vector(t.winding_targets.empty() ? g.descriptor.values
                                                              : t.winding_targets.back()));
        rec.set("winding_robot", detail::json_vector(t.winding));
        rec.set("plan_ms", t.plan_ms);
        rec.set("sweeps", t.sweeps);
        rec.set("reason", t.planned ? std::string(t.shake.reason) : t.reason);
        grasps.push_back(rec);
      }
    }
  }
  Json doc = Json::object();
  doc.set("generator", std::string(results_generator));
  doc.set("config", cfg);
  doc.set("objects", out_objects);
  doc.set("grasps", grasps);
  return doc;
}

}  // namespace topograsp

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The results of the grasp-transfer experiment as JSON (results.json, schema in
/// docs/transfer.md) and each tested grasp as an MJCF scene.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <topograsp/evaluation/statistics.hpp>
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
/// where it was after closing, the motors holding as closing left them (hold_targets() with
/// options.sim.human_hold_fraction for the human hand, close.hold_fraction for a robot hand).
template <const auto& M>
[[nodiscard]] std::string grasp_mjcf(const GraspObject& object, const Eigen::Isometry3d& hand_pose,
                                     const Vec<M.nq>& q, const Eigen::Isometry3d& object_pose,
                                     const TransferOptions& options) {
  ObjectSpec spec = object_spec(object, hand_surface<M>(), options.sim.friction);
  spec.pose = to_pose(object_pose);
  HandScene<M> scene(hand_pose, q, spec, options.sim.scene);
  scene.set_joint_targets(hold_targets(scene, q,
                                       hand_surface<M>() == HandSurface::human_skin
                                           ? options.sim.human_hold_fraction
                                           : options.sim.close.hold_fraction));
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

// One test's record as results.json writes it.
inline Json json_record(const StabilityRecord& t) {
  Json r = Json::object();
  r.set("name", std::string(t.name));
  r.set("passed", t.passed);
  r.set("reason", std::string(t.reason));
  r.set("translation", t.translation);
  r.set("rotation", t.rotation);
  r.set("contacts", t.contacts);
  r.set("force_median", t.force_median);
  r.set("force_end", t.force_end);
  r.set("force_ratio", t.force_ratio);
  r.set("penetration", t.penetration);
  r.set("steps", t.steps);
  r.set("status", std::string(to_string(t.status)));
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
  rec.set("tests", tests);
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
    j.set("collider_error", second->collider_error);
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

// A grasp judged by both engines: the first's verdict, the second's, and whether both colliders
// measured the closed grasp's contacts to within k_collider_tolerance (the built-in's is exact;
// with --judge mujoco MuJoCo's verdict is the first).
struct Verdicts {
  bool first = false;
  bool second = false;
  bool exact = false;
};

inline Verdicts verdicts_of(const StabilityResult& first, const StabilityResult& second) {
  return {first.stable, second.stable,
          std::max(first.collider_error, second.collider_error) <= k_collider_tolerance};
}

// A rate's 95 % Wilson interval as [lower, upper].
inline Json json_interval(int successes, int trials) {
  const RateInterval i = wilson_interval(successes, trials);
  Json::Array a;
  a.emplace_back(i.lower);
  a.emplace_back(i.upper);
  return Json(std::move(a));
}

// Each engine's stable count over the grasps with both verdicts, the second engine's rate over
// the \p tested grasps (those judged by neither count as failing) with its Wilson interval, and
// how often the engines agree: over all judged grasps, and over those whose colliders were exact
// at the start.
inline Json agreement_summary(const std::vector<Verdicts>& verdicts, int tested,
                              std::string_view second_name) {
  if (verdicts.empty()) return Json();
  int first = 0, second = 0, agree = 0, exact = 0, agree_exact = 0;
  for (const Verdicts& v : verdicts) {
    first += v.first ? 1 : 0;
    second += v.second ? 1 : 0;
    agree += v.first == v.second ? 1 : 0;
    exact += v.exact ? 1 : 0;
    agree_exact += v.exact && v.first == v.second ? 1 : 0;
  }
  const double n = static_cast<double>(verdicts.size());
  Json s = Json::object();
  s.set("engine", std::string(second_name));
  s.set("judged", static_cast<int>(verdicts.size()));
  s.set("stable_first", first);
  s.set("stable_second", second);
  s.set("rate_second", tested > 0 ? second / static_cast<double>(tested) : 0.0);
  s.set("interval_second", json_interval(second, tested));
  s.set("agreement", agree / n);
  s.set("judged_exact", exact);
  s.set("agreement_exact", exact > 0 ? Json(agree_exact / static_cast<double>(exact)) : Json());
  return s;
}

// The median of v (0 values: null).
inline Json json_median(std::vector<double> v) {
  if (v.empty()) return Json();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return Json(n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

// The summary of a set of grasps (nullptr: not simulated, counts as failing every test): how
// many, how many stable, the rate, each test's pass rate, and the median over the stable ones of
// the paper shake's force ratio.
inline Json stability_summary(const std::vector<const StabilityResult*>& grasps) {
  Json s = Json::object();
  const int n = static_cast<int>(grasps.size());
  int stable = 0;
  std::array<int, k_stability_tests> passed{};
  std::vector<double> ratios;
  for (const StabilityResult* g : grasps) {
    if (g == nullptr) continue;
    for (std::size_t i = 0; i < k_stability_tests; ++i) passed[i] += g->tests[i].passed ? 1 : 0;
    if (!g->stable) continue;
    ++stable;
    ratios.push_back(g->shake().force_ratio);
  }
  const auto rate = [n](int k) { return n > 0 ? static_cast<double>(k) / n : 0.0; };
  s.set("tested", n);
  s.set("stable", stable);
  s.set("rate", rate(stable));
  s.set("interval", json_interval(stable, n));
  Json tests = Json::object();
  for (std::size_t i = 0; i < k_stability_tests; ++i)
    tests.set(std::string(to_string(static_cast<StabilityTest>(i))), rate(passed[i]));
  s.set("test_pass_rate", tests);
  s.set("median_force_ratio_stable", json_median(std::move(ratios)));
  return s;
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
  return j;
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
  // 0: each pair from the table of materials (docs/objects.md); else --friction's coefficient.
  cfg.set("friction", options.transfer.sim.friction);
  cfg.set("hand_stiffness", options.transfer.sim.scene.stepper.hand_stiffness);
  cfg.set("hold_fraction", options.transfer.sim.close.hold_fraction);
  cfg.set("human_hold_fraction", options.transfer.sim.human_hold_fraction);
  cfg.set("judge", std::string(to_string(options.judge)));
  cfg.set("closing_steps", options.transfer.sim.close.closing_steps);
  cfg.set("stability",
          detail::json_stability_options(options.transfer.sim.stability,
                                         options.transfer.sim.scene.stepper.time_step));
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
    const std::string& second_name = options.transfer.sim.second_judge_name;
    std::vector<const StabilityResult*> set;
    std::vector<detail::Verdicts> verdicts;
    for (const HumanGrasp& g : r.human)
      if (g.reached) {
        set.push_back(&g.stability);
        if (g.second) verdicts.push_back(detail::verdicts_of(g.stability, *g.second));
      }
    Json human = detail::stability_summary(set);
    human.set("second_judge",
              detail::agreement_summary(verdicts, static_cast<int>(set.size()), second_name));
    o.set("human", human);
    Json ms = Json::object();
    const auto topological = std::find_if(
        r.methods.begin(), r.methods.end(),
        [](const MethodSummary& m) { return m.method == TransferMethod::topological; });
    const bool with_second =
        std::any_of(r.transfers.begin(), r.transfers.end(), [](const std::vector<RobotGrasp>& ts) {
          return std::any_of(ts.begin(), ts.end(), [](const RobotGrasp& t) { return t.second; });
        });
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
      set.clear();
      verdicts.clear();
      for (const RobotGrasp& t : r.transfers[m]) {
        set.push_back(t.planned ? &t.stability : nullptr);
        if (t.planned && t.second) verdicts.push_back(detail::verdicts_of(t.stability, *t.second));
      }
      Json s = detail::stability_summary(set);
      s.set("tested", r.methods[m].tested);
      s.set("stable", r.methods[m].stable);
      s.set("rate", r.methods[m].rate());
      s.set("interval", detail::json_interval(r.methods[m].stable, r.methods[m].tested));
      s.set("second_judge", detail::agreement_summary(verdicts, r.methods[m].tested, second_name));
      // Against the topological method on the same grasps (same shakes): McNemar's exact test.
      const auto paired = [&](bool second_judge) -> Json {
        if (topological == r.methods.end() || r.methods[m].method == TransferMethod::topological ||
            (second_judge && !with_second))
          return Json();
        const std::size_t t = static_cast<std::size_t>(topological - r.methods.begin());
        const PairedComparison c = compare_paired(method_outcomes(r, m, second_judge),
                                                  method_outcomes(r, t, second_judge));
        Json j = Json::object();
        j.set("against", "topological");
        j.set("both", c.both);
        j.set("only_this", c.only_first);
        j.set("only_against", c.only_second);
        j.set("neither", c.neither);
        j.set("p_value", c.p_value);
        return j;
      };
      s.set("paired", paired(false));
      s.set("paired_second", paired(true));
      ms.set(to_string(r.methods[m].method), s);
    }
    o.set("methods", ms);
    out_objects.push_back(o);
    for (const HumanGrasp& g : r.human) {
      if (!g.reached) continue;
      Json rec = Json::object();
      rec.set("object", r.object.name);
      rec.set("id", g.id);
      rec.set("method", "human");
      rec.set("shake_seed", std::to_string(grasp_seed(options.seed, r.object.name, g.id)));
      rec.set("stable", g.stable());
      rec.set("scene", scene_path(r.object.name, g.id, "human"));
      rec.set("winding_human", detail::json_vector(g.windings));
      rec.set("winding_robot", Json::array());
      rec.set("plan_ms", 0.0);
      rec.set("sweeps", 0);
      rec.set("reason", g.stability.reason);
      detail::set_stability(rec, &g.stability);
      detail::set_second_and_quality(rec, g.second, &g.quality, second_name);
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
        rec.set("shake_seed", std::to_string(grasp_seed(options.seed, r.object.name, id)));
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
        rec.set("reason", t.planned ? t.stability.reason : t.reason);
        detail::set_stability(rec, t.planned ? &t.stability : nullptr);
        detail::set_second_and_quality(rec, t.planned ? t.second : std::nullopt,
                                       t.planned ? &t.quality : nullptr, second_name);
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

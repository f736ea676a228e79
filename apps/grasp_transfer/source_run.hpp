// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// grasp_transfer --source: a robot hand as the demonstrator. The stable topological transfers of
/// an earlier run (its results.json: each planned transfer's source_grasp, record and scene)
/// become the demonstrations of a run to another hand (docs/transfer.md, "A robot hand as the
/// demonstrator").
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/output_folder.hpp>
#include <grasp_transfer/results.hpp>
#include <grasp_transfer/source_json.hpp>
#include <topograsp/io/json_schema.hpp>
#include <topograsp/io/ycb_objects.hpp>

namespace topograsp {

/// The keys of the config (results_config) under which a source run must equal the run that
/// takes its grasps: what decides a verdict (the shakes' seed, the judges, friction, the closing
/// and the stability suite), so that a demonstration's verdict and its transfers' are made alike.
inline const std::vector<std::string>& source_config_keys() {
  static const std::vector<std::string> keys{"seed",           "judge",         "friction",
                                             "hand_stiffness", "hold_fraction", "closing_steps",
                                             "hold_object",    "release_steps", "proximal_first",
                                             "balanced_hold",  "stability"};
  return keys;
}

namespace detail {

// The record of transfer record rec (grasps[i] of the run's results.json at `file`, `where`; one
// the schema accepts) as a demonstration of this run: its verdicts, closing and windings as they
// were, method "source", the source hand's model name, the run it comes from, its closed
// configuration (hand_pose in the object's frame, joints and their names) and its scene's path in
// this run.
inline Json source_demonstration_record(const Json& rec, const std::string& hand,
                                        const std::string& file, const std::string& where) {
  const auto field = [&](std::string_view key) -> const Json& { return rec.at(key); };
  Json out = Json::object();
  for (const std::string_view key :
       {"object", "id", "shake_seed", "stable", "winding_human", "winding_robot", "plan_ms",
        "sweeps", "reason", "closing", "weight", "closing_penetration", "collider_error", "tests",
        "second_judge", "q1"})
    out.set(key, field(key));
  out.set("method", "source");
  out.set("hand", hand);
  out.set("demonstration", file);
  out.set("scene", scene_path(field("object").as_string(),
                              static_cast<int>(field("id").as_number()), "source"));
  const Json& configurations = field("configurations");
  if (configurations.is_null())  // the schema allows it for a transfer that was not placed
    throw_invalid_argument(where + ".configurations", "null for a stable transfer");
  const Json& closed = configurations.at("closed");
  out.set("hand_pose", closed.at("hand_pose"));
  Json values = Json::array(), names = Json::array();
  for (const auto& [name, value] : closed.at("joints").as_object()) {
    names.push_back(name);
    values.push_back(value);
  }
  out.set("joints", std::move(values));
  out.set("joint_names", std::move(names));
  out.set("cluster", Json());
  return out;
}

}  // namespace detail

/// Reads the run \p run (a grasp_transfer output folder, or its results.json) as the
/// demonstrations of \p options (options.sources, source_results: the file's canonical path,
/// source_hand, source_hash, source_config): each planned topological transfer its deciding judge
/// held, of an object of \p objects (all of the run's when empty), with its source grasp, its
/// record as a demonstration (detail::source_demonstration_record) and its scene.
/// \throws topograsp::invalid_argument naming "--source", then the file and the field: a path that
/// does not exist or cannot be read; a file that is not a results.json of grasp_transfer of this
/// schema_version, or that does not conform to the shipped schema (data/schemas/
/// results.schema.json, which must be readable); a shard of a run (merge it first); an object of
/// \p objects that the run does not have; a source grasp of another hand than the run's, or one
/// that unusable_source() refuses; a hypothesis given twice; a scene that is not the one
/// grasp_transfer writes for the record (scenes/<object>_<id>_topological.xml, a regular file
/// beside the results.json); or a run with no stable topological transfer.
inline void read_source_run(const std::filesystem::path& run,
                            const std::vector<std::string>& objects, ExperimentOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(run, ec))
    detail::throw_invalid_argument("--source", "\"" + run.string() +
                                                   "\" does not exist (expected a grasp_transfer "
                                                   "output folder or its results.json)");
  const fs::path file = fs::is_directory(run, ec) ? run / "results.json" : run;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  const std::string name = ec ? file.string() : canonical.string();
  const std::string text = detail::read_text_file(file, "--source");
  const fs::path schema_file = fs::path(data_directory()) / "schemas" / "results.schema.json";
  const Json schema = Json::parse(detail::read_text_file(schema_file, "--source"));
  try {
    const Json doc = Json::parse(text);
    const auto top = [&](std::string_view key) -> const Json& {
      if (!doc.is_object() || !doc.contains(key))
        detail::throw_invalid_argument(key, "missing (not a results.json of grasp_transfer)");
      return doc.at(key);
    };
    if (!top("generator").is_string() || top("generator").as_string() != results_generator)
      detail::throw_invalid_argument("generator",
                                     "expected \"" + std::string(results_generator) + "\"");
    if (!top("schema_version").is_number() ||
        top("schema_version").as_number() != results_schema_version)
      detail::throw_invalid_argument(
          "schema_version", "expected " + std::to_string(results_schema_version) +
                                " (a run of an older grasp_transfer has no source grasps: run it "
                                "again)");
    // Every field as the schema says (types, ids, records), so that what is copied is sound.
    if (const std::vector<std::string> problems = validate_json(doc, schema); !problems.empty())
      detail::throw_invalid_argument("schema",
                                     problems.front() + " (" + schema_file.string() + ")");
    const Json& config = doc.at("config");
    if (config.at("shard").as_string() != "1/1")
      detail::throw_invalid_argument("config.shard",
                                     "a shard of a run (" + config.at("shard").as_string() +
                                         "): merge its shards first (grasp_transfer merge)");
    for (const std::string& o : objects) {
      bool has = false;
      for (const Json& n : config.at("objects").as_array()) has = has || n.as_string() == o;
      if (!has)
        detail::throw_invalid_argument("config.objects",
                                       "the run has no object \"" + o + "\" (--objects)");
    }
    const std::string hand = config.at("hand").as_string();
    const Json::Array& grasps = doc.at("grasps").as_array();
    std::vector<SourceDemonstration> sources;
    for (std::size_t i = 0; i < grasps.size(); ++i) {
      const Json& rec = grasps[i];
      const std::string where = "grasps[" + std::to_string(i) + "]";
      if (rec.at("method").as_string() != "topological" || !rec.at("stable").as_bool()) continue;
      SourceDemonstration d;
      d.object = rec.at("object").as_string();
      if (!objects.empty() && std::find(objects.begin(), objects.end(), d.object) == objects.end())
        continue;
      d.id = static_cast<int>(rec.at("id").as_number());  // the schema: a whole number < 2^31
      for (const SourceDemonstration& e : sources)
        if (e.object == d.object && e.id == d.id)
          detail::throw_invalid_argument(where, d.object + " hypothesis " + std::to_string(d.id) +
                                                    " by topological is given twice");
      d.grasp = source_grasp_of(rec.at("source_grasp"), where + ".source_grasp");
      if (d.grasp.hand != hand)
        detail::throw_invalid_argument(
            where + ".source_grasp.hand",
            "\"" + d.grasp.hand + "\", but the run's hand is \"" + hand + "\"");
      d.record = detail::source_demonstration_record(rec, hand, name, where);
      const std::string scene = scene_path(d.object, d.id, "topological");
      if (!rec.at("scene").is_string() || rec.at("scene").as_string() != scene)
        detail::throw_invalid_argument(where + ".scene", "expected \"" + scene + "\"");
      const fs::path scene_file = file.parent_path() / scene;
      if (!fs::is_regular_file(scene_file, ec))
        detail::throw_invalid_argument(where + ".scene",
                                       "\"" + scene_file.string() + "\" is not a file");
      d.scene = detail::read_text_file(scene_file, where + ".scene");
      sources.push_back(std::move(d));
    }
    if (sources.empty())
      detail::throw_invalid_argument(
          "grasps", "no stable topological transfer" +
                        std::string(objects.empty() ? "" : " of the run's objects") +
                        " to take as a demonstration");
    options.sources = std::move(sources);
    options.source_results = name;
    options.source_hand = hand;
    options.source_hash = detail::fnv1a_hex(text);
    options.source_config = config;
  } catch (const invalid_argument& e) {
    detail::throw_invalid_argument("--source", name + ": " + e.what());
  }
}

/// Checks that the source run of \p options was made as the run of config \p config will judge
/// (source_config_keys()). \throws topograsp::invalid_argument naming "--source", the key and both
/// values, if they differ.
inline void check_source_config(const ExperimentOptions& options, const Json& config) {
  if (options.sources.empty()) return;
  for (const std::string& key : source_config_keys()) {
    const std::string a = options.source_config.contains(key)
                              ? options.source_config.at(key).dump(0)
                              : std::string("missing");
    const std::string b = config.at(key).dump(0);
    if (a != b)
      detail::throw_invalid_argument(
          "--source", options.source_results + ": its config's \"" + key + "\" is " + a +
                          ", this run's " + b +
                          " (a demonstration is judged as its transfers are: run both alike)");
  }
}

}  // namespace topograsp

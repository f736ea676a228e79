// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// grasp_transfer --source: a robot hand as the demonstrator. The stable topological transfers of
/// an earlier run (its results.json: each planned transfer's source_grasp, record and scene)
/// become the demonstrations of a run to another hand (docs/transfer.md, "A robot hand as the
/// demonstrator").
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/output_folder.hpp>
#include <grasp_transfer/results.hpp>
#include <grasp_transfer/source_json.hpp>

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

// The record of transfer record rec (grasps[i] of the run's results.json at `file`) as a
// demonstration of this run: its verdicts, closing and windings as they were, method "source",
// the source hand's model name, the run it comes from, its closed configuration (hand_pose in
// the object's frame, joints and their names) and its scene's path in this run.
inline Json source_demonstration_record(const Json& rec, const std::string& hand,
                                        const std::string& file, const std::string& where) {
  const auto field = [&](std::string_view key) -> const Json& {
    if (!rec.contains(key)) throw_invalid_argument(where, "missing \"" + std::string(key) + "\"");
    return rec.at(key);
  };
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
  if (!configurations.is_object() || !configurations.contains("closed"))
    throw_invalid_argument(where + ".configurations", "expected the closed configuration");
  const Json& closed = configurations.at("closed");
  if (!closed.contains("hand_pose") || !closed.contains("joints") ||
      !closed.at("joints").is_object())
    throw_invalid_argument(where + ".configurations.closed", "expected hand_pose and joints");
  out.set("hand_pose", closed.at("hand_pose"));
  Json values = Json::array(), names = Json::array();
  for (const auto& [name, value] : closed.at("joints").as_object()) {
    if (!value.is_number())
      throw_invalid_argument(where + ".configurations.closed.joints." + name, "expected a number");
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
/// demonstrations of \p options (options.sources, source_results, source_hand, source_hash,
/// source_config): each planned topological transfer its deciding judge held, of an object of the
/// run when \p objects is not empty, with its source grasp, its record as a demonstration
/// (detail::source_demonstration_record) and its scene.
/// \throws topograsp::invalid_argument naming "--source", then the file and the field: a file
/// that cannot be read or is not a results.json of this schema_version, a record or source grasp
/// that is malformed or that unusable_source() refuses, a scene that cannot be read, an object of
/// \p objects that the run does not have, or a run with no stable topological transfer.
inline void read_source_run(const std::filesystem::path& run,
                            const std::vector<std::string>& objects, ExperimentOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(run, ec))
    detail::throw_invalid_argument("--source", "\"" + run.string() +
                                                   "\" does not exist (expected a grasp_transfer "
                                                   "output folder or its results.json)");
  const fs::path file = fs::is_directory(run, ec) ? run / "results.json" : run;
  const std::string name = file.string();
  const std::string text = detail::read_text_file(file, "--source");
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
    const Json& config = top("config");
    if (!config.is_object() || !config.contains("hand") || !config.at("hand").is_string() ||
        !config.contains("objects") || !config.at("objects").is_array())
      detail::throw_invalid_argument("config", "expected its hand and objects");
    for (const std::string& o : objects) {
      bool has = false;
      for (const Json& n : config.at("objects").as_array()) has = has || n.as_string() == o;
      if (!has)
        detail::throw_invalid_argument("config.objects",
                                       "the run has no object \"" + o + "\" (--objects)");
    }
    const std::string hand = config.at("hand").as_string();
    const Json& grasps = top("grasps");
    if (!grasps.is_array()) detail::throw_invalid_argument("grasps", "expected an array");
    std::vector<SourceDemonstration> sources;
    for (std::size_t i = 0; i < grasps.as_array().size(); ++i) {
      const Json& rec = grasps.as_array()[i];
      const std::string where = "grasps[" + std::to_string(i) + "]";
      if (!rec.is_object() || !rec.contains("method") || !rec.contains("stable") ||
          !rec.contains("object") || !rec.contains("id"))
        detail::throw_invalid_argument(where, "expected a grasp record");
      if (rec.at("method").as_string() != "topological" || !rec.at("stable").as_bool()) continue;
      SourceDemonstration d;
      d.object = rec.at("object").as_string();
      if (!objects.empty() && std::find(objects.begin(), objects.end(), d.object) == objects.end())
        continue;
      d.id = static_cast<int>(rec.at("id").as_number());
      if (!rec.contains("source_grasp"))
        detail::throw_invalid_argument(where, "missing \"source_grasp\"");
      d.grasp = source_grasp_of(rec.at("source_grasp"), where + ".source_grasp");
      d.record = detail::source_demonstration_record(rec, hand, name, where);
      if (!rec.contains("scene") || !rec.at("scene").is_string())
        detail::throw_invalid_argument(where + ".scene", "expected the scene's file");
      d.scene = detail::read_text_file(file.parent_path() / rec.at("scene").as_string(), where);
      sources.push_back(std::move(d));
    }
    if (sources.empty())
      detail::throw_invalid_argument(
          "grasps", "no stable topological transfer" +
                        std::string(objects.empty() ? "" : " of the run's objects") +
                        " to take as a demonstration");
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx",
                  static_cast<unsigned long long>(detail::fnv1a_64(text)));
    options.sources = std::move(sources);
    options.source_results = name;
    options.source_hand = hand;
    options.source_hash = hash;
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

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// grasp_transfer's program for one robot hand: run_hand<M> runs the experiment with the
/// demonstrations (the human hand's, or a source hand's) transferred to hand M (or resumes it),
/// journals each hypothesis, writes its scenes, records and figures and commits the output folder;
/// print_table prints Table I from a results.json. Each hand of a program is compiled in a
/// translation unit of its own that registers it (TOPOGRASP_HAND_PROGRAM,
/// apps/grasp_transfer/hands/*.cpp; a user's imported hand by topograsp_add_hand_program()), and
/// main.cpp picks the one --hand names (docs/transfer.md, "Any hand").
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <grasp_transfer/command_line.hpp>
#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/output_folder.hpp>
#include <grasp_transfer/report.hpp>
#include <grasp_transfer/results.hpp>
#include <topograsp/grasp/check_hand.hpp>
#ifdef TOPOGRASP_HAVE_MUJOCO
#include <topograsp/mujoco/mujoco_scene.hpp>
#endif

namespace topograsp::app {

/// The MJCF scene of the demonstration \p g (grasp_mjcf of the human hand; human.cpp).
[[nodiscard]] std::string human_scene(const GraspObject& object, const HumanGrasp& g,
                                      const TransferOptions& options);

#ifdef TOPOGRASP_HAVE_MUJOCO
/// The stability suite of a human grasp's scene run in MuJoCo (human.cpp).
[[nodiscard]] StabilityResult mujoco_judge_human(const HandScene<models::human_hand>& scene,
                                                 const StabilityOptions& options);
#endif

/// Prints the paper's Table I next to the measured one from a results.json (the paper's numbers
/// for the SDH only), with a second judge its rates too, then each method against the
/// topological one on the same grasps (main.cpp).
void print_table(const Json& doc);

/// Copies the scene files of \p records from the folder \p from into the folder \p to (both hold
/// scenes/; main.cpp). \throws topograsp::invalid_argument naming the file that cannot be copied.
void copy_scenes(const std::vector<Json>& records, const std::filesystem::path& from,
                 const std::filesystem::path& to);

// The MJCF scene of each grasp of a hypothesis, into dir/scenes: the demonstration (the human
// hand's, or a source's scene as its run wrote it) and each planned transfer to hand M.
template <const auto& M>
void write_scenes(const std::filesystem::path& dir, const ExperimentOptions& experiment,
                  const GraspObject& object, const HumanGrasp& g,
                  const std::vector<HandTransfer<M>>& transfers) {
  if (!g.reached) return;
  if (const SourceDemonstration* source =
          find_source(experiment.sources, object.name,
                      g.id))  // a robot hand's grasp: its scene in the run it comes from
    detail::write_text_file(dir / scene_path(object.name, g.id, "source"), source->scene);
  else
    detail::write_text_file(dir / scene_path(object.name, g.id, "human"),
                            human_scene(object, g, experiment.transfer));
  for (const HandTransfer<M>& t : transfers)
    if (t.planned)
      detail::write_text_file(dir / scene_path(object.name, g.id, to_string(t.method)),
                              grasp_mjcf<M>(object, t.hand_pose, t.q_closed, t.object_pose,
                                            t.closing.hold_torque, experiment.transfer));
}

// The self-check of hand M (check_hand) before any transfer: each trial through progress; a hand
// that fails it is refused, naming what is wrong (topograsp::invalid_argument naming "--hand").
template <const auto& M>
void check_program_hand(const ProgressFn& progress) {
  const HandCheck check = check_hand<M>();
  const std::string hand(M.name.view());
  std::string trials;
  for (const HandTrial& t : check.trials) {
    const std::string line = t.object + (t.stable ? " held" : " not held: " + t.reason);
    progress("check_hand: " + hand + ": " + line);
    trials += (trials.empty() ? "" : "; ") + line;
  }
  if (check.ok()) return;
  std::string problems;
  for (const std::string& p : check.problems) problems += "; " + p;
  detail::throw_invalid_argument(
      "--hand", "the " + hand + " fails its self-check (check_hand, docs/models.md): " + trials +
                    problems + " (fix its description, or run anyway with --skip-hand-check)");
}

// The experiment with hand M: run (or resume), journal each hypothesis, write and commit the output
// folder. started: the computation has started (exit status 1 from here, 2 before); committing:
// the output folder's commit has started.
template <const auto& M>
int run_hand(CommandLine& cli, bool& started, bool& committing) {
  SecondJudge<M> second;  // hand M's, with --judge mujoco or both
#ifdef TOPOGRASP_HAVE_MUJOCO
  if (cli.experiment.judge != Judge::builtin) {
    // MuJoCo judges each closed grasp with the same suite: the scene exported articulated
    // (io/mjcf.hpp) and stepped through MujocoScene.
    GraspSimOptions& sim = cli.experiment.transfer.sim;
    sim.second_judge_human = mujoco_judge_human;
    second = [](const HandScene<M>& scene, const StabilityOptions& o) {
      return stability_suite(MujocoScene(scene), o);
    };
    sim.second_judge_name = cli.experiment.judge == Judge::mujoco ? "builtin" : "mujoco";
    sim.second_judge_decides = cli.experiment.judge == Judge::mujoco;
  }
#endif
  if (cli.resume && cli.figures)
    throw invalid_argument(
        "--figures: draws the grasps of this run only, so not with --resume (draw them from a "
        "run without it)");
  validate_experiment_options<M>(cli.experiment, second);
  const ProgressFn progress = [quiet = cli.quiet](std::string_view line) {
    if (!quiet || line.starts_with("warning:")) std::cerr << line << '\n';
  };
  if (cli.check_hand) check_program_hand<M>(progress);
  check_scene_names(cli.experiment);
  OutputFolder folder(cli.out, cli.force, "--out", cli.resume);  // checked before any work
  const std::filesystem::path& stage = folder.staging();
  std::filesystem::create_directories(stage / "scenes");
  const Json config = results_config(cli.experiment, M.name.view());
  // --resume: the hypotheses that interrupted runs journalled (with all their scenes), once each.
  std::vector<JournalEntry> resumed;
  for (const std::filesystem::path& leftover : folder.leftovers()) {
    if (!std::filesystem::exists(leftover / journal_file_name)) continue;
    for (JournalEntry& e : read_journal(leftover / journal_file_name, config)) {
      const bool seen = std::any_of(resumed.begin(), resumed.end(), [&](const JournalEntry& r) {
        return r.object == e.object && r.id == e.id;
      });
      const bool whole = std::all_of(e.records.begin(), e.records.end(), [&](const Json& r) {
        return !r.at("scene").is_string() ||
               std::filesystem::exists(leftover / r.at("scene").as_string());
      });
      if (seen || !whole) continue;
      copy_scenes(e.records, leftover, stage);
      resumed.push_back(std::move(e));
    }
  }
  folder.remove_leftovers();
  ResultsJournal journal(stage / journal_file_name, config);
  folder.keep_staging_on_failure();  // the journal is what --resume takes over
  std::vector<ObjectRecords> earlier;
  for (const JournalEntry& e : resumed) {
    journal.append(e);
    cli.experiment.skip.emplace_back(e.object, e.id);
    auto o = std::find_if(earlier.begin(), earlier.end(),
                          [&](const ObjectRecords& r) { return r.name == e.object; });
    if (o == earlier.end()) o = earlier.insert(earlier.end(), ObjectRecords{e.object, 0, {}});
    ++o->hypotheses;
    o->grasps.insert(o->grasps.end(), e.records.begin(), e.records.end());
  }
  started = true;
  if (cli.resume)
    progress(std::to_string(resumed.size()) + " hypotheses taken over from an interrupted run");
  // Each finished hypothesis: its scenes, then its line in the journal.
  const HypothesisDoneFnOf<M> on_done = [&](const GraspObject& object, const HumanGrasp& g,
                                            const std::vector<HandTransfer<M>>& transfers) {
    write_scenes<M>(stage, cli.experiment, object, g, transfers);
    std::vector<const HandTransfer<M>*> ts;
    for (const HandTransfer<M>& t : transfers) ts.push_back(&t);
    journal.append({object.name, g.id, hypothesis_records(cli.experiment, object, g, ts)});
  };
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<ObjectResultOf<M>> results =
      run_experiment<M>(cli.experiment, progress, on_done, second);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Json doc = results_json(cli.experiment, results, earlier);
  detail::write_text_file(stage / "results.json", doc.dump(2) + "\n");
  if (cli.figures) (void)write_report<M>(stage, results, 3, cli.experiment.sources);
  committing = true;
  folder.commit();
  print_table(doc);
  std::printf("\n%.1f s with %d job(s); results in %s%s\n", seconds, cli.experiment.jobs,
              (cli.out / "results.json").string().c_str(),
              cli.figures ? (", figures in " + (cli.out / "index.html").string()).c_str() : "");
  return 0;
}

/// A hand of the program: the name --hand takes, its model's name, and its run_hand.
struct HandProgram {
  std::string_view name;
  std::string_view model;
  int (*run)(CommandLine&, bool&, bool&) = nullptr;
};

/// The program's hands, as registered (TOPOGRASP_HAND_PROGRAM), "sdh" first, the rest by name.
[[nodiscard]] inline std::vector<HandProgram>& hand_programs() {
  static std::vector<HandProgram> hands;
  return hands;
}

/// Registers hand model M as the program's hand \p name; called while the program starts, by
/// TOPOGRASP_HAND_PROGRAM.
template <const auto& M>
bool register_hand_program(std::string_view name) {
  std::vector<HandProgram>& hands = hand_programs();
  hands.push_back({name, M.name.view(), &run_hand<M>});
  std::sort(hands.begin(), hands.end(), [](const HandProgram& a, const HandProgram& b) {
    return std::pair{a.name != "sdh", a.name} < std::pair{b.name != "sdh", b.name};
  });
  return true;
}

}  // namespace topograsp::app

/// Makes hand model \p model (a constant reference, e.g. topograsp::models::allegro_hand) a hand
/// of the program under the name \p name ("allegro"): one use per translation unit.
#define TOPOGRASP_HAND_PROGRAM(name, model)                       \
  namespace {                                                     \
  [[maybe_unused]] const bool topograsp_hand_program_registered = \
      ::topograsp::app::register_hand_program<model>(name);       \
  }

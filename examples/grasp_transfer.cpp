// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer: the paper's experiment. Generates the human grasps on the objects, keeps the
// stable ones, transfers them to the Schunk SDH with each method, tests every result, and prints
// the paper's Table I beside its own; writes DIR/results.json and DIR/scenes/*.xml (MJCF), and
// with --figures DIR/figures/*.svg and DIR/index.html, through a staging folder committed at the
// end (io/output_folder.hpp). The command line is parse_command_line (io/command_line.hpp).
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/grasp/experiment.hpp>
#include <topograsp/io/command_line.hpp>
#include <topograsp/io/output_folder.hpp>
#include <topograsp/io/report.hpp>
#include <topograsp/io/results.hpp>
#ifdef TOPOGRASP_HAVE_MUJOCO
#include <topograsp/io/mujoco_scene.hpp>
#endif

namespace {

using namespace topograsp;

std::string percent(const MethodSummary* m) {
  if (m == nullptr || m->tested == 0) return "-";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.0f%%", 100.0 * m->rate());
  return buf;
}

// The paper's Table I next to ours, one column per object.
void print_table(const ExperimentOptions& experiment, const std::vector<ObjectResult>& results) {
  const auto find = [&](const ObjectResult& r, TransferMethod m) -> const MethodSummary* {
    for (const MethodSummary& s : r.methods)
      if (s.method == m) return &s;
    return nullptr;
  };
  const auto paper = [](const std::string& object, int row) -> std::string {
    // Table I of the paper: hammer, bottle; rows: grasps, stable, autoclose, topological.
    if (object == "hammer")
      return std::array<const char*, 4>{"101", "67", "13%", "53%"}[static_cast<std::size_t>(row)];
    if (object == "bottle")
      return std::array<const char*, 4>{"151", "32", "25%", "63%"}[static_cast<std::size_t>(row)];
    return "-";
  };
  std::printf("\n%-40s", "TABLE I (paper | topograsp)");
  for (const ObjectResult& r : results) std::printf(" %20s", r.object.name.c_str());
  std::printf("\n");
  const auto row = [&](const char* label, int paper_row, const auto& ours) {
    std::printf("%-40s", label);
    for (const ObjectResult& r : results) {
      const std::string cell =
          (paper_row >= 0 ? paper(r.object.name, paper_row) : "-") + " | " + ours(r);
      std::printf(" %20s", cell.c_str());
    }
    std::printf("\n");
  };
  row("Total number of grasps", 0,
      [](const ObjectResult& r) { return std::to_string(r.hypotheses); });
  row("Stable grasps", 1, [](const ObjectResult& r) { return std::to_string(r.stable_human()); });
  for (const TransferMethod m : experiment.methods) {
    const int paper_row = m == TransferMethod::transplant    ? 2
                          : m == TransferMethod::topological ? 3
                                                             : -1;
    const char* label = m == TransferMethod::transplant    ? "Autoclose (transplant)"
                        : m == TransferMethod::topological ? "Topological synergies"
                                                           : "Fingertip mapping";
    row(label, paper_row, [&](const ObjectResult& r) { return percent(find(r, m)); });
  }
}

}  // namespace

int main(int argc, char** argv) {
#ifdef SIGXFSZ
  // Past a file-size limit a write fails with EFBIG (a readable error, the previous run in DIR
  // untouched) instead of the signal ending the process.
  (void)std::signal(SIGXFSZ, SIG_IGN);
#endif
  bool started = false;     // exit status 2 before the computation starts, 1 after
  bool committing = false;  // the output folder's commit has started
  try {
    const std::vector<std::string_view> args(argv + 1, argv + argc);
#ifdef TOPOGRASP_HAVE_MUJOCO
    constexpr bool mujoco_linked = true;
#else
    constexpr bool mujoco_linked = false;
#endif
    CommandLine cli = parse_command_line(args, mujoco_linked);
    if (cli.help) {
      std::fputs(command_line_usage().c_str(), stdout);
      return 0;
    }
#ifdef TOPOGRASP_HAVE_MUJOCO
    if (cli.experiment.judge != Judge::builtin) {
      // MuJoCo judges each closed grasp with the same suite: the scene exported articulated
      // (io/mjcf.hpp) and stepped through MujocoScene.
      GraspSimOptions& sim = cli.experiment.transfer.sim;
      sim.second_judge_human = [](const HandScene<models::human_hand>& scene,
                                  const StabilityOptions& o) {
        return stability_suite(MujocoScene(scene), o);
      };
      sim.second_judge_sdh = [](const HandScene<models::schunk_sdh>& scene,
                                const StabilityOptions& o) {
        return stability_suite(MujocoScene(scene), o);
      };
      sim.second_judge_name = cli.experiment.judge == Judge::mujoco ? "builtin" : "mujoco";
      sim.second_judge_decides = cli.experiment.judge == Judge::mujoco;
    }
#endif
    validate_experiment_options(cli.experiment);
    check_scene_names(cli.experiment);
    OutputFolder folder(cli.out, cli.force, "--out");  // checked before any work
    started = true;
    const auto t0 = std::chrono::steady_clock::now();
    const ProgressFn progress = [quiet = cli.quiet](std::string_view line) {
      if (!quiet || line.starts_with("warning:")) std::cerr << line << '\n';
    };
    const std::vector<ObjectResult> results = run_experiment(cli.experiment, progress);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // Everything into the staging folder: the scenes of every tested grasp, results.json, the
    // figures; then the commit puts them in place, results.json last.
    const std::filesystem::path& stage = folder.staging();
    std::filesystem::create_directories(stage / "scenes");
    for (const ObjectResult& r : results) {
      for (const HumanGrasp& g : r.human)
        if (g.reached)
          detail::write_text_file(
              stage / scene_path(r.object.name, g.id, "human"),
              grasp_mjcf<models::human_hand>(r.object, g.hand_pose, g.q, g.object_pose,
                                             cli.experiment.transfer));
      for (std::size_t m = 0; m < r.transfers.size(); ++m)
        for (std::size_t k = 0; k < r.transfers[m].size(); ++k) {
          const RobotGrasp& t = r.transfers[m][k];
          if (!t.planned) continue;
          detail::write_text_file(
              stage / scene_path(r.object.name, r.transferred_ids[k], to_string(t.method)),
              grasp_mjcf<models::schunk_sdh>(r.object, t.hand_pose, t.q_closed, t.object_pose,
                                             cli.experiment.transfer));
        }
    }
    detail::write_text_file(stage / "results.json",
                            results_json(cli.experiment, results).dump(2) + "\n");
    if (cli.figures) (void)write_report(stage, results);
    committing = true;
    folder.commit();
    print_table(cli.experiment, results);
    std::printf("\n%.1f s with %d job(s); results in %s%s\n", seconds, cli.experiment.jobs,
                (cli.out / "results.json").string().c_str(),
                cli.figures ? (", figures in " + (cli.out / "index.html").string()).c_str() : "");
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "grasp_transfer: " << e.what() << '\n';
    if (committing)
      std::cerr << "grasp_transfer: the commit failed part way; the output folder has no "
                   "results.json, and the new run is in the staging folder named above\n";
    else if (started)
      std::cerr << "grasp_transfer: the previous run in the output folder is untouched\n";
    return started ? 1 : 2;
  }
}

// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer: the paper's experiment. Generates the human grasps on the objects, keeps the
// stable ones, transfers them to the Schunk SDH with each method, tests every result, and prints
// the paper's Table I beside its own; writes DIR/results.json and DIR/scenes/*.xml (MJCF), and
// with --figures DIR/figures/*.svg and DIR/index.html, through a staging folder committed at the
// end (io/output_folder.hpp). The command line is parse_command_line (io/command_line.hpp).
#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/evaluation/statistics.hpp>
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

// "62% [36, 82]": a rate with its 95 % Wilson interval, in percent.
std::string percent(int stable, int tested) {
  if (tested == 0) return "-";
  const RateInterval i = wilson_interval(stable, tested);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.0f%% [%.0f, %.0f]", 100.0 * stable / tested, 100.0 * i.lower,
                100.0 * i.upper);
  return buf;
}

// The stable count of method m on r by the deciding engine or the second judge.
int stable_count(const ObjectResult& r, std::size_t m, bool second) {
  const std::vector<bool> v = method_outcomes(r, m, second);
  return static_cast<int>(std::count(v.begin(), v.end(), true));
}

// The paper's Table I next to ours, one column per object; with a second judge its rates too;
// then each method against the topological one on the same grasps (McNemar's exact test).
void print_table(const ExperimentOptions& experiment, const std::vector<ObjectResult>& results) {
  const auto paper = [](const std::string& object, int row) -> std::string {
    // Table I of the paper: hammer, bottle; rows: grasps, stable, autoclose, topological.
    if (object == "hammer")
      return std::array<const char*, 4>{"101", "67", "13%", "53%"}[static_cast<std::size_t>(row)];
    if (object == "bottle")
      return std::array<const char*, 4>{"151", "32", "25%", "63%"}[static_cast<std::size_t>(row)];
    return "-";
  };
  const auto label = [](TransferMethod m) {
    return m == TransferMethod::transplant    ? "Autoclose (transplant)"
           : m == TransferMethod::topological ? "Topological synergies"
                                              : "Fingertip mapping";
  };
  const auto header = [&](const char* title) {
    std::printf("\n%-34s", title);
    for (const ObjectResult& r : results) std::printf(" %26s", r.object.name.c_str());
    std::printf("\n");
  };
  const auto row = [&](const std::string& text, const auto& cell) {
    std::printf("%-34s", text.c_str());
    for (const ObjectResult& r : results) std::printf(" %26s", cell(r).c_str());
    std::printf("\n");
  };
  const bool second = experiment.judge != Judge::builtin;
  const std::string first_name(second && experiment.judge == Judge::mujoco ? "MuJoCo" : "built-in");
  header(("TABLE I (paper | " + first_name + ", 95% CI)").c_str());
  row("Total number of grasps", [&](const ObjectResult& r) {
    return paper(r.object.name, 0) + " | " + std::to_string(r.hypotheses);
  });
  row("Stable grasps", [&](const ObjectResult& r) {
    return paper(r.object.name, 1) + " | " + std::to_string(r.stable_human());
  });
  for (std::size_t m = 0; m < experiment.methods.size(); ++m) {
    const TransferMethod method = experiment.methods[m];
    const int paper_row = method == TransferMethod::transplant    ? 2
                          : method == TransferMethod::topological ? 3
                                                                  : -1;
    row(label(method), [&](const ObjectResult& r) {
      return (paper_row >= 0 ? paper(r.object.name, paper_row) : "-") + " | " +
             percent(stable_count(r, m, false), r.methods[m].tested);
    });
  }
  if (second) {
    const std::string second_name(experiment.judge == Judge::mujoco ? "built-in" : "MuJoCo");
    header(("The same grasps judged by " + second_name + " (95% CI)").c_str());
    row("Stable grasps", [&](const ObjectResult& r) {
      int n = 0;
      for (const HumanGrasp& g : r.human) n += g.second && g.second->stable ? 1 : 0;
      return std::to_string(n);
    });
    for (std::size_t m = 0; m < experiment.methods.size(); ++m)
      row(label(experiment.methods[m]), [&](const ObjectResult& r) {
        return percent(stable_count(r, m, true), r.methods[m].tested);
      });
  }
  const auto topological =
      std::find(experiment.methods.begin(), experiment.methods.end(), TransferMethod::topological);
  if (topological == experiment.methods.end() || experiment.methods.size() < 2) return;
  const std::size_t t = static_cast<std::size_t>(topological - experiment.methods.begin());
  header("Against topological, same grasps:");
  std::printf("(held by this method only | by topological only, McNemar's exact p)\n");
  for (std::size_t m = 0; m < experiment.methods.size(); ++m) {
    if (m == t) continue;
    for (const bool by_second : {false, true}) {
      if (by_second && !second) continue;
      const std::string engine =
          !second ? ""
                  : (by_second == (experiment.judge == Judge::mujoco) ? ", built-in" : ", MuJoCo");
      row(label(experiment.methods[m]) + engine, [&](const ObjectResult& r) {
        const PairedComparison c =
            compare_paired(method_outcomes(r, m, by_second), method_outcomes(r, t, by_second));
        char buf[48];
        std::snprintf(buf, sizeof buf, "%d | %d, p = %.2g", c.only_first, c.only_second, c.p_value);
        return std::string(buf);
      });
    }
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

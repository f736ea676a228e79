// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer: the paper's experiment. Generates the human grasps on the objects, keeps the
// stable ones, transfers them to the Schunk SDH with each method, tests every result, and prints
// the paper's Table I beside its own; writes DIR/results.json and DIR/scenes/*.xml (MJCF).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <topograsp/grasp/experiment.hpp>
#include <topograsp/io/command_line.hpp>
#include <topograsp/io/report.hpp>
#include <topograsp/io/results.hpp>

namespace {

using namespace topograsp;

// Creates DIR/scenes and checks that DIR is writable, before any work is done.
void prepare_output(const std::filesystem::path& out) {
  std::error_code ec;
  std::filesystem::create_directories(out / "scenes", ec);
  const std::filesystem::path probe = out / ".write_test";
  std::ofstream f(probe);
  if (ec || !f) throw std::runtime_error("--out: cannot write to \"" + out.string() + "\"");
  f.close();
  std::filesystem::remove(probe, ec);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  if (!f) throw std::runtime_error("cannot write \"" + path.string() + "\"");
}

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
  try {
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    const CommandLine cli = parse_command_line(args);
    if (cli.help) {
      std::fputs(command_line_usage().c_str(), stdout);
      return 0;
    }
    prepare_output(cli.out);
    const auto t0 = std::chrono::steady_clock::now();
    ProgressFn progress;
    if (!cli.quiet) progress = [](std::string_view line) { std::cerr << line << '\n'; };
    const std::vector<ObjectResult> results = run_experiment(cli.experiment, progress);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // Scenes of every tested grasp, then results.json.
    for (const ObjectResult& r : results) {
      for (const HumanGrasp& g : r.human)
        if (g.reached)
          write_text(cli.out / scene_path(r.object.name, g.id, "human"),
                     grasp_mjcf<models::human_hand>(r.object, g.hand_pose, g.q, g.object_pose,
                                                    cli.experiment.transfer));
      for (std::size_t m = 0; m < r.transfers.size(); ++m)
        for (std::size_t k = 0; k < r.transfers[m].size(); ++k) {
          const RobotGrasp& t = r.transfers[m][k];
          if (!t.planned) continue;
          write_text(cli.out / scene_path(r.object.name, r.transferred_ids[k], to_string(t.method)),
                     grasp_mjcf<models::schunk_sdh>(r.object, t.hand_pose, t.q_closed,
                                                    t.object_pose, cli.experiment.transfer));
        }
    }
    write_text(cli.out / "results.json", results_json(cli.experiment, results).dump(2) + "\n");
    if (cli.figures) (void)write_report(cli.out, results);
    print_table(cli.experiment, results);
    std::printf("\n%.1f s with %d job(s); results in %s%s\n", seconds, cli.experiment.jobs,
                (cli.out / "results.json").string().c_str(),
                cli.figures ? (", figures in " + (cli.out / "index.html").string()).c_str() : "");
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "grasp_transfer: " << e.what() << '\n';
    return 2;
  }
}

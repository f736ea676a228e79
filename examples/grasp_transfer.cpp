// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer: the paper's experiment. Generates the human grasps on the objects, keeps the
// stable ones, transfers them to the Schunk SDH with each method, tests every result, and prints
// the paper's Table I beside its own; writes DIR/results.json and DIR/scenes/*.xml (MJCF).
#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <topograsp/grasp/experiment.hpp>
#include <topograsp/io/report.hpp>
#include <topograsp/io/results.hpp>

namespace {

using namespace topograsp;

constexpr const char* k_usage = R"(usage: grasp_transfer [options]

Transfers stable human grasps to the Schunk SDH (on a 7-DOF arm) and tests every result in
simulation, as in "Topological Synergies for Grasp Transfer" (Table I).

options:
  --objects LIST   comma-separated objects (default hammer,bottle; also mug, box, ball, can)
  --methods LIST   comma-separated methods (default topological,transplant,fingertip)
  --out DIR        write DIR/results.json and DIR/scenes/*.xml (default grasp_transfer_out)
  --jobs N         worker threads (default 1)
  --seed S         seed of the shake tests (default 1); same seed, same results
  --shard K/N      run only hypotheses with id % N == K - 1 (1 <= K <= N), for job arrays
  --max-hypotheses M  only the first M hypotheses of each object (default all)
  --winding-reference R  where the windings are taken: centre_of_mass (default, the paper)
                   or nearest_point (the object's point nearest the human's grasp centre)
  --set NAME=VALUE  set a transfer parameter (repeatable; the names and defaults are listed
                   below, their meaning in docs/transfer.md), e.g. --set final_approach=0.1
  --figures        also write DIR/figures/*.svg and DIR/index.html (Fig. 5-7, Table I)
  --quiet          no progress on stderr
  --help           this text
)";

struct Cli {
  ExperimentOptions experiment;
  std::filesystem::path out = "grasp_transfer_out";
  bool quiet = false;
  bool figures = false;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> parts;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) parts.push_back(item);
  return parts;
}

template <class T>
T parse_number(const std::string& text, const char* option) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size())
    throw std::invalid_argument(std::string(option) + ": expected a number, got \"" + text + "\"");
  return value;
}

Cli parse(int argc, char** argv) {
  Cli cli;
  std::vector<std::string> objects{"hammer", "bottle"};
  std::vector<std::string> methods{"topological", "transplant", "fingertip"};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + ": expected a value");
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      std::fputs(k_usage, stdout);
      std::printf("\ntransfer parameters (default):\n");
      const TransferOptions defaults;
      for (const auto& [name, field] : transfer_parameters)
        std::printf("  %-24s %g\n", std::string(name).c_str(), defaults.*field);
      std::exit(0);
    } else if (arg == "--objects") {
      objects = split(value());
    } else if (arg == "--methods") {
      methods = split(value());
    } else if (arg == "--out") {
      cli.out = value();
    } else if (arg == "--jobs") {
      cli.experiment.jobs = parse_number<int>(value(), "--jobs");
      if (cli.experiment.jobs < 1) throw std::invalid_argument("--jobs: expected at least 1");
    } else if (arg == "--seed") {
      cli.experiment.seed = parse_number<std::uint64_t>(value(), "--seed");
    } else if (arg == "--max-hypotheses") {
      cli.experiment.max_hypotheses = parse_number<int>(value(), "--max-hypotheses");
    } else if (arg == "--shard") {
      const std::string s = value();
      const auto slash = s.find('/');
      if (slash == std::string::npos)
        throw std::invalid_argument("--shard: expected K/N, got \"" + s + "\"");
      const int k = parse_number<int>(s.substr(0, slash), "--shard");
      const int n = parse_number<int>(s.substr(slash + 1), "--shard");
      if (n < 1 || k < 1 || k > n)
        throw std::invalid_argument("--shard: expected 1 <= K <= N, got \"" + s + "\"");
      cli.experiment.shard_index = k - 1;
      cli.experiment.shard_count = n;
    } else if (arg == "--winding-reference") {
      cli.experiment.transfer.winding_reference = winding_reference(value());
    } else if (arg == "--set") {
      const std::string s = value();
      const auto eq = s.find('=');
      if (eq == std::string::npos)
        throw std::invalid_argument("--set: expected NAME=VALUE, got \"" + s + "\"");
      set_transfer_parameter(cli.experiment.transfer, s.substr(0, eq),
                             parse_number<double>(s.substr(eq + 1), "--set"));
    } else if (arg == "--figures") {
      cli.figures = true;
    } else if (arg == "--quiet") {
      cli.quiet = true;
    } else {
      throw std::invalid_argument("unknown option \"" + arg + "\" (see --help)");
    }
  }
  if (objects.empty()) throw std::invalid_argument("--objects: expected at least one object");
  if (methods.empty()) throw std::invalid_argument("--methods: expected at least one method");
  for (const std::string& name : objects) {
    const auto o = objects::find(name);
    if (!o) throw std::invalid_argument("--objects: unknown object \"" + name + "\"");
    cli.experiment.objects.push_back(*o);
  }
  for (const std::string& name : methods) cli.experiment.methods.push_back(transfer_method(name));
  return cli;
}

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
    const Cli cli = parse(argc, argv);
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

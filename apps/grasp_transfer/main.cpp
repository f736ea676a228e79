// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer: the paper's experiment. Generates the human grasps on the objects, keeps the
// stable ones, transfers them to a robot hand (--hand; the Schunk SDH by default) with each
// method, tests every result, and prints the paper's Table I beside its own; writes
// DIR/results.json and DIR/scenes/*.xml (MJCF), and with --figures DIR/figures/*.svg and
// DIR/index.html, through a staging folder committed at the end
// (apps/grasp_transfer/output_folder.hpp). The command line is parse_command_line
// (apps/grasp_transfer/command_line.hpp); each hand's run is compiled apart (program.hpp), and
// grasp_transfer runs the program of a hand it does not hold, grasp_transfer-<hand> beside it.
#include <spawn.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <grasp_transfer/hands_table.hpp>
#include <grasp_transfer/program.hpp>

namespace topograsp::app {

namespace {

// "62% [36, 82]": a rate with its 95 % Wilson interval, in percent.
std::string percent(const Json& stable, const Json& tested, const Json& interval) {
  if (tested.as_number() == 0.0) return "-";
  const auto& i = interval.as_array();
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.0f%% [%.0f, %.0f]",
                100.0 * stable.as_number() / tested.as_number(), 100.0 * i[0].as_number(),
                100.0 * i[1].as_number());
  return buf;
}

}  // namespace

// One column per object (and one over all objects), from results.json's summaries.
void print_table(const Json& doc) {
  const Json& config = doc.at("config");
  // One column per object, then one over every object when there are several.
  std::vector<const Json*> objects;
  for (const Json& o : doc.at("objects").as_array()) objects.push_back(&o);
  if (objects.size() > 1 && doc.contains("overall")) objects.push_back(&doc.at("overall"));
  // The paper's numbers are the SDH's, transferred from the human hand.
  const bool paper_hand =
      config.at("hand").as_string() == models::schunk_sdh.name.view() && !config.contains("source");
  const auto paper = [paper_hand](const std::string& object, int row) -> std::string {
    // Table I of the paper: hammer, bottle; rows: grasps, stable, autoclose, topological.
    if (!paper_hand) return "-";
    if (object == "hammer")
      return std::array<const char*, 4>{"101", "67", "13%", "53%"}[static_cast<std::size_t>(row)];
    if (object == "bottle")
      return std::array<const char*, 4>{"151", "32", "25%", "63%"}[static_cast<std::size_t>(row)];
    return "-";
  };
  const auto label = [](const std::string& m) -> std::string {
    return m == "autoclose"           ? "Autoclose (the paper's baseline)"
           : m == "transplant"        ? "Transplant (fair, opened)"
           : m == "topological"       ? "Topological synergies"
           : m == "fingertip"         ? "Fingertip mapping"
           : m == "virtual_finger"    ? "Virtual-finger mapping"
           : m == "paper"             ? "Topological, as in the paper"
           : m == "paper_line"        ? "  paper + line task"
           : m == "paper_approach"    ? "  paper + final approach"
           : m == "no_windings"       ? "  topological, no windings"
           : m == "nearest_point"     ? "  topological, nearest point"
           : m == "closed_windings"   ? "  topological, closed windings"
           : m == "no_plan"           ? "  control: no plan"
           : m == "shuffled_windings" ? "  control: shuffled windings"
                                      : m;
  };
  const auto header = [&](const std::string& title) {
    std::printf("\n%-44s", title.c_str());
    for (const Json* o : objects) std::printf(" %26s", o->at("name").as_string().c_str());
    std::printf("\n");
  };
  const auto row = [&](const std::string& text, const auto& cell) {
    std::printf("%-44s", text.c_str());
    for (const Json* o : objects) std::printf(" %26s", cell(*o).c_str());
    std::printf("\n");
  };
  const std::string judge = config.at("judge").as_string();
  const bool second = judge != "builtin";
  const std::string first_name = judge == "mujoco" ? "MuJoCo" : "built-in";
  const std::string second_name = judge == "mujoco" ? "built-in" : "MuJoCo";
  std::vector<std::string> methods;
  for (const Json& m : config.at("methods").as_array()) methods.push_back(m.as_string());
  const auto summary = [](const Json& o, const std::string& m) -> const Json& {
    return o.at("methods").at(m);
  };
  header("TABLE I (paper | " + first_name + ", 95% CI)");
  row("Total number of grasps", [&](const Json& o) {
    return paper(o.at("name").as_string(), 0) + " | " + o.at("hypotheses").dump(0);
  });
  row("Stable grasps", [&](const Json& o) {
    return paper(o.at("name").as_string(), 1) + " | " + o.at("stable_human").dump(0);
  });
  row("  distinct (up to symmetry)",
      [&](const Json& o) { return "- | " + o.at("distinct_human").dump(0); });
  if (second)
    row("  stable in both engines (distinct)", [&](const Json& o) {
      const Json& d = o.at("demonstrations");
      return "- | " + d.at("stable_both").dump(0) + " (" + d.at("distinct_both").dump(0) + ")";
    });
  row("  object's median motion while closing", [&](const Json& o) {
    const Json& m = o.at("demonstrations").at("median_object_shift");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f mm", m.is_null() ? 0.0 : 1000.0 * m.as_number());
    return "- | " + (m.is_null() ? std::string("-") : std::string(buf));
  });
  for (const std::string& m : methods) {
    const int paper_row = m == "autoclose" ? 2 : m == "topological" || m == "paper" ? 3 : -1;
    row(label(m), [&](const Json& o) {
      const Json& s = summary(o, m);
      return (paper_row >= 0 ? paper(o.at("name").as_string(), paper_row) : "-") + " | " +
             percent(s.at("stable"), s.at("tested"), s.at("interval"));
    });
  }
  if (second) {
    header("The same grasps judged by " + second_name + " (95% CI)");
    row("Stable grasps", [&](const Json& o) {
      const Json& j = o.at("human").at("second_judge");
      return j.is_null() ? std::string("-") : j.at("stable_second").dump(0);
    });
    for (const std::string& m : methods)
      row(label(m), [&](const Json& o) {
        const Json& s = summary(o, m);
        const Json& j = s.at("second_judge");
        return j.is_null()
                   ? std::string("-")
                   : percent(j.at("stable_second"), s.at("tested"), j.at("interval_second"));
      });
  }
  header("One demonstration per distinct grasp (" + first_name +
         (second ? " | " + second_name : std::string()) + ")");
  for (const std::string& m : methods)
    row(label(m), [&](const Json& o) {
      const Json& d = summary(o, m).at("distinct");
      std::string text = percent(d.at("stable"), d.at("tested"), d.at("interval"));
      if (second && !d.at("stable_second").is_null()) text += " | " + d.at("stable_second").dump(0);
      return text;
    });
  if (std::find(methods.begin(), methods.end(), "topological") == methods.end() ||
      methods.size() < 2)
    return;
  header("Against topological, same grasps:");
  std::printf(
      "(held by this method only | by topological only, McNemar's exact p, the test's "
      "power to tell 15 points apart)\n");
  for (const std::string& m : methods) {
    if (m == "topological") continue;
    for (const char* key :
         {"paired", "paired_second", "paired_distinct", "paired_distinct_second"}) {
      const std::string_view k = key;
      if (k.ends_with("_second") && !second) continue;
      const std::string engine =
          (!second ? std::string() : ", " + (k.ends_with("_second") ? second_name : first_name)) +
          (k.starts_with("paired_distinct") ? ", distinct" : "");
      row(label(m) + engine, [&](const Json& o) {
        const Json& c = summary(o, m).at(key);
        if (c.is_null()) return std::string("-");
        char buf[48];
        std::snprintf(buf, sizeof buf, "%s | %s, p %.2g, power %.2f",
                      c.at("only_this").dump(0).c_str(), c.at("only_against").dump(0).c_str(),
                      c.at("p_value").as_number(), c.at("power_15").as_number());
        return std::string(buf);
      });
    }
  }
}

void copy_scenes(const std::vector<Json>& records, const std::filesystem::path& from,
                 const std::filesystem::path& to) {
  namespace fs = std::filesystem;
  fs::create_directories(to / "scenes");
  for (const Json& r : records) {
    if (!r.at("scene").is_string()) continue;
    const std::string& scene = r.at("scene").as_string();
    std::error_code ec;
    fs::copy_file(from / scene, to / scene, fs::copy_options::overwrite_existing, ec);
    if (ec)
      throw invalid_argument("cannot copy \"" + (from / scene).string() + "\" (" + ec.message() +
                             ")");
  }
}

}  // namespace topograsp::app

namespace {

using namespace topograsp;
using namespace topograsp::app;

// The text of the file at path, or an error naming what.
std::string read_file(const std::filesystem::path& path, const std::string& what) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw invalid_argument(what + ": cannot read \"" + path.string() + "\"");
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// The --hands table of the folder dir: each hand's results.json read, hands.json and hands.md
// written (each whole or not at all), the table printed.
void write_hands_table(const std::filesystem::path& dir, const std::vector<std::string>& hands) {
  std::vector<HandRun> runs;
  for (const std::string& h : hands) {
    const std::string results = h + "/results.json";
    runs.push_back({h, results, Json::parse(read_file(dir / results, "--hands"))});
  }
  const Json summary = hands_summary(runs);
  const std::string table = hands_markdown(summary);
  detail::write_text_file(dir / "hands.json", summary.dump(2) + "\n");
  detail::write_text_file(dir / "hands.md", table);
  std::printf("\n%s\nevery hand's table in %s\n", table.c_str(),
              (dir / "hands.md").string().c_str());
}

// The names of the hands of a --hands run's folder (its hands.json), or none.
std::vector<std::string> hands_of(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  if (!std::filesystem::is_regular_file(dir / "hands.json")) return out;
  const Json doc = Json::parse(read_file(dir / "hands.json", "merge"));
  if (!doc.contains("hands") || !doc.at("hands").is_array())
    throw invalid_argument("merge: \"" + (dir / "hands.json").string() +
                           "\" is not the table of a grasp_transfer --hands run");
  for (const Json& h : doc.at("hands").as_array()) out.push_back(h.at("hand").as_string());
  return out;
}

int merge(const CommandLine& cli, bool& started, bool& committing);

// grasp_transfer merge of the shards of a --hands run: each hand's shards merged into DIR/<hand>,
// then the table of every hand. The shards must hold the same hands.
int merge_hands(const CommandLine& cli, const std::vector<std::string>& hands, bool& started,
                bool& committing) {
  for (const std::filesystem::path& dir : cli.shards)
    if (hands_of(dir) != hands)
      throw invalid_argument("merge: \"" + dir.string() + "\" holds other hands than \"" +
                             cli.shards.front().string() + "\" (each hands.json names them)");
  std::error_code ec;
  if (std::filesystem::create_directories(cli.out, ec); ec)
    throw invalid_argument("--out: cannot create \"" + cli.out.string() + "\" (" + ec.message() +
                           ")");
  for (const std::string& h : hands) {
    CommandLine one = cli;
    one.out = cli.out / h;
    for (std::filesystem::path& dir : one.shards) dir /= h;
    if (!cli.quiet) std::printf("== %s\n", h.c_str());
    (void)merge(one, started, committing);
    committing = false;
  }
  write_hands_table(cli.out, hands);
  return 0;
}

// grasp_transfer merge: the shards' results.json and scenes into one output folder.
int merge(const CommandLine& cli, bool& started, bool& committing) {
  if (const std::vector<std::string> hands = hands_of(cli.shards.front()); !hands.empty())
    return merge_hands(cli, hands, started, committing);
  OutputFolder folder(cli.out, cli.force, "--out");
  std::vector<Json> docs;
  for (const std::filesystem::path& dir : cli.shards) {
    if (!is_grasp_transfer_results(dir / "results.json"))
      throw invalid_argument("merge: \"" + dir.string() +
                             "\" holds no results.json of grasp_transfer");
    docs.push_back(Json::parse(read_file(dir / "results.json", "merge")));
  }
  const Json doc = merge_results(docs);  // checks the shards: nothing is written before
  started = true;
  for (std::size_t i = 0; i < docs.size(); ++i)
    copy_scenes(docs[i].at("grasps").as_array(), cli.shards[i], folder.staging());
  detail::write_text_file(folder.staging() / "results.json", doc.dump(2) + "\n");
  committing = true;
  folder.commit();
  print_table(doc);
  std::printf("\n%zu shard(s) merged; results in %s\n", docs.size(),
              (cli.out / "results.json").string().c_str());
  return 0;
}

#ifndef TOPOGRASP_SIBLING_HANDS
#define TOPOGRASP_SIBLING_HANDS ""
#endif

// A hand that grasp_transfer runs through another program: grasp_transfer-<name> in the folder
// of grasp_transfer (apps/CMakeLists.txt builds one for every shipped hand but the SDH).
struct SiblingHand {
  std::string name;
  std::filesystem::path program;  // empty: this tree's build has not built it
};

// The sibling hands of this program: none unless it is grasp_transfer itself (a hand program of
// topograsp_add_hand_program holds its one hand); the ones built beside it, and the ones this tree
// builds (TOPOGRASP_SIBLING_HANDS) but has not built yet.
std::vector<SiblingHand> sibling_hands(const char* argv0) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) self = fs::absolute(argv0, ec);
  std::vector<SiblingHand> out;
  if (ec || self.filename() != "grasp_transfer") return out;
  const std::string prefix = "grasp_transfer-";
  for (const fs::directory_entry& e : fs::directory_iterator(self.parent_path(), ec)) {
    const std::string file = e.path().filename().string();
    if (file.size() > prefix.size() && file.starts_with(prefix) && e.is_regular_file(ec) &&
        ::access(e.path().c_str(), X_OK) == 0)
      out.push_back({file.substr(prefix.size()), e.path()});
  }
  std::string_view built_here = TOPOGRASP_SIBLING_HANDS;
  while (!built_here.empty()) {
    const std::string_view name = built_here.substr(0, built_here.find(','));
    built_here.remove_prefix(std::min(built_here.size(), name.size() + 1));
    if (std::none_of(out.begin(), out.end(), [&](const SiblingHand& h) { return h.name == name; }))
      out.push_back({std::string(name), {}});
  }
  std::sort(out.begin(), out.end(),
            [](const SiblingHand& a, const SiblingHand& b) { return a.name < b.name; });
  return out;
}

// The program's hands for --help.
std::string hands_help(const std::vector<SiblingHand>& siblings) {
  const auto line = [](std::string_view name, const std::string& what) {
    return "  " + std::string(name) + std::string(name.size() < 14 ? 14 - name.size() : 1, ' ') +
           what + "\n";
  };
  std::string text = "\nhands of this program (--hand):\n";
  for (const HandProgram& h : hand_programs())
    text += line(h.name,
                 std::string(h.model) + (&h == &hand_programs().front() ? " (the default)" : ""));
  for (const SiblingHand& h : siblings)
    text += line(h.name,
                 h.program.empty()
                     ? "not built: cmake --build --preset release --target grasp_transfer-" + h.name
                     : "run by " + h.program.filename().string());
  return text;
}

// What says that the program of the hand \p name is not built, and how to build it.
std::string not_built(const std::string& name) {
  return "the program of the hand \"" + name + "\", grasp_transfer-" + name +
         ", is not built: cmake --build --preset release --target grasp_transfer-" + name;
}

// Runs the sibling program of \p hand with this program's arguments in place of this process;
// returns only if it cannot: throws naming --hand.
[[noreturn]] void run_sibling(const SiblingHand& hand, char** argv) {
  if (hand.program.empty()) throw invalid_argument("--hand: " + not_built(hand.name));
  std::fflush(stdout);
  ::execv(hand.program.c_str(), argv);
  throw invalid_argument("--hand: cannot run \"" + hand.program.string() + "\" (" +
                         std::error_code(errno, std::generic_category()).message() + ")");
}

// grasp_transfer --hands A,B,...: this program run once for each hand, with the same arguments
// but --hand <hand> and --out DIR/<hand>, one after another (each its own output folder,
// journal and shards); with --resume a hand whose results.json holds a finished run of the same
// options is not run again. Then the table of every hand. A hand's run that fails ends the whole:
// its exit status (1 once an earlier hand has finished), the hands before it kept.
int run_hands(const CommandLine& cli, std::span<const std::string_view> args,
              const std::vector<SiblingHand>& siblings, bool& started) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw invalid_argument("--hands: cannot find this program (/proc/self/exe)");
  if (fs::exists(cli.out) && !fs::is_directory(cli.out))
    throw invalid_argument("--out: \"" + cli.out.string() + "\" exists and is not a folder");
  // What only the SDH runs, refused for the other hands before any of them runs.
  for (const std::string& h : cli.hands) {
    const auto p = std::find_if(hand_programs().begin(), hand_programs().end(),
                                [&](const HandProgram& hp) { return hp.name == h; });
    const bool sdh = p != hand_programs().end() && p->model == models::schunk_sdh.name.view();
    if (sdh) continue;
    for (const TransferMethod m : cli.experiment.methods)
      if (!any_hand_method(m))
        throw invalid_argument("--hands: " + h + ": --methods " + std::string(to_string(m)) +
                               " runs with the SDH on the arm only");
    if (cli.experiment.arm_setting)
      throw invalid_argument("--hands: " + h + ": --setting arm: the arm carries the SDH only");
    if (const auto s = std::find_if(siblings.begin(), siblings.end(),
                                    [&](const SiblingHand& sh) { return sh.name == h; });
        s != siblings.end() && s->program.empty())
      throw invalid_argument("--hands: " + not_built(h));
  }
  if (fs::create_directories(cli.out, ec); ec)
    throw invalid_argument("--out: cannot create \"" + cli.out.string() + "\" (" + ec.message() +
                           ")");
  // The arguments of each hand's run: these but --hands and --out.
  std::vector<std::string> common;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--hands" || args[i] == "--out") {
      ++i;
      continue;
    }
    common.emplace_back(args[i]);
  }
  for (const std::string& h : cli.hands) {
    const fs::path dir = cli.out / h;
    if (cli.resume && fs::is_regular_file(dir / "results.json")) {
      const Json done = Json::parse(read_file(dir / "results.json", "--resume"));
      if (done.contains("config") && done.at("config").contains("hand") &&
          done.at("config").at("hand").is_string() &&
          done.at("config").dump(0) ==
              results_config(cli.experiment, done.at("config").at("hand").as_string()).dump(0)) {
        std::printf("== %s: finished in %s, not run again\n", h.c_str(), dir.string().c_str());
        continue;
      }
    }
    std::vector<std::string> words{self.string()};
    words.insert(words.end(), common.begin(), common.end());
    words.insert(words.end(), {"--hand", h, "--out", dir.string()});
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    if (!cli.quiet) std::printf("== %s\n", h.c_str());
    std::fflush(stdout);
    pid_t pid = 0;
    if (const int e = ::posix_spawn(&pid, self.c_str(), nullptr, nullptr, argv.data(), environ);
        e != 0)
      throw invalid_argument("--hands: cannot run \"" + self.string() + "\" (" +
                             std::error_code(e, std::generic_category()).message() + ")");
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
    if (code != 0) {
      std::fprintf(stderr, "grasp_transfer: --hands: the run of %s failed (exit %d)%s\n", h.c_str(),
                   code, started ? "; the hands before it are finished in their folders" : "");
      return started ? 1 : code;
    }
    started = true;
  }
  started = true;
  write_hands_table(cli.out, cli.hands);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // MuJoCo 2.2 allocates each judged grasp's model and data as large aligned blocks; glibc's
  // heap cannot reuse those between the small allocations around them once its mmap threshold
  // has risen past them, so a run grew by about a megabyte per grasp (docs/transfer.md,
  // "Memory"). A fixed threshold keeps blocks of 1 MiB and more in their own mappings, returned
  // to the system when freed. The program's choice, not the library's: it is process-wide.
  (void)mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
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
    const std::vector<SiblingHand> siblings = sibling_hands(argv[0]);
    std::vector<std::string_view> hands;
    for (const HandProgram& h : hand_programs()) hands.push_back(h.name);
    for (const SiblingHand& h : siblings) hands.push_back(h.name);
    CommandLine cli = parse_command_line(args, mujoco_linked, hands);
    if (cli.help) {
      std::fputs((command_line_usage() + hands_help(siblings)).c_str(), stdout);
      return 0;
    }
    if (cli.merge) return merge(cli, started, committing);
    if (!cli.hands.empty()) return run_hands(cli, args, siblings, started);
    for (const HandProgram& h : hand_programs())
      if (h.name == cli.hand) return h.run(cli, started, committing);
    run_sibling(*std::find_if(siblings.begin(), siblings.end(),
                              [&](const SiblingHand& h) { return h.name == cli.hand; }),
                argv);
  } catch (const std::exception& e) {
    std::cerr << "grasp_transfer: " << e.what() << '\n';
    if (committing)
      std::cerr << "grasp_transfer: the commit failed part way; the output folder keeps the "
                   "previous results.json, and the new run is in the staging folder named "
                   "above: the next run into the folder finishes the commit first\n";
    else if (started)
      std::cerr << "grasp_transfer: the previous run in the output folder is untouched\n";
    return started ? 1 : 2;
  }
}

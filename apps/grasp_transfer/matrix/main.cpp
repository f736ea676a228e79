// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix (issue 15, docs/results.md "Any hand to any hand"): the human demonstrations
// of the paper's experiment transferred to the SDH, the Barrett, the Allegro, the LEAP and the
// Shadow hand on a free base, and two robot -> robot pairs (SDH -> Allegro, Allegro -> Shadow,
// from the stable topological transfers of the same demonstrations), by each method, each grasp
// judged by the built-in stepper and, where MuJoCo is linked, by MuJoCo. The transfers to each
// target hand are compiled in a file of their own (pair.hpp).
//
//   transfer_matrix [--objects hammer,bottle]
//                   [--methods topological,paper,transplant,fingertip,virtual_finger]
//                   [--hypotheses demonstrator|box] [--closing balanced|held|free]
//                   [--human-grip G] [--max-hypotheses N] [--seed S] [--jobs N]
//                   [--out DIR] [--force] [--quiet]
//
// The demonstrations are grasp_transfer's (the same hypotheses, closing protocol and seeds, the
// same defaults): each stable one (built-in) is transferred, and each cell is also counted on one
// demonstration per distinct grasp (grasp_clusters(), the object's symmetry, the default
// tolerance), as grasp_transfer's results count them.
//
// Writes DIR/matrix.json, DIR/matrix.md and the results page DIR/index.html as one: staged in a
// folder inside DIR and committed together, matrix.json last (grasp_transfer's output folder rule,
// output_folder.hpp). Bad arguments or an unusable DIR: a message naming the option on stderr,
// exit status 2, nothing computed.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include <grasp_transfer/command_line.hpp>
#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/output_folder.hpp>
#include <topograsp/evaluation/statistics.hpp>
#include <topograsp/grasp/grasp_identity.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/io/text_file.hpp>
#include <topograsp/render/html_page.hpp>

#include "pair.hpp"

namespace {

using namespace topograsp;
using matrix::Record;

struct Options {
  std::vector<std::string> objects{"hammer", "bottle"};
  std::vector<TransferMethod> methods{TransferMethod::topological, TransferMethod::paper,
                                      TransferMethod::transplant, TransferMethod::fingertip,
                                      TransferMethod::virtual_finger};
  int max_hypotheses = 0;  // 0: all
  std::uint64_t seed = 1;
  HypothesisRule hypotheses = HypothesisRule::demonstrator;  // grasp_transfer's default
  TransferOptions transfer = [] {  // the closing of grasp_transfer's default: balanced
    TransferOptions t;
    detail::set_closing(t.sim, "balanced");
    return t;
  }();
  int jobs = 2;
  std::string out = "matrix";
  bool force = false;
  bool quiet = false;
};

constexpr std::string_view usage =
    "usage: transfer_matrix [--objects hammer,bottle]\n"
    "                       [--methods topological,paper,transplant,fingertip,virtual_finger]\n"
    "                       [--hypotheses demonstrator|box] [--closing balanced|held|free]\n"
    "                       [--human-grip G] [--max-hypotheses N] [--seed S] [--jobs N]\n"
    "                       [--out DIR] [--force] [--quiet]\n"
    "Transfers the stable human demonstrations of grasp_transfer's experiment (its hypotheses,\n"
    "closing and seeds; --hypotheses, --closing and --human-grip as there, default\n"
    "demonstrator, balanced and 5) to the SDH, Barrett, Allegro, LEAP and Shadow hands,\n"
    "and SDH -> Allegro, Allegro -> Shadow, each cell also counted on one demonstration per\n"
    "distinct grasp; writes DIR/matrix.json,\n"
    "DIR/matrix.md and DIR/index.html (default DIR: matrix), staged and committed together;\n"
    "a non-empty DIR without a matrix.json of transfer_matrix is refused unless --force.\n"
    "Methods: every method of the fair experiment but closed_windings (docs/transfer.md,\n"
    "\"Any hand\").\n";

Options parse(std::span<char*> args) {
  Options o;
  std::map<std::string, bool> seen;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view a = args[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage.data(), stdout);
      std::exit(0);
    }
    if (a == "--quiet" || a == "--force") {
      (a == "--quiet" ? o.quiet : o.force) = true;
      continue;
    }
    if (a != "--objects" && a != "--methods" && a != "--max-hypotheses" && a != "--seed" &&
        a != "--jobs" && a != "--out" && a != "--hypotheses" && a != "--closing" &&
        a != "--human-grip")
      throw invalid_argument("unknown option " + detail::quote_argument(a) +
                             " (--help lists them)");
    if (seen[std::string(a)]) detail::throw_invalid_argument(a, "given twice");
    seen[std::string(a)] = true;
    if (i + 1 == args.size() || std::string_view(args[i + 1]).starts_with("--") ||
        std::string_view(args[i + 1]).empty())
      detail::throw_invalid_argument(a, "expected a value");
    const std::string_view v = args[++i];
    if (a == "--objects") {
      o.objects.clear();
      for (const std::string_view n : detail::split_cli_list(v, a, objects::all_names(), "object"))
        o.objects.emplace_back(n);
    } else if (a == "--methods") {
      std::vector<std::string> known;
      for (const TransferMethod m : all_transfer_methods)
        if (any_hand_method(m)) known.emplace_back(to_string(m));
      o.methods.clear();
      for (const std::string_view n : detail::split_cli_list(v, a, known, "method"))
        o.methods.push_back(transfer_method(n));
    } else if (a == "--hypotheses") {
      o.hypotheses = detail::parse_hypothesis_rule(v, a);
    } else if (a == "--closing") {
      detail::parse_closing(v, a, o.transfer.sim);
    } else if (a == "--human-grip") {
      o.transfer.sim.human_max_grip = detail::parse_human_grip(v, a);
    } else if (a == "--max-hypotheses") {
      o.max_hypotheses = detail::parse_cli_number<int>(v, a);
      if (o.max_hypotheses < 0) detail::throw_invalid_argument(a, "expected >= 0");
    } else if (a == "--seed") {
      o.seed = detail::parse_cli_number<std::uint64_t>(v, a);
    } else if (a == "--jobs") {
      o.jobs = detail::parse_cli_number<int>(v, a);
      if (o.jobs < 1 || o.jobs > max_command_line_jobs)
        detail::throw_invalid_argument(a, "expected 1 to " + std::to_string(max_command_line_jobs));
    } else {
      o.out = std::string(v);
    }
  }
  return o;
}

// The verdicts of one cell of the matrix: a source -> target pair, an object, a method.
struct Cell {
  int tested = 0, planned = 0, stable = 0, stable_second = 0;
  // The same on one demonstration per distinct grasp (the first of its cluster).
  int distinct_tested = 0, distinct_stable = 0, distinct_stable_second = 0;
  bool second = false;                  // a second judge ran
  std::map<std::string, int> failures;  // why not stable (built-in), how often
  std::vector<double> winding_errors;   // topological: max |w closed - target|
};
using Key = std::tuple<std::string, std::string, std::string>;  // pair, object, method

// A method against the first method of the run on the same grasps of one pair, both objects:
// [engine: built-in, MuJoCo][raw, one per distinct grasp], the grasps only this method held and
// those only the first method held (McNemar's exact test).
struct Paired {
  int only_this[2][2] = {}, only_first[2][2] = {};
};

// The most frequent failure of a cell and its count ("-" if none).
std::string top_failure(const Cell& c) {
  const auto it =
      std::max_element(c.failures.begin(), c.failures.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  return it == c.failures.end() ? std::string("-")
                                : it->first + " (" + std::to_string(it->second) + ")";
}

// Every transfer of one demonstration: human -> each hand, then the robot -> robot pairs from the
// stable (built-in) transfers of the first method.
std::vector<Record> transfer_all(const GraspObject& object, const HumanGrasp& g, const Options& o,
                                 const TransferOptions& options) {
  using matrix::transfer_pair;
  std::vector<Record> out;
  const SourceGrasp human = describe_source(g);
  const auto& m = o.methods;
  const auto& op = options;
  const auto sdh = transfer_pair<models::schunk_sdh>("human -> SDH", object, human, m, op, out);
  (void)transfer_pair<models::barrett_bh8>("human -> Barrett", object, human, m, op, out);
  const auto allegro =
      transfer_pair<models::allegro_hand>("human -> Allegro", object, human, m, op, out);
  (void)transfer_pair<models::leap_hand>("human -> LEAP", object, human, m, op, out);
  (void)transfer_pair<models::shadow_hand>("human -> Shadow", object, human, m, op, out);
  if (!sdh.empty() && sdh.front().stable())
    (void)transfer_pair<models::allegro_hand>("SDH -> Allegro", object, source_grasp(sdh.front()),
                                              m, op, out);
  if (!allegro.empty() && allegro.front().stable())
    (void)transfer_pair<models::shadow_hand>("Allegro -> Shadow", object,
                                             source_grasp(allegro.front()), m, op, out);
  return out;
}

std::string rate(int k, int n) {
  if (n == 0) return "-";
  const RateInterval ci = wilson_interval(k, n);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%d/%d = %.0f %% [%.0f, %.0f]", k, n, 100.0 * k / n,
                100.0 * ci.lower, 100.0 * ci.upper);
  return buf;
}

Json interval_json(int k, int n) {
  const RateInterval ci = wilson_interval(k, n);
  return Json::array().push_back(ci.lower).push_back(ci.upper);
}

int run(const Options& o, OutputFolder& folder) {
  std::vector<GraspObject> objs;
  for (const std::string& n : o.objects) objs.push_back(*objects::find_any(n));
  std::vector<std::pair<std::size_t, int>> tasks;
  std::vector<std::vector<GraspHypothesis>> hyps;
  for (std::size_t oi = 0; oi < objs.size(); ++oi) {
    hyps.push_back(o.hypotheses == HypothesisRule::demonstrator
                       ? demonstrator_hypotheses(objs[oi], o.seed)
                       : box_hypotheses(objs[oi]));
    for (int i = 0; i < static_cast<int>(hyps.back().size()); ++i)
      if (o.max_hypotheses == 0 || i < o.max_hypotheses) tasks.emplace_back(oi, i);
  }
  const TransferOptions& base = o.transfer;
  std::vector<std::vector<Record>> records(tasks.size());
  std::vector<std::optional<HandGrasp<models::human_hand>>> demonstrated(tasks.size());
  std::mutex say;
  std::atomic<int> done{0};
  detail::parallel_for(static_cast<int>(tasks.size()), o.jobs, [&](int k) {
    const auto [oi, id] = tasks[static_cast<std::size_t>(k)];
    TransferOptions options = base;
    options.sim.stability.seed = grasp_seed(o.seed, objs[oi].name, id);
    const HumanGrasp g =
        demonstrate(objs[oi], hyps[oi][static_cast<std::size_t>(id)], id, options.sim);
    if (g.stable()) {
      // The grasp in the frame of the object where closing left it, as results.json's
      // hand_pose, which grasp_transfer clusters.
      demonstrated[static_cast<std::size_t>(k)] =
          HandGrasp<models::human_hand>{g.object_pose.inverse() * g.hand_pose, g.q};
      records[static_cast<std::size_t>(k)] = transfer_all(objs[oi], g, o, options);
    }
    if (!o.quiet) {
      const std::lock_guard lock(say);
      std::fprintf(stderr, "[%s] hypothesis %d done (%d/%zu)\n", objs[oi].name.c_str(), id, ++done,
                   tasks.size());
    }
  });
  // Which stable demonstrations stand for their grasp: the first of each cluster, per object.
  std::vector<bool> representative(tasks.size());
  int distinct_demos = 0;
  for (std::size_t oi = 0; oi < objs.size(); ++oi) {
    std::vector<std::size_t> ks;
    std::vector<Eigen::Isometry3d> poses;
    std::vector<Vec<20>> joints;
    for (std::size_t k = 0; k < tasks.size(); ++k)
      if (tasks[k].first == oi && demonstrated[k]) {
        ks.push_back(k);
        poses.push_back(demonstrated[k]->root);
        joints.push_back(demonstrated[k]->q);
      }
    const std::vector<int> cluster =
        grasp_clusters<Vec<20>>(poses, joints, object_symmetry(objs[oi]), GraspTolerance{});
    for (std::size_t i = 0; i < ks.size(); ++i)
      if (cluster[i] == static_cast<int>(i)) {
        representative[ks[i]] = true;
        ++distinct_demos;
      }
  }
  std::map<Key, Cell> cells;
  std::vector<Key> order;  // first appearance: pairs in transfer_all's order
  const std::string first = std::string(to_string(o.methods.front()));
  std::map<std::pair<std::string, std::string>, Paired> paired;  // (pair, method)
  std::vector<std::pair<std::string, std::string>> paired_order;
  for (std::size_t k = 0; k < tasks.size(); ++k)
    for (const Record& r : records[k]) {
      if (r.method != first)
        for (const Record& f : records[k])
          if (f.pair == r.pair && f.method == first) {
            const std::pair<std::string, std::string> pm{r.pair, r.method};
            if (!paired.contains(pm)) paired_order.push_back(pm);
            Paired& pr = paired[pm];
            const bool held[2] = {r.stable, r.stable_second},
                       first_held[2] = {f.stable, f.stable_second};
            for (int e = 0; e < 2; ++e)
              for (int v = 0; v < (representative[k] ? 2 : 1); ++v) {
                pr.only_this[e][v] += held[e] && !first_held[e];
                pr.only_first[e][v] += first_held[e] && !held[e];
              }
          }
      const Key key{r.pair, r.object, r.method};
      if (!cells.contains(key)) order.push_back(key);
      Cell& c = cells[key];
      ++c.tested;
      c.planned += r.planned;
      c.stable += r.stable;
      c.stable_second += r.stable_second;
      if (representative[k]) {
        ++c.distinct_tested;
        c.distinct_stable += r.stable;
        c.distinct_stable_second += r.stable_second;
      }
      c.second = c.second || r.second;
      if (!r.failure.empty()) ++c.failures[r.failure];
      if (!std::isnan(r.winding_error)) c.winding_errors.push_back(r.winding_error);
    }
  // Grouped by pair (in transfer_all's order), then objects and methods as they came.
  std::vector<std::string> pairs;
  for (const Key& k : order)
    if (std::find(pairs.begin(), pairs.end(), std::get<0>(k)) == pairs.end())
      pairs.push_back(std::get<0>(k));
  std::stable_sort(order.begin(), order.end(), [&](const Key& a, const Key& b) {
    return std::find(pairs.begin(), pairs.end(), std::get<0>(a)) <
           std::find(pairs.begin(), pairs.end(), std::get<0>(b));
  });
  Json cell_list = Json::array();
  HtmlPage page;
  page.title = "topograsp: the transfer matrix";
  page.header = {"source -> target", "object",
                 "method",           "tested",
                 "planned",          "stable (built-in)",
                 "stable (MuJoCo)",  "distinct grasps: stable (built-in / MuJoCo)",
                 "winding error",    "most frequent failure"};
  std::string md =
      "| source -> target | object | method | tested | planned | stable (built-in) | stable "
      "(MuJoCo) | distinct grasps: stable (built-in / MuJoCo) | winding error | most frequent "
      "failure |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Key& key : order) {
    const Cell& c = cells[key];
    const auto& [pair, object, method] = key;
    std::vector<double> errors = c.winding_errors;
    const double we = median(errors);
    char werr[32] = "-";
    if (!std::isnan(we)) std::snprintf(werr, sizeof werr, "%.2f", we);
    const std::string of = "/" + std::to_string(c.distinct_tested);
    const std::string distinct =
        std::to_string(c.distinct_stable) + of + " / " +
        (c.second ? std::to_string(c.distinct_stable_second) + of : std::string("-"));
    md += "| " + pair + " | " + object + " | " + method + " | " + std::to_string(c.tested) + " | " +
          std::to_string(c.planned) + " | " + rate(c.stable, c.tested) + " | " +
          (c.second ? rate(c.stable_second, c.tested) : std::string("-")) + " | " + distinct +
          " | " + werr + " | " + top_failure(c) + " |\n";
    page.rows.push_back({pair, object, method, std::to_string(c.tested), std::to_string(c.planned),
                         rate(c.stable, c.tested),
                         c.second ? rate(c.stable_second, c.tested) : std::string("-"), distinct,
                         werr, top_failure(c)});
    Json j = Json::object();
    j.set("pair", pair);
    j.set("object", object);
    j.set("method", method);
    j.set("tested", c.tested);
    j.set("planned", c.planned);
    j.set("stable", c.stable);
    j.set("interval", interval_json(c.stable, c.tested));
    Json failures = Json::object();
    for (const auto& [why, n] : c.failures) failures.set(why, n);
    j.set("failures", std::move(failures));
    if (!std::isnan(we)) j.set("winding_error_median", we);
    if (c.second) {
      j.set("stable_second", c.stable_second);
      j.set("interval_second", interval_json(c.stable_second, c.tested));
    }
    Json d = Json::object();
    d.set("tested", c.distinct_tested);
    d.set("stable", c.distinct_stable);
    if (c.second) d.set("stable_second", c.distinct_stable_second);
    j.set("distinct", std::move(d));
    cell_list.push_back(std::move(j));
  }
  // The paired comparisons, in the order the pairs and methods came.
  std::stable_sort(paired_order.begin(), paired_order.end(), [&](const auto& a, const auto& b) {
    return std::find(pairs.begin(), pairs.end(), a.first) <
           std::find(pairs.begin(), pairs.end(), b.first);
  });
  const bool second_judge = cells.empty() || cells.begin()->second.second;
  Json paired_list = Json::array();
  if (!paired_order.empty())
    md += "\nAgainst " + first +
          ", on the same grasps, both objects: held by this method only : by " + first +
          " only, McNemar's exact p\n\n| source -> target | method | built-in | MuJoCo | "
          "distinct grasps, built-in | distinct grasps, MuJoCo |\n|---|---|---|---|---|---|\n";
  for (const auto& pm : paired_order) {
    const Paired& pr = paired[pm];
    Json j = Json::object();
    j.set("pair", pm.first);
    j.set("method", pm.second);
    j.set("against", first);
    md += "| " + pm.first + " | " + pm.second + " |";
    for (int v = 0; v < 2; ++v)
      for (int e = 0; e < 2; ++e) {
        const char* name[2][2] = {{"builtin", "mujoco"}, {"distinct_builtin", "distinct_mujoco"}};
        if (e == 1 && !second_judge) {
          md += " - |";
          continue;
        }
        const int b = pr.only_this[e][v], c = pr.only_first[e][v];
        const double p = mcnemar_exact_p(b, c);
        char buf[96];
        std::snprintf(buf, sizeof buf, " %d : %d, p = %.2g |", b, c, p);
        md += buf;
        Json x = Json::object();
        x.set("only_this", b);
        x.set("only_first", c);
        x.set("p", p);
        j.set(name[v][e], std::move(x));
      }
    md += "\n";
    paired_list.push_back(std::move(j));
  }
  int stable_demos = 0;
  for (const auto& d : demonstrated) stable_demos += d.has_value();
  Json doc = Json::object();
  doc.set("generator", "topograsp transfer_matrix");
  doc.set("seed", std::to_string(o.seed));  // a string: every 64-bit seed exactly
  doc.set("hypotheses", static_cast<int>(tasks.size()));
  doc.set("hypothesis_rule", std::string(to_string(o.hypotheses)));
  doc.set("closing", !o.transfer.sim.close.hold_object    ? "free"
                     : o.transfer.sim.close.balanced_hold ? "balanced"
                                                          : "held");
  doc.set("human_max_grip", o.transfer.sim.human_max_grip);
  doc.set("demonstrations", stable_demos);
  doc.set("distinct_demonstrations", distinct_demos);
  doc.set("second_judge", second_judge ? "mujoco" : "none");
  doc.set("cells", std::move(cell_list));
  doc.set("paired", std::move(paired_list));
  char intro[320];
  std::snprintf(intro, sizeof intro,
                "Seed %llu: %d grasp hypotheses, %d stable human demonstrations (%d distinct "
                "grasps). Rates with 95 %% Wilson intervals; robot -> robot rows start from the "
                "stable topological transfers (docs/results.md).",
                static_cast<unsigned long long>(o.seed), static_cast<int>(tasks.size()),
                stable_demos, distinct_demos);
  page.intro = intro;
  write_html_page((folder.staging() / "index.html").string(), page);
  detail::write_text_file(folder.staging() / "matrix.md", md);
  detail::write_text_file(folder.staging() / "matrix.json", doc.dump() + "\n");
  folder.commit();
  std::fputs(md.c_str(), stdout);
  std::printf(
      "%d hypotheses, %d stable demonstrations (%d distinct grasps); wrote %s/matrix.json, "
      "matrix.md and index.html\n",
      static_cast<int>(tasks.size()), stable_demos, distinct_demos, o.out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef SIGXFSZ
  // Past a file-size limit a write fails with EFBIG (a readable error, the previous outputs
  // untouched) instead of the signal ending the process.
  (void)std::signal(SIGXFSZ, SIG_IGN);
#endif
  Options o;
  try {
    o = parse(std::span<char*>(argv + 1, static_cast<std::size_t>(argc - 1)));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "transfer_matrix: %s\n%s", e.what(), usage.data());
    return 2;
  }
  // The output folder before the work: a run that cannot write its results does not start.
  std::optional<OutputFolder> folder;
  try {
    folder.emplace(o.out, o.force, "--out", false, transfer_matrix_layout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "transfer_matrix: %s\n", e.what());
    return 2;
  }
  try {
    return run(o, *folder);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "transfer_matrix: %s\n", e.what());
    return 1;
  }
}

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The command line of grasp_transfer as a library function: parse_command_line turns the
/// arguments into an ExperimentOptions, the output folder and the flags, or throws
/// topograsp::invalid_argument naming the option; command_line_usage is the --help text.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/source_run.hpp>
#include <topograsp/io/keypoint_grasp.hpp>
#include <topograsp/io/ycb_objects.hpp>

namespace topograsp {

/// What the command line of grasp_transfer asks for.
struct CommandLine {
  /// The experiment: objects and methods are filled (default hammer, bottle and the five
  /// methods of Table I, in the order given); the hypotheses default to the power grip's and
  /// the closing to the balanced hold (--hypotheses, --closing); every other field as parsed or
  /// its default.
  ExperimentOptions experiment;
  /// --hand: the robot hand the demonstrations are transferred to, one of the program's hands
  /// (default its first: the SDH for grasp_transfer, docs/transfer.md "Any hand")
  std::string hand;
  /// --hands: several of the program's hands, in the order given: the same run for each, into
  /// DIR/<hand>/, and a table of every hand (DIR/hands.json, DIR/hands.md; docs/transfer.md,
  /// "Several hands"). Empty without --hands.
  std::vector<std::string> hands;
  std::filesystem::path out = "grasp_transfer_out";  ///< --out: the output folder (non-empty)
  bool quiet = false;    ///< --quiet: no progress lines (warnings are still printed)
  bool figures = false;  ///< --figures: also DIR/figures/*.svg and DIR/index.html
  bool force = false;    ///< --force: write into a non-empty folder that holds no earlier run
  bool help = false;     ///< --help or -h: print command_line_usage() and do nothing else
  /// false with --skip-hand-check: run even if the hand fails its self-check (check_hand)
  bool check_hand = true;
  /// --resume: skip the hypotheses that an interrupted run into DIR with the same options
  /// journalled, and keep their records and scenes (docs/transfer.md)
  bool resume = false;
  /// `grasp_transfer merge [--out DIR] [--force] [--quiet] SHARD_DIR...`: merge the output
  /// folders of a run's shards into DIR (merge is true, the shards' folders in shards).
  bool merge = false;
  std::vector<std::filesystem::path> shards;  ///< merge: the shards' output folders
  /// --source: the earlier run whose hand's stable topological transfers are the demonstrations
  /// (read into experiment.sources; docs/transfer.md, "A robot hand as the demonstrator")
  std::filesystem::path source;
};

/// The largest --jobs accepted.
inline constexpr int max_command_line_jobs = 1024;
/// The largest --friction accepted (a Coulomb coefficient).
inline constexpr double max_command_line_friction = 10.0;

namespace detail {

// The recorded grasps of --demonstrations: one keypoint file, or every *.json file of a folder
// (by name). Errors name the option, then the file and the field (keypoint_error).
inline std::vector<RecordedGrasp> read_demonstrations(std::string_view value) {
  namespace fs = std::filesystem;
  const fs::path path{std::string(value)};
  std::error_code ec;
  std::vector<fs::path> files;
  if (fs::is_directory(path, ec)) {
    for (const fs::directory_entry& e : fs::directory_iterator(path, ec))
      if (e.is_regular_file(ec) && e.path().extension() == ".json") files.push_back(e.path());
    if (ec)
      throw_invalid_argument("--demonstrations",
                             "cannot list \"" + path.string() + "\": " + ec.message());
    std::sort(files.begin(), files.end());
    if (files.empty())
      throw_invalid_argument("--demonstrations",
                             "\"" + path.string() + "\" holds no keypoint files (*.json)");
  } else {
    files.push_back(path);
  }
  std::vector<RecordedGrasp> out;
  for (const fs::path& f : files) {
    try {
      out.push_back({f.string(), read_keypoint_grasp(f.string())});
    } catch (const invalid_argument& e) {
      throw_invalid_argument("--demonstrations", e.what());
    }
  }
  return out;
}

// s in double quotes for a message: bytes outside printable ASCII as \xNN, at most 80 bytes shown.
inline std::string quote_argument(std::string_view s) {
  std::string q = "\"";
  const std::size_t shown = std::min<std::size_t>(s.size(), 80);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c >= 0x7f || c == '"' || c == '\\') {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", static_cast<unsigned>(c));
      q += b;
    } else {
      q += static_cast<char>(c);
    }
  }
  if (shown < s.size()) q += "...";
  return q + "\"";
}

// The whole of text as a T, or an error naming option.
template <class T>
T parse_cli_number(std::string_view text, std::string_view option) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range)
    throw_invalid_argument(option, "number out of range: " + quote_argument(text));
  if (ec != std::errc() || end != text.data() + text.size())
    throw_invalid_argument(option, "expected a number, got " + quote_argument(text));
  return value;
}

inline std::string expected_names(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + names[i];
  return s;
}

// The comma-separated names of list, each one of known (in the order given). An empty, unknown
// or repeated name is an error naming option; so at most known.size() + 1 names are looked at,
// however long the list.
inline std::vector<std::string_view> split_cli_list(std::string_view list, std::string_view option,
                                                    const std::vector<std::string>& known,
                                                    std::string_view noun) {
  std::vector<std::string_view> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::string_view name = list.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    if (name.empty())
      throw_invalid_argument(
          option, "empty name in " + quote_argument(list) + " (expected comma-separated names)");
    bool is_known = false;
    for (const std::string& k : known) is_known = is_known || k == name;
    if (!is_known)
      throw_invalid_argument(option, "unknown " + std::string(noun) + " " + quote_argument(name) +
                                         " (expected " + expected_names(known) + ")");
    for (const std::string_view seen : names)
      if (seen == name)
        throw_invalid_argument(option,
                               quote_argument(name) + " is given twice in " + quote_argument(list));
    names.push_back(name);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return names;
}

// The closing protocol of --closing (free, held or balanced; docs/evaluation.md) in sim. free:
// the object free while the hands close, the human hand approaching until any link touches (the
// paper's). held: every hand closes on the object held still, the object released for 0.25 s
// (gravity off) before the tests, and the human hand approaches palm first. balanced: the same,
// each hand holding with torques whose contact forces balance on the object.
inline void set_closing(GraspSimOptions& sim, std::string_view protocol) {
  const bool held = protocol != "free";
  sim.close.hold_object = held;
  sim.close.release_steps = held ? 15 : 0;
  sim.close.proximal_first = held;
  sim.close.balanced_hold = protocol == "balanced";
  sim.palm_first = held;
}

// --human-grip's value: the human hand's strongest grip, a multiple of its holding torques in
// [1, k_max_grip]; \p option names it in the error.
inline double parse_human_grip(std::string_view value, std::string_view option) {
  const double g = parse_cli_number<double>(value, option);
  if (!(g >= 1.0 && g <= k_max_grip))
    throw_invalid_argument(option,
                           "expected a multiple of the human hand's holding torques in [1, " +
                               number_text(k_max_grip) + "], got " + quote_argument(value));
  return g;
}

// --closing's value checked (free, held or balanced) and set in sim; \p option names it in the
// message.
inline void parse_closing(std::string_view value, std::string_view option, GraspSimOptions& sim) {
  if (value != "free" && value != "held" && value != "balanced")
    throw_invalid_argument(option, "expected free, held or balanced, got " + quote_argument(value));
  set_closing(sim, value);
}

// --hypotheses' value: demonstrator, power or box.
[[nodiscard]] inline HypothesisRule parse_hypothesis_rule(std::string_view value,
                                                          std::string_view option) {
  return enum_from_name(value,
                        {HypothesisRule::box, HypothesisRule::demonstrator, HypothesisRule::power},
                        option, "rule");
}
}  // namespace detail

/// Parses the arguments of grasp_transfer (\p args without the program name; the options are
/// listed by command_line_usage()). An option's value is the next argument; it may not be empty
/// nor start with "--". `--help` (or `-h`) returns at once with help set, ignoring what follows.
/// \throws topograsp::invalid_argument, and nothing else, whose message starts with the offending
/// option (e.g. "--out: expected a value, got the option \"--jobs\"") for: an unknown option, a
/// missing, empty or "--" value, a value option given twice, a number that does not parse or is
/// out of range (--jobs 1..1024, --max-hypotheses >= 0, --shard K/N with 1 <= K <= N, --seed an
/// unsigned 64-bit integer, --friction a number in (0, 10]), an unknown, empty or repeated
/// object or method, an unknown
/// --winding-reference, a --set that is not NAME=VALUE, names an unknown parameter, sets one twice
/// or a value outside its range (transfer_parameters), an --out with a NUL character, an unknown
/// --judge, and --judge mujoco or both when \p mujoco_linked is false. With "merge" first: an
/// option other than --out, --force, --quiet (the message says which it takes), --out without a
/// value or twice, an empty shard folder name, or no shard folder. \p mujoco_linked says
/// whether the program was built with MuJoCo (TOPOGRASP_HAVE_MUJOCO); it sets the default of
/// --judge: both with MuJoCo, builtin without. \p hands: the names --hand accepts, the first the
/// default (empty: "sdh" only); another --hand is refused with the list.
[[nodiscard]] inline CommandLine parse_command_line(std::span<const std::string_view> args,
                                                    bool mujoco_linked = false,
                                                    std::span<const std::string_view> hands = {}) {
  CommandLine cli;
  const std::vector<std::string> hand_names =
      hands.empty() ? std::vector<std::string>{"sdh"}
                    : std::vector<std::string>(hands.begin(), hands.end());
  cli.hand = hand_names.front();
  cli.experiment.judge = mujoco_linked ? Judge::both : Judge::builtin;
  // The program's protocol (issue 28; docs/evaluation.md, "The balanced hold" and "The power
  // grip"): the power grip's hypotheses, every hand closing on the held object and holding with
  // balanced torques. The paper's is --hypotheses box --closing free (ExperimentOptions' and
  // GraspSimOptions' own defaults, which library callers get).
  cli.experiment.hypotheses = HypothesisRule::power;
  detail::set_closing(cli.experiment.transfer.sim, "balanced");
  if (!args.empty() && args.front() == "merge") {
    cli.merge = true;
    bool out_seen = false;
    for (std::size_t i = 1; i < args.size(); ++i) {
      const std::string_view arg = args[i];
      if (arg == "--help" || arg == "-h") {
        cli.help = true;
        return cli;
      }
      if (arg == "--quiet" || arg == "--force") {
        (arg == "--quiet" ? cli.quiet : cli.force) = true;
      } else if (arg == "--out") {
        if (out_seen) detail::throw_invalid_argument(arg, "given twice");
        out_seen = true;
        if (i + 1 >= args.size() || args[i + 1].empty() || args[i + 1].starts_with("--"))
          detail::throw_invalid_argument(arg, "expected a value");
        const std::string_view value = args[++i];
        if (value.find('\0') != std::string_view::npos)
          detail::throw_invalid_argument(arg, "the folder name contains a NUL character");
        cli.out = std::filesystem::path(std::string(value));
      } else if (arg.starts_with("-")) {
        detail::throw_invalid_argument(
            arg,
            "not an option of merge (merge takes --out DIR, --force, --quiet and the "
            "shards' output folders)");
      } else if (arg.empty() || arg.find('\0') != std::string_view::npos) {
        detail::throw_invalid_argument(
            "merge", "expected a shard's output folder, got " + detail::quote_argument(arg));
      } else {
        cli.shards.emplace_back(std::string(arg));
      }
    }
    if (cli.shards.empty())
      detail::throw_invalid_argument("merge", "expected the shards' output folders");
    return cli;
  }
  std::string_view objects_list = "hammer,bottle";
  std::string demonstration_objects;  // the recordings' objects, with --demonstrations
  std::string_view methods_list = "topological,autoclose,transplant,fingertip,virtual_finger";
  std::vector<std::string_view> seen;  // value options given so far
  std::vector<std::string_view> set_names;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    if (arg == "--help" || arg == "-h") {
      cli.help = true;
      return cli;
    }
    if (arg == "--figures") {
      cli.figures = true;
      continue;
    }
    if (arg == "--quiet") {
      cli.quiet = true;
      continue;
    }
    if (arg == "--force") {
      cli.force = true;
      continue;
    }
    if (arg == "--resume") {
      cli.resume = true;
      continue;
    }
    if (arg == "--skip-hand-check") {
      cli.check_hand = false;
      continue;
    }
    if (arg == "--every-test") {
      cli.experiment.transfer.sim.stability.every_test = true;
      continue;
    }
    constexpr std::string_view value_options[] = {
        "--objects", "--methods",        "--out",           "--jobs",
        "--seed",    "--max-hypotheses", "--shard",         "--winding-reference",
        "--set",     "--friction",       "--hold-fraction", "--human-grip",
        "--judge",   "--demonstrations", "--hypotheses",    "--closing",
        "--setting", "--hand",           "--hands",         "--source"};
    bool known = false;
    for (const std::string_view o : value_options) known = known || o == arg;
    if (!known)
      detail::throw_invalid_argument(
          arg.empty() ? std::string_view("argument") : arg,
          "unknown option " + detail::quote_argument(arg) + " (see --help)");
    if (i + 1 >= args.size()) detail::throw_invalid_argument(arg, "expected a value");
    const std::string_view value = args[++i];
    if (value.empty()) detail::throw_invalid_argument(arg, "expected a value, got \"\"");
    if (value.starts_with("--"))
      detail::throw_invalid_argument(
          arg, "expected a value, got the option " + detail::quote_argument(value));
    if (arg != "--set") {
      for (const std::string_view s : seen)
        if (s == arg) detail::throw_invalid_argument(arg, "given twice");
      seen.push_back(arg);
    }
    if (arg == "--objects") {
      objects_list = value;
    } else if (arg == "--hand") {
      if (std::find(hand_names.begin(), hand_names.end(), value) == hand_names.end()) {
        std::string list;
        for (const std::string& h : hand_names) list += (list.empty() ? "" : ", ") + h;
        detail::throw_invalid_argument(
            arg, "no hand " + detail::quote_argument(value) + " in this program (" + list + ")");
      }
      cli.hand = std::string(value);
    } else if (arg == "--hands") {
      for (const std::string_view h : detail::split_cli_list(value, arg, hand_names, "hand"))
        cli.hands.emplace_back(h);
    } else if (arg == "--demonstrations") {
      cli.experiment.demonstrations = detail::read_demonstrations(value);
    } else if (arg == "--source") {
      if (value.find('\0') != std::string_view::npos)
        detail::throw_invalid_argument(arg, "the path contains a NUL character");
      cli.source = std::filesystem::path(std::string(value));
    } else if (arg == "--methods") {
      methods_list = value;
    } else if (arg == "--out") {
      if (value.find('\0') != std::string_view::npos)
        detail::throw_invalid_argument(arg, "the folder name contains a NUL character");
      cli.out = std::filesystem::path(std::string(value));
    } else if (arg == "--jobs") {
      const int jobs = detail::parse_cli_number<int>(value, arg);
      if (jobs < 1 || jobs > max_command_line_jobs)
        detail::throw_invalid_argument(arg, "expected 1 to " +
                                                std::to_string(max_command_line_jobs) + ", got " +
                                                std::to_string(jobs));
      cli.experiment.jobs = jobs;
    } else if (arg == "--seed") {
      cli.experiment.seed = detail::parse_cli_number<std::uint64_t>(value, arg);
    } else if (arg == "--max-hypotheses") {
      const int m = detail::parse_cli_number<int>(value, arg);
      if (m < 0)
        detail::throw_invalid_argument(arg,
                                       "expected a count >= 0 (0: all), got " + std::to_string(m));
      cli.experiment.max_hypotheses = m;
    } else if (arg == "--shard") {
      const std::size_t slash = value.find('/');
      if (slash == std::string_view::npos)
        detail::throw_invalid_argument(arg, "expected K/N, got " + detail::quote_argument(value));
      const int k = detail::parse_cli_number<int>(value.substr(0, slash), arg);
      const int n = detail::parse_cli_number<int>(value.substr(slash + 1), arg);
      if (n < 1 || k < 1 || k > n)
        detail::throw_invalid_argument(
            arg, "expected 1 <= K <= N, got " + detail::quote_argument(value));
      cli.experiment.shard_index = k - 1;
      cli.experiment.shard_count = n;
    } else if (arg == "--friction") {
      const double mu = detail::parse_cli_number<double>(value, arg);
      if (!(mu > 0.0 && mu <= max_command_line_friction))
        detail::throw_invalid_argument(
            arg, "expected a Coulomb coefficient in (0, " +
                     std::to_string(static_cast<int>(max_command_line_friction)) + "], got " +
                     detail::quote_argument(value));
      cli.experiment.transfer.sim.friction = mu;
    } else if (arg == "--hold-fraction") {
      const double f = detail::parse_cli_number<double>(value, arg);
      if (!(f > 0.0 && f <= 1.0))
        detail::throw_invalid_argument(
            arg, "expected a fraction of the motors' torque limits in (0, 1], got " +
                     detail::quote_argument(value));
      cli.experiment.transfer.sim.close.hold_fraction = f;
    } else if (arg == "--human-grip") {
      cli.experiment.transfer.sim.human_max_grip = detail::parse_human_grip(value, arg);
    } else if (arg == "--hypotheses") {
      cli.experiment.hypotheses = detail::parse_hypothesis_rule(value, arg);
    } else if (arg == "--setting") {
      if (value != "hand" && value != "arm")
        detail::throw_invalid_argument(
            arg, "expected hand or arm, got " + detail::quote_argument(value));
      cli.experiment.arm_setting = value == "arm";
    } else if (arg == "--closing") {
      detail::parse_closing(value, arg, cli.experiment.transfer.sim);
    } else if (arg == "--winding-reference") {
      cli.experiment.transfer.winding_reference =
          enum_from_name(value, {WindingReference::centre_of_mass, WindingReference::nearest_point},
                         arg, "reference");
    } else if (arg == "--judge") {
      cli.experiment.judge =
          enum_from_name(value, {Judge::builtin, Judge::mujoco, Judge::both}, arg, "judge");
      if (cli.experiment.judge != Judge::builtin && !mujoco_linked)
        detail::throw_invalid_argument(arg,
                                       "this grasp_transfer was built without MuJoCo, so "
                                       "only --judge builtin is available (install MuJoCo "
                                       "2.2, e.g. Debian's libmujoco-dev, and configure "
                                       "again)");
    } else {  // --set
      const std::size_t eq = value.find('=');
      if (eq == std::string_view::npos || eq == 0 || eq + 1 == value.size())
        detail::throw_invalid_argument(arg,
                                       "expected NAME=VALUE, got " + detail::quote_argument(value));
      const std::string_view name = value.substr(0, eq);
      // set_transfer_parameter's message ("name: ..." or "<parameter>: ..."), after the option.
      const auto set = [&](double v) {
        try {
          set_transfer_parameter(cli.experiment.transfer, name, v);
        } catch (const invalid_argument& e) {
          detail::throw_invalid_argument(arg, e.what());
        }
      };
      const TransferParameter* p = find_transfer_parameter(name);
      if (p == nullptr) set(0.0);  // throws: unknown parameter, the known ones listed
      for (const std::string_view s : set_names)
        if (s == name) detail::throw_invalid_argument(arg, std::string(name) + " is set twice");
      set_names.push_back(name);
      set(detail::parse_cli_number<double>(value.substr(eq + 1), "--set " + std::string(name)));
    }
  }
  if (!cli.hands.empty() && std::find(seen.begin(), seen.end(), "--hand") != seen.end())
    detail::throw_invalid_argument("--hands", "not with --hand: give the hands in one list");
  if (!cli.experiment.demonstrations.empty()) {
    // The recordings' objects, in the order they first come.
    if (std::find(seen.begin(), seen.end(), "--objects") != seen.end())
      detail::throw_invalid_argument("--objects",
                                     "not with --demonstrations: the recordings name the objects");
    std::string names;
    for (const RecordedGrasp& r : cli.experiment.demonstrations) {
      const std::vector<std::string> known = objects::all_names();
      if (std::find(known.begin(), known.end(), r.grasp.object) == known.end())
        detail::throw_invalid_argument("--demonstrations",
                                       r.source + ": object: unknown object \"" + r.grasp.object +
                                           "\" (docs/objects.md lists them)");
      if (("," + names + ",").find("," + r.grasp.object + ",") == std::string::npos)
        names += (names.empty() ? "" : ",") + r.grasp.object;
    }
    demonstration_objects = names;
    objects_list = demonstration_objects;
  }
  std::string source_objects;  // the source run's objects, with --source
  if (!cli.source.empty()) {
    for (const std::string_view other : {"--demonstrations", "--hypotheses", "--human-grip"})
      if (std::find(seen.begin(), seen.end(), other) != seen.end())
        detail::throw_invalid_argument(other,
                                       "not with --source: the source run's grasps are the "
                                       "demonstrations");
    const bool chosen = std::find(seen.begin(), seen.end(), "--objects") != seen.end();
    std::vector<std::string> wanted;
    if (chosen)
      for (const std::string_view name :
           detail::split_cli_list(objects_list, "--objects", objects::all_names(), "object"))
        wanted.emplace_back(name);
    read_source_run(cli.source, wanted, cli.experiment);
    if (!chosen) {  // every object of the source run, in its order
      for (const Json& o : cli.experiment.source_config.at("objects").as_array())
        source_objects += (source_objects.empty() ? "" : ",") + o.as_string();
      objects_list = source_objects;
    }
  }
  for (const std::string_view name :
       detail::split_cli_list(objects_list, "--objects", objects::all_names(), "object")) {
    std::optional<GraspObject> o;
    try {
      o = objects::find_any(name);
    } catch (const invalid_argument& e) {  // a YCB mesh that cannot be read: say which option
      detail::throw_invalid_argument("--objects", e.what());
    }
    if (!o)
      detail::throw_invalid_argument("--objects", "no object " + detail::quote_argument(name));
    cli.experiment.objects.push_back(std::move(*o));
  }
  std::vector<std::string> method_names;
  for (const TransferMethod m : all_transfer_methods) method_names.emplace_back(to_string(m));
  for (const std::string_view name :
       detail::split_cli_list(methods_list, "--methods", method_names, "method"))
    cli.experiment.methods.push_back(transfer_method(name));
  // A source's verdicts are comparable with this run's only if both were judged alike.
  if (!cli.source.empty()) check_source_config(cli.experiment, results_config(cli.experiment));
  return cli;
}

/// The --help text of grasp_transfer: the options, the output folder rule, the exit statuses and
/// the table of transfer parameters (name, default, valid range, meaning).
[[nodiscard]] inline std::string command_line_usage() {
  std::string text = R"(usage: grasp_transfer [options]
       grasp_transfer merge [--out DIR] [--force] [--quiet] SHARD_DIR...

Transfers stable human grasps to the Schunk SDH (on a 7-DOF arm) and tests every result in
simulation, as in "Topological Synergies for Grasp Transfer" (Table I); or to another hand.

options:
  --hand NAME      the robot hand (default sdh; the hands of this program are listed below):
                   the SDH as in the paper, any other hand on a free base, by every method but
                   closed_windings and shuffled_windings, in the hand setting
                   (docs/transfer.md, "Any hand"); every run first checks the hand
                   (check_hand: its palm frame, closing directions, motors and masses, and a
                   ball and a cylinder closed at its palm) and stops if it fails
  --hands A,B,...  the same run for each of these hands, one after another, each into DIR/<hand>
                   (its own results, scenes, figures, journal: --resume, --shard and merge
                   work hand by hand), then DIR/hands.json and DIR/hands.md: every hand's
                   rates side by side (docs/transfer.md, "Several hands"); not with --hand
  --skip-hand-check  run even if the hand fails its self-check
  --demonstrations FILE_OR_DIR  recorded human grasps (21 hand keypoints each, the JSON format
                   of docs/transfer.md; a folder: its *.json files by name) as the
                   demonstrations, in place of the planned ones; their objects are the run's
  --source RUN     a robot hand as the demonstrator: the stable topological transfers of the
                   earlier run RUN (an output folder, or its results.json) are the
                   demonstrations (each keeps its id; --max-hypotheses M: the first M of each
                   object), transferred to --hand on a free base; the objects default to RUN's;
                   RUN must be a whole run (not a shard) judged as this run is (seed, judges,
                   friction, closing, stability suite); not with --demonstrations,
                   --hypotheses, --human-grip or --setting arm
  --objects LIST   comma-separated objects, each once (default hammer,bottle; also mug, box,
                   ball, can, and the YCB objects ycb_cracker_box, ycb_sugar_box,
                   ycb_tomato_soup_can, ycb_mustard_bottle, ycb_banana, ycb_bleach_cleanser,
                   ycb_mug, ycb_power_drill, ycb_hammer: docs/objects.md)
  --methods LIST   comma-separated methods, each once (default topological,autoclose,transplant,
                   fingertip,virtual_finger; also the topological method's variants paper,
                   paper_line, paper_approach, no_windings, nearest_point, closed_windings, and
                   the controls no_plan and shuffled_windings: docs/transfer.md)
  --out DIR        the output folder (default grasp_transfer_out; see below)
  --force          write into DIR even if it is not empty and holds no earlier run
  --jobs N         worker threads, 1 to 1024 (default 1); if fewer threads can be started, the
                   run goes on with those and says so
  --seed S         seed of the stability suites (default 1); same seed, same results
  --shard K/N      run only hypotheses with id % N == K - 1 (1 <= K <= N), for job arrays; the
                   shards together give exactly the records of the whole run (see merge)
  --resume         skip the hypotheses that an interrupted run into DIR with the same options
                   finished (its journal), keeping their results and scenes
  --max-hypotheses M  only the first M hypotheses of each object (default 0: all)
  --hypotheses R   the grasp hypotheses of the planned demonstrations: power (default: the
                   power grip, the part's long axis laid across the palm's oblique band, near
                   the centre of mass, 5 angles each way, each also jittered 3 times in
                   position, tilt and roll by a seeded rule; docs/evaluation.md), demonstrator
                   (8 rolls per box face, each also jittered once) or box (the paper's: BADGr's
                   4 rolls per reachable box face)
  --closing C      balanced (default: every hand closes on the object held still, which is
                   then released for 0.25 s before the tests, and holds with torques whose
                   contact forces balance on the object; the human hand approaches palm first),
                   held (the same, every closing joint holding with its whole holding torque) or
                   free (the paper's: the object is free while the hands close, and the human
                   hand approaches until any link touches)
  --setting S      hand (default: every hand placed and judged without the arm; the topological
                   plan runs on the arm with the object turned to meet it) or arm (the paper's
                   setting: each object fixed in front of the arm, the arm moved from its ready
                   pose to the plan's start and every method's hand reached by the arm by
                   inverse kinematics, clear of the object, or failed: docs/transfer.md, "The
                   arm setting")
  --winding-reference R  where the windings are taken: centre_of_mass (default, the paper)
                   or nearest_point (the object's point nearest the human's grasp centre)
  --friction MU    one Coulomb coefficient for every hand-object pair, in (0, 10], for a friction
                   sensitivity run (default: each pair from the table of materials,
                   docs/objects.md)
  --hold-fraction F  the fraction of its motors' torque limits with which the robot hand
                   closes and holds, in (0, 1] (default 0.5); the human hand holds with its
                   holding torques
  --human-grip G   how much harder than its holding torques the human hand may grip where the
                   object's load asks for it under --closing balanced, in [1, 10] (default 5:
                   its holding torques are about a fifth of its strength; 1: the holding
                   torques alone, as before 2026-12-06; docs/evaluation.md)
  --judge J        which simulator judges the grasps: builtin, mujoco or both (default both
                   when built with MuJoCo, else builtin; mujoco and both need MuJoCo)
  --every-test     run every test of the stability suite on every grasp (default: a grasp's
                   suite stops at its first failed test, the same verdicts in about half the
                   simulation; docs/evaluation.md)
  --set NAME=VALUE  set a transfer parameter (repeatable, each name once; the names, defaults
                   and valid ranges are listed below, their meaning in docs/transfer.md)
  --figures        also write DIR/figures/*.svg and DIR/index.html (Fig. 5-7, Table I)
  --quiet          no progress on stderr (warnings are still printed)
  --help, -h       this text

An option's value may not be empty nor start with "--".

output folder: the run owns DIR/results.json, DIR/scenes/, DIR/figures/ and DIR/index.html.
Everything is first written into DIR/.grasp_transfer-staging-<id>/, then committed: scenes/,
figures/ and index.html are replaced entirely (an earlier run's are removed even if this run
writes none), and the new results.json is renamed over the old one last, so DIR always has one.
A run that fails or is interrupted before the commit leaves the previous run untouched (its
staging folder is removed by the next run into DIR); a commit interrupted part way is finished
by the next run into DIR. DIR is checked before any work: a non-empty DIR without a results.json of
grasp_transfer is refused unless --force, and so is a DIR where another run is writing (give each
--shard its own --out); DIR/results.json and DIR/index.html must be files, DIR/scenes and
DIR/figures folders. Other files in DIR are left alone.

resume: every finished hypothesis is journalled in the staging folder (its records in
journal.jsonl, its scenes in scenes/) as the run goes. A run that was killed or failed leaves
them; --resume takes them over (if the options but --jobs are the same; else it is refused,
naming the option that differs) and runs only the rest. Without --resume they are discarded.

merge: grasp_transfer merge --out DIR SHARD_DIR... puts the output folders of a run's shards
(--shard 1/N to N/N, each once, same options but --jobs) together into DIR: one results.json
with every record and every summary computed over all of them, and every scene, as the unsharded
run would have written them (but for the timings). The same output folder rule applies to DIR.

exit status: 0 done; 2 bad arguments or an unusable output folder (nothing was computed);
1 the run failed after it started (the previous run in DIR is untouched).

transfer parameters (--set NAME=VALUE):
)";
  return text + parameter_help(transfer_parameters, TransferOptions{});
}

}  // namespace topograsp

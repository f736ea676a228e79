// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The paper's experiment (section IV, Table I) as a library call: human demonstrations on each
/// object's box hypotheses, the stable ones transferred to a robot hand (the SDH by default, any
/// hand model with a hand description) by each method, every result judged by the stability
/// suite; in parallel, sharded, reproducible. run_experiment is a template on the target hand,
/// instantiated only where it is called (docs/architecture.md, "Compile time").
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include <topograsp/core/random.hpp>
#include <topograsp/grasp/grasp_identity.hpp>
#include <topograsp/grasp/keypoint_fit.hpp>
#include <topograsp/grasp/transfer.hpp>
#include <topograsp/grasp/transfer/hand.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp {

/// Which simulator judges a grasp's stability: the built-in stepper, MuJoCo
/// (mujoco/mujoco_scene.hpp, only where MuJoCo is linked), or both.
enum class Judge : std::uint8_t { builtin, mujoco, both };

/// The name of \p j ("builtin", "mujoco", "both").
[[nodiscard]] constexpr std::string_view to_string(Judge j) noexcept {
  switch (j) {
    case Judge::builtin:
      return "builtin";
    case Judge::mujoco:
      return "mujoco";
    case Judge::both:
      return "both";
  }
  return "unknown";
}

/// A recorded human grasp and where it comes from (a file's path, for the records).
struct RecordedGrasp {
  std::string source;
  KeypointGrasp grasp;
};

/// A robot hand's grasp as a demonstration (grasp_transfer --source): a stable transfer of an
/// earlier run, read from its results.json (source_run.hpp).
struct SourceDemonstration {
  std::string object;  ///< the object's name
  int id = 0;          ///< the hypothesis id in the earlier run (its shake seed, grasp_seed)
  SourceGrasp grasp;   ///< the source hand when closing ended, as its record's source_grasp
  /// The demonstration's record in this run's results.json (the earlier run's record of the
  /// transfer, as the demonstration: method "source", source_demonstration_record()).
  Json record;
  std::string scene;  ///< the MJCF text of its scene in the earlier run
};

/// Which rule makes the grasp hypotheses of the planned demonstrations.
enum class HypothesisRule : std::uint8_t {
  box,           ///< box_hypotheses(): BADGr's, 4 per reachable box face
  demonstrator,  ///< demonstrator_hypotheses(): 8 rolls per face, each also jittered once
  power,         ///< power_grip_hypotheses(): the long axis across the palm's oblique band
};
[[nodiscard]] constexpr std::string_view to_string(HypothesisRule r) noexcept {
  return r == HypothesisRule::demonstrator ? "demonstrator"
         : r == HypothesisRule::power      ? "power"
                                           : "box";
}

/// What to run.
struct ExperimentOptions {
  std::vector<GraspObject> objects;     ///< default: the paper's hammer and bottle
  std::vector<TransferMethod> methods;  ///< default: all three
  int jobs = 1;                         ///< worker threads (>= 1)
  std::uint64_t seed = 1;               ///< seeds every stability suite (see grasp_seed)
  int shard_index = 0;                  ///< run hypotheses with id % shard_count == shard_index
  int shard_count = 1;
  int max_hypotheses = 0;  ///< if > 0, only the first this many hypotheses of each object
  TransferOptions transfer{};
  /// Which engine judges each grasp (grasp_transfer --judge). builtin: the built-in stepper;
  /// mujoco or both need transfer.sim's second judges set (grasp_transfer sets MuJoCo's): with
  /// both, the built-in decides and MuJoCo's verdict is recorded beside it; with mujoco, MuJoCo's
  /// decides (transfer.sim.second_judge_decides) and the built-in's is recorded.
  Judge judge = Judge::builtin;
  /// Hypotheses not to run, as (object name, hypothesis id): those an earlier run into the same
  /// output folder has done (grasp_transfer --resume). They are left out of the results
  /// (ObjectResult::hypotheses does not count them); the caller has their records.
  std::vector<std::pair<std::string, int>> skip;
  /// Recorded human grasps (grasp_transfer --demonstrations): when not empty they are the
  /// demonstrations in place of the planned ones, each judged as demonstrate_recorded() says and
  /// transferred if stable; an object's k-th recording (in this order) is its hypothesis k. Every
  /// recording's object must be one of `objects`.
  std::vector<RecordedGrasp> demonstrations;
  /// A robot hand's grasps (grasp_transfer --source): when not empty they are the demonstrations,
  /// in place of the human hand's, each transferred as it is (it was judged stable in its run);
  /// an object's demonstrations are its sources, each hypothesis id the source's id. Every
  /// source's object must be one of `objects`; not with `demonstrations`, the arm setting, or a
  /// method that runs on the arm only (experiment_method for a hand other than the SDH).
  std::vector<SourceDemonstration> sources;
  /// The source run: its results.json's path, its hand's model name, the FNV-1a hash of its text
  /// and its config (results_config; read_source_run), recorded in this run's config.
  std::string source_results, source_hand, source_hash;
  Json source_config;
  /// How the planned demonstrations are made: box_hypotheses (BADGr's 4 per reachable box face,
  /// the default), demonstrator_hypotheses (8 rolls per face, each also jittered once,
  /// grasp_transfer --hypotheses demonstrator) or power_grip_hypotheses (the power grip's rolls,
  /// grasp_transfer's default).
  HypothesisRule hypotheses = HypothesisRule::box;
  /// The arm setting (grasp_transfer --setting arm): each object fixed in front of the arm
  /// (arm_setting_object_pose(), TransferOptions::arm_object), every method's hand reached by
  /// the arm. False (--setting hand, the default): the object turned to meet the topological
  /// plan, the hand alone placed and judged.
  bool arm_setting = false;
  /// When two stable demonstrations count as the same grasp (grasp_clusters()).
  GraspTolerance grasp_tolerance{};
};

/// The source of \p sources that is hypothesis \p id of the object called \p object, or null.
[[nodiscard]] inline const SourceDemonstration* find_source(
    const std::vector<SourceDemonstration>& sources, std::string_view object, int id) noexcept {
  for (const SourceDemonstration& d : sources)
    if (d.object == object && d.id == id) return &d;
  return nullptr;
}

/// The numbers of one method on one object.
struct MethodSummary {
  TransferMethod method = TransferMethod::topological;
  int tested = 0;  ///< stable demonstrations transferred
  int stable = 0;  ///< transfers that the stability suite called stable
  [[nodiscard]] double rate() const noexcept {
    return tested > 0 ? static_cast<double>(stable) / tested : 0.0;
  }
};

/// Everything measured on one object, the demonstrations transferred to hand \p M.
template <const auto& M>
struct ObjectResultOf {
  GraspObject object;
  int hypotheses = 0;                  ///< hypotheses run (after sharding)
  std::vector<HumanGrasp> human;       ///< every demonstration, in id order
  std::vector<MethodSummary> methods;  ///< in options.methods order
  /// [method][k]: the transfer of the k-th stable demonstration by each method
  std::vector<std::vector<HandTransfer<M>>> transfers;
  std::vector<int> transferred_ids;  ///< the human grasp id of each k
  [[nodiscard]] int stable_human() const noexcept {
    return static_cast<int>(transferred_ids.size());
  }
};
/// Everything measured on one object, the demonstrations transferred to the SDH (the paper's).
using ObjectResult = ObjectResultOf<models::schunk_sdh>;

/// The verdicts of method \p m (an index into \p r.methods) on each stable demonstration of \p r,
/// in the order of r.transferred_ids: by the engine that decides (\p second_judge false) or by
/// the second judge (true). A transfer that was not planned fails in both; a planned one without
/// a second verdict (no second judge in the run) fails in the second. Every method's vector has
/// the same grasps in the same order, so two of them are paired (compare_paired).
/// \throws topograsp::invalid_argument for m out of range.
template <const auto& M>
[[nodiscard]] std::vector<bool> method_outcomes(const ObjectResultOf<M>& r, std::size_t m,
                                                bool second_judge) {
  if (m >= r.transfers.size())
    detail::throw_invalid_argument(
        "m", "expected a method index below " + std::to_string(r.transfers.size()));
  std::vector<bool> out;
  out.reserve(r.transfers[m].size());
  for (const HandTransfer<M>& t : r.transfers[m])
    out.push_back(second_judge ? t.planned && t.second && t.second->stable : t.stable());
  return out;
}

/// The seed of the stability suite of grasp \p id of the object called \p object: the object's
/// name hashed (FNV-1a), then a SplitMix64 mix. The human demonstration and every method's transfer
/// of it share the seed, so every method meets the same shake, the same six directions and the
/// same hard shake on the same human grasp (a paired comparison, McNemar's test). A grasp's random
/// stream depends only on what it is, never on the order, the threads, the other objects of the
/// run or the shard, so any split of a run reproduces the whole.
[[nodiscard]] constexpr std::uint64_t grasp_seed(std::uint64_t seed, std::string_view object,
                                                 int id) noexcept {
  return detail::splitmix64_mix(seed ^ detail::splitmix64_mix(detail::fnv1a_64(object)) ^
                                (0xbf58476d1ce4e5b9ull * static_cast<std::uint64_t>(id + 1)));
}

/// The order in which grasp_transfer looks for the demonstration whose windings the
/// shuffled-windings control of hypothesis \p id (of \p n of its object) aims at: id + n/2,
/// id + n/2 + 1, ... modulo n, never id itself; the first whose human grasp reaches the object is
/// taken (reached, not necessarily stable: its windings are those of a closed human hand around
/// the object). Fixed in advance, the same in every shard. Empty for n < 2.
[[nodiscard]] inline std::vector<int> shuffle_partner_order(int id, int n) {
  std::vector<int> order;
  for (int k = 0; k < n; ++k) {
    const int j = (id + n / 2 + k) % n;
    if (j != id) order.push_back(j);
  }
  return order;
}

namespace detail {

// Starts a std::thread running f: the default thread factory of parallel_for.
struct StartStdThread {
  template <class F>
  std::thread operator()(F&& f) const {
    return std::thread(std::forward<F>(f));
  }
};

// Runs body(i) for i in [0, n) on up to `jobs` threads, the calling thread one of them; each index
// at most once; after an exception of body no thread starts a new index, and the first exception
// is rethrown after every thread has been joined. Threads come
// from start_thread(worker) (a std::thread); if starting one throws (std::system_error when the
// system has no more threads, std::bad_alloc), no more are started and the work goes on with the
// threads that did start (the calling thread always works), so a failed start never ends in
// std::terminate. Returns the number of threads that ran, and the start's error in *start_error.
template <class StartThread = StartStdThread>
int parallel_for(int n, int jobs, const std::function<void(int)>& body,
                 StartThread&& start_thread = {}, std::string* start_error = nullptr) {
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto worker = [&] {
    for (int i = next++; i < n; i = next++) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = n;  // no new work: the run has failed
      }
    }
  };
  std::vector<std::thread> threads;
  const int wanted = std::min(jobs, n);
  try {
    threads.reserve(static_cast<std::size_t>(std::max(wanted - 1, 0)));
    for (int t = 1; t < wanted; ++t) threads.push_back(start_thread(worker));
  } catch (const std::exception& e) {
    if (start_error != nullptr) *start_error = e.what();
  } catch (...) {
    if (start_error != nullptr) *start_error = "unknown error";
  }
  worker();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return static_cast<int>(threads.size()) + 1;
}

}  // namespace detail

/// Called with a line of progress (no newline) as the experiment runs; may be called from
/// worker threads, one call at a time.
using ProgressFn = std::function<void(std::string_view)>;

/// Called once for each hypothesis when it is done: the object, the demonstration, and each
/// method's transfer of it to hand \p M in options.methods order (empty when the demonstration
/// was not stable). From worker threads, one call at a time, in no fixed order (grasp_transfer
/// journals each hypothesis so that --resume can skip it). An exception it throws ends the run.
template <const auto& M>
using HypothesisDoneFnOf =
    std::function<void(const GraspObject&, const HumanGrasp&, const std::vector<HandTransfer<M>>&)>;
/// The same for the SDH (the paper's).
using HypothesisDoneFn = HypothesisDoneFnOf<models::schunk_sdh>;

/// Whether hand model \p M is the SDH (models::schunk_sdh), the paper's hand.
template <const auto& M>
[[nodiscard]] consteval bool is_sdh() noexcept {
  if constexpr (std::is_same_v<std::remove_cvref_t<decltype(M)>,
                               std::remove_cvref_t<decltype(models::schunk_sdh)>>)
    return &M == &models::schunk_sdh;
  else
    return false;
}

/// Whether the experiment runs \p method on hand \p M: every method on the SDH (the paper's
/// hand: its topological plan on the arm, transfer()); on any other hand the methods of
/// transfer_hand() (any_hand_method: on a free base, so not closed_windings, whose closing
/// corrections run on the arm, nor shuffled_windings).
template <const auto& M>
[[nodiscard]] constexpr bool experiment_method(TransferMethod method) noexcept {
  return is_sdh<M>() || any_hand_method(method);
}

namespace detail {
// run_experiment with the threads started by start_thread (a test seam, see parallel_for).
template <const auto& M, class StartThread>
std::vector<ObjectResultOf<M>> run_experiment_with(const ExperimentOptions& options,
                                                   const ProgressFn& progress,
                                                   const HypothesisDoneFnOf<M>& on_done,
                                                   const SecondJudge<M>& second,
                                                   StartThread&& start_thread);

// One method's transfer of the demonstration g to hand M: the SDH's by transfer() (the paper's
// setting, judged also by options.sim.second_judge_sdh), any other hand's by transfer_hand() on a
// free base, judged also by second. A robot hand's grasp (source not null) is transferred by
// transfer_hand() to every hand, the SDH too.
template <const auto& M>
HandTransfer<M> experiment_transfer(TransferMethod method, const GraspObject& object,
                                    const HumanGrasp& g, const SourceDemonstration* source,
                                    const TransferOptions& options, const SecondJudge<M>& second) {
  if constexpr (is_sdh<M>()) {
    if (source != nullptr)
      return transfer_hand<M>(method, object, source->grasp, options,
                              second ? second : options.sim.second_judge_sdh);
    return transfer(method, object, g, options);
  } else {
    if (source != nullptr) return transfer_hand<M>(method, object, source->grasp, options, second);
    TransferRun<M> refusal(method, unusable_human_grasp(g), options);
    if (refusal.refused()) return refusal.unplanned();
    return transfer_hand<M>(method, object, describe_source(g), options, second);
  }
}
}  // namespace detail

/// Checks \p options as run_experiment<M> does before any work, \p second the second judge of
/// hand M (for the SDH, options.transfer.sim.second_judge_sdh when \p second is empty).
/// \throws topograsp::invalid_argument naming the field for jobs < 1, a bad shard,
/// max_hypotheses < 0, an empty object or method list, an object (by name) or a method given twice
/// (their scenes would overwrite each other), a method hand M does not run (experiment_method), the
/// arm setting for a hand other than the SDH, an invalid object, or a transfer parameter outside
/// its range (validate_transfer_parameters), a negative or non-finite transfer.sim.friction, a
/// hold fraction outside (0, 1] (transfer.sim.close.hold_fraction, human_hold_fraction), a
/// human_max_grip outside [1, k_max_grip], a closing option outside its range (close_parameters,
/// named "transfer.sim.close.<option>"),
/// bad stability options (validate_stability_options, named "transfer.sim.stability.<option>"),
/// a skipped hypothesis of an object that is not in the run; for sources (options.sources): with
/// recorded demonstrations or the arm setting ("sources"), a method that transfers a human
/// demonstration only ("methods"), a source whose object is not in the run, a negative source id
/// or a source given twice.
template <const auto& M = models::schunk_sdh>
void validate_experiment_options(const ExperimentOptions& options,
                                 const SecondJudge<M>& second = {}) {
  if (options.jobs < 1) detail::throw_invalid_argument("jobs", "expected at least 1");
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count)
    detail::throw_invalid_argument("shard", "expected 0 <= index < count");
  if (options.max_hypotheses < 0)
    detail::throw_invalid_argument("max_hypotheses", "expected >= 0 (0: all)");
  if (options.objects.empty()) detail::throw_invalid_argument("objects", "expected at least one");
  if (options.methods.empty()) detail::throw_invalid_argument("methods", "expected at least one");
  for (std::size_t i = 0; i < options.objects.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (options.objects[i].name == options.objects[j].name)
        detail::throw_invalid_argument(
            "objects", "\"" + options.objects[i].name + "\" is given twice (each object once)");
  for (std::size_t i = 0; i < options.methods.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (options.methods[i] == options.methods[j])
        detail::throw_invalid_argument("methods", "\"" +
                                                      std::string(to_string(options.methods[i])) +
                                                      "\" is given twice (each method once)");
  constexpr std::string_view hand = M.name.view();
  for (const TransferMethod m : options.methods)
    if (!experiment_method<M>(m))
      detail::throw_invalid_argument(
          "methods", "\"" + std::string(to_string(m)) +
                         "\" runs with the SDH on the arm only; the " + std::string(hand) +
                         " is placed on a free base (docs/transfer.md, \"Any hand\")");
  if (options.arm_setting && !is_sdh<M>())
    detail::throw_invalid_argument("arm_setting", "the arm carries the SDH only; the " +
                                                      std::string(hand) +
                                                      " is placed on a free base (--setting hand)");
  for (const GraspObject& o : options.objects) o.validate();
  for (std::size_t i = 0; i < options.demonstrations.size(); ++i) {
    const std::string& name = options.demonstrations[i].grasp.object;
    if (std::none_of(options.objects.begin(), options.objects.end(),
                     [&](const GraspObject& o) { return o.name == name; }))
      detail::throw_invalid_argument("demonstrations[" + std::to_string(i) + "].object",
                                     "\"" + name + "\" (" + options.demonstrations[i].source +
                                         ") is not an object of the run");
  }
  if (!options.sources.empty()) {
    if (!options.demonstrations.empty())
      detail::throw_invalid_argument("sources", "not with recorded demonstrations");
    if (options.arm_setting)
      detail::throw_invalid_argument("sources",
                                     "a robot hand's grasps are transferred on a free base, not "
                                     "in the arm setting");
    for (const TransferMethod m : options.methods)
      if (!any_hand_method(m))
        detail::throw_invalid_argument(
            "methods", "\"" + std::string(to_string(m)) +
                           "\" transfers a human demonstration only (on the SDH on the arm); a "
                           "robot hand's grasp is transferred on a free base");
    for (std::size_t i = 0; i < options.sources.size(); ++i) {
      const SourceDemonstration& d = options.sources[i];
      if (std::none_of(options.objects.begin(), options.objects.end(),
                       [&](const GraspObject& o) { return o.name == d.object; }))
        detail::throw_invalid_argument("sources[" + std::to_string(i) + "].object",
                                       "\"" + d.object + "\" is not an object of the run");
      if (d.id < 0)
        detail::throw_invalid_argument(
            "sources[" + std::to_string(i) + "].id",
            "expected >= 0 (a hypothesis id), got " + std::to_string(d.id));
      for (std::size_t j = 0; j < i; ++j)
        if (options.sources[j].object == d.object && options.sources[j].id == d.id)
          detail::throw_invalid_argument(
              "sources[" + std::to_string(i) + "]",
              d.object + " hypothesis " + std::to_string(d.id) + " is given twice");
    }
  }
  validate_transfer_parameters(options.transfer);
  require_non_negative(options.transfer.sim.friction, "transfer.sim.friction");
  const GraspSimOptions& sim = options.transfer.sim;
  bool target_judged = static_cast<bool>(second);
  if constexpr (is_sdh<M>()) target_judged = target_judged || sim.second_judge_sdh;
  if (options.judge != Judge::builtin && !(sim.second_judge_human && target_judged))
    detail::throw_invalid_argument(
        "judge", "--judge " + std::string(to_string(options.judge)) +
                     " needs a second judge (transfer.sim.second_judge_human and the " +
                     std::string(hand) + "'s)");
  if (options.judge == Judge::builtin && (sim.second_judge_human || target_judged))
    detail::throw_invalid_argument(
        "judge", "builtin, but a second judge is set (transfer.sim.second_judge_*)");
  if (sim.second_judge_decides != (options.judge == Judge::mujoco))
    detail::throw_invalid_argument("transfer.sim.second_judge_decides",
                                   "expected true exactly when judge is mujoco");
  for (const auto& [f, name] :
       {std::pair{options.transfer.sim.close.hold_fraction, "transfer.sim.close.hold_fraction"},
        std::pair{options.transfer.sim.human_hold_fraction, "transfer.sim.human_hold_fraction"}})
    if (!(f > 0.0 && f <= 1.0)) detail::throw_invalid_argument(name, "expected a value in (0, 1]");
  const double grip = options.transfer.sim.human_max_grip;
  if (!(grip >= 1.0 && grip <= k_max_grip))
    detail::throw_invalid_argument(
        "transfer.sim.human_max_grip",
        "expected a value in [1, " + detail::number_text(k_max_grip) + "]");
  validate_parameters(options.transfer.sim.close, close_parameters, "transfer.sim.close.");
  validate_stability_options(options.transfer.sim.stability, "transfer.sim.stability");
  for (const std::pair<std::string, int>& s : options.skip)
    if (std::none_of(options.objects.begin(), options.objects.end(),
                     [&](const GraspObject& o) { return o.name == s.first; }))
      detail::throw_invalid_argument("skip", "object \"" + s.first + "\" (hypothesis " +
                                                 std::to_string(s.second) + ") is not in the run");
}

/// Runs the experiment described by \p options, the demonstrations transferred to hand \p M (the
/// SDH by default, as in the paper: detail::experiment_transfer says how each hand is reached),
/// each transfer judged also by \p second when the run has a second judge (for the SDH,
/// options.transfer.sim.second_judge_sdh when \p second is empty). Throws
/// topograsp::invalid_argument naming the field, before any work, for the options
/// validate_experiment_options<M> refuses. Each hypothesis
/// (of every object, but those in options.skip; or each recorded grasp of options.demonstrations)
/// is one task: its demonstration, then, if stable,
/// each method's transfer of it; \p on_done is called when it is done. Results are identical for
/// equal options whatever the number of jobs, and a grasp's result does not depend on the other
/// objects or the shard (grasp_seed). If fewer than \p options.jobs threads can be started, the
/// run goes on with those that did (at least the calling thread) and says so once through
/// \p progress, in a line that starts with "warning: ".
template <const auto& M = models::schunk_sdh>
[[nodiscard]] std::vector<ObjectResultOf<M>> run_experiment(
    const ExperimentOptions& options, const ProgressFn& progress = {},
    const HypothesisDoneFnOf<M>& on_done = {}, const SecondJudge<M>& second = {}) {
  return detail::run_experiment_with<M>(options, progress, on_done, second,
                                        detail::StartStdThread{});
}

template <const auto& M, class StartThread>
std::vector<ObjectResultOf<M>> detail::run_experiment_with(const ExperimentOptions& options,
                                                           const ProgressFn& progress,
                                                           const HypothesisDoneFnOf<M>& on_done,
                                                           const SecondJudge<M>& second,
                                                           StartThread&& start_thread) {
  validate_experiment_options<M>(options, second);
  std::mutex report_mutex;  // progress and on_done: one call at a time
  const auto say = [&](const std::string& line) {
    if (!progress) return;
    const std::lock_guard lock(report_mutex);
    progress(line);
  };
  // Every task: (object index, hypothesis id), objects in order, ids ascending.
  const std::size_t no = options.objects.size(), nm = options.methods.size();
  std::vector<std::vector<GraspHypothesis>> hyps(no);
  std::vector<std::vector<const RecordedGrasp*>> recorded(no);
  std::vector<std::vector<const SourceDemonstration*>> sources(no);  // [object]: by id
  std::vector<std::pair<std::size_t, int>> tasks;
  std::vector<ObjectResultOf<M>> results(no);
  std::vector<std::vector<std::size_t>> task_of(no);  // [object][k]: the task of its k-th id
  for (std::size_t oi = 0; oi < no; ++oi) {
    results[oi].object = options.objects[oi];
    for (const SourceDemonstration& d : options.sources)
      if (d.object == options.objects[oi].name) sources[oi].push_back(&d);
    std::sort(
        sources[oi].begin(), sources[oi].end(),
        [](const SourceDemonstration* a, const SourceDemonstration* b) { return a->id < b->id; });
    if (options.demonstrations.empty() && options.sources.empty())
      hyps[oi] = options.hypotheses == HypothesisRule::demonstrator
                     ? demonstrator_hypotheses(options.objects[oi], options.seed)
                 : options.hypotheses == HypothesisRule::power
                     ? power_grip_hypotheses(options.objects[oi], options.seed)
                     : box_hypotheses(options.objects[oi]);
    for (const RecordedGrasp& r : options.demonstrations)
      if (r.grasp.object == options.objects[oi].name) recorded[oi].push_back(&r);
    const int n = static_cast<int>(!options.sources.empty()         ? sources[oi].size()
                                   : options.demonstrations.empty() ? hyps[oi].size()
                                                                    : recorded[oi].size());
    for (int k = 0; k < n; ++k) {
      // A source keeps its hypothesis id (its shake seed); the others' id is their index.
      const int i = options.sources.empty() ? k : sources[oi][static_cast<std::size_t>(k)]->id;
      if (i % options.shard_count != options.shard_index ||
          (options.max_hypotheses > 0 && k >= options.max_hypotheses))
        continue;
      const std::pair<std::string, int> key{options.objects[oi].name, i};
      if (std::find(options.skip.begin(), options.skip.end(), key) != options.skip.end()) continue;
      task_of[oi].push_back(tasks.size());
      tasks.emplace_back(oi, i);
    }
    results[oi].hypotheses = static_cast<int>(task_of[oi].size());
  }
  std::vector<HumanGrasp> human(tasks.size());
  std::vector<std::vector<HandTransfer<M>>> transfers(tasks.size());
  std::atomic<int> done{0}, stable_done{0};
  std::string start_error;
  const int ran = detail::parallel_for(
      static_cast<int>(tasks.size()), options.jobs,
      [&](int k) {
        const auto [oi, id] = tasks[static_cast<std::size_t>(k)];
        const GraspObject& object = options.objects[oi];
        TransferOptions transfer_options = options.transfer;
        transfer_options.sim.stability.seed = grasp_seed(options.seed, object.name, id);
        if (options.arm_setting) transfer_options.arm_object = arm_setting_object_pose(object);
        if constexpr (is_sdh<M>())
          if (second) transfer_options.sim.second_judge_sdh = second;
        HumanGrasp& g = human[static_cast<std::size_t>(k)];
        const auto i = static_cast<std::size_t>(id);
        const SourceDemonstration* source = find_source(options.sources, object.name, id);
        if (source != nullptr) {
          // A robot hand's grasp: stable in its run, so transferred as it is. g carries its id
          // and verdict only (its record is the source's: hypothesis_records).
          g.id = id;
          g.reached = true;
          g.stability.stable = true;
        } else {
          g = recorded[oi].empty()
                  ? demonstrate(object, hyps[oi][i], id, transfer_options.sim)
                  : demonstrate_recorded(object, recorded[oi][i]->grasp, id, transfer_options.sim);
        }
        if (!recorded[oi].empty()) {
          const std::string which = "warning: [" + object.name + "] recording " +
                                    recorded[oi][i]->source + " (hypothesis " + std::to_string(id) +
                                    "): ";
          if (g.fit_error && !(g.fit_error->max <= k_keypoint_fit_warning))
            say(which + "the human hand fits its keypoints only within " +
                std::to_string(g.fit_error->max) +
                " m (check its units, frame and keypoint order)");
          if (!g.reached)
            say(which +
                "the human hand cannot be placed at the object along its palm's approach "
                "from the recorded pose; no record");
        }
        std::vector<HandTransfer<M>>& t = transfers[static_cast<std::size_t>(k)];
        if (g.stable()) {
          // The shuffled-windings control's other demonstration, made when first needed (the SDH
          // only).
          [[maybe_unused]] std::optional<HumanGrasp> partner;
          [[maybe_unused]] bool sought = false;
          const std::size_t object_index = oi;  // clang 14 captures no structured binding
          const int grasp_id = id;
          [[maybe_unused]] const auto find_partner = [&]() -> std::optional<HumanGrasp> {
            GraspSimOptions sim = transfer_options.sim;
            sim.second_judge_human = {};  // only its windings are used
            const auto& own = recorded[object_index];
            const int n = static_cast<int>(own.empty() ? hyps[object_index].size() : own.size());
            for (const int j : shuffle_partner_order(grasp_id, n)) {
              const auto u = static_cast<std::size_t>(j);
              HumanGrasp p = own.empty() ? demonstrate(object, hyps[object_index][u], j, sim)
                                         : demonstrate_recorded(object, own[u]->grasp, j, sim);
              if (p.reached) return p;
            }
            return std::nullopt;
          };
          for (const TransferMethod m : options.methods) {
            if (m != TransferMethod::shuffled_windings) {
              t.push_back(experiment_transfer<M>(m, object, g, source, transfer_options, second));
              continue;
            }
            if constexpr (is_sdh<M>()) {  // the SDH only (experiment_method)
              if (!sought) partner = find_partner();
              sought = true;
              t.push_back(
                  transfer_shuffled(object, g, partner ? &*partner : nullptr, transfer_options));
            }
          }
          ++stable_done;
        }
        if (on_done) {
          const std::lock_guard lock(report_mutex);
          on_done(object, g, t);
        }
        say("[" + object.name + "] hypothesis " + std::to_string(id) + " done (" +
            std::to_string(++done) + "/" + std::to_string(tasks.size()) + ", " +
            std::to_string(stable_done.load()) + " stable demonstrations transferred)");
      },
      start_thread, &start_error);
  if (!start_error.empty())
    say("warning: could start only " + std::to_string(ran) + " of " +
        std::to_string(
            std::min<std::size_t>(static_cast<std::size_t>(options.jobs), tasks.size())) +
        " threads (" + start_error + "); the run goes on with " + std::to_string(ran));
  for (std::size_t oi = 0; oi < no; ++oi) {
    ObjectResultOf<M>& res = results[oi];
    res.transfers.assign(nm, {});
    for (const std::size_t k : task_of[oi]) {
      res.human.push_back(std::move(human[k]));
      if (!res.human.back().stable()) continue;
      res.transferred_ids.push_back(res.human.back().id);
      for (std::size_t m = 0; m < nm; ++m) res.transfers[m].push_back(std::move(transfers[k][m]));
    }
    for (std::size_t m = 0; m < nm; ++m) {
      MethodSummary summary;
      summary.method = options.methods[m];
      summary.tested = res.stable_human();
      for (const HandTransfer<M>& r : res.transfers[m]) summary.stable += r.stable() ? 1 : 0;
      res.methods.push_back(summary);
    }
  }
  return results;
}

}  // namespace topograsp

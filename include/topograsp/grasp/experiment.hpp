// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The paper's experiment (section IV, Table I) as a library call: human demonstrations on each
/// object's box hypotheses, the stable ones transferred to the SDH by each method, every result
/// shaken; in parallel, sharded, reproducible.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <topograsp/core/random.hpp>
#include <topograsp/grasp/transfer.hpp>

namespace topograsp {

/// What to run.
struct ExperimentOptions {
  std::vector<GraspObject> objects;     ///< default: the paper's hammer and bottle
  std::vector<TransferMethod> methods;  ///< default: all three
  int jobs = 1;                         ///< worker threads (>= 1)
  std::uint64_t seed = 1;               ///< seeds every shake test (mixed with the grasp's id)
  int shard_index = 0;                  ///< run hypotheses with id % shard_count == shard_index
  int shard_count = 1;
  int max_hypotheses = 0;  ///< if > 0, only the first this many hypotheses of each object
  TransferOptions transfer{};
};

/// The numbers of one method on one object.
struct MethodSummary {
  TransferMethod method = TransferMethod::topological;
  int tested = 0;  ///< stable human grasps transferred
  int stable = 0;  ///< transfers that passed the shake test
  [[nodiscard]] double rate() const noexcept {
    return tested > 0 ? static_cast<double>(stable) / tested : 0.0;
  }
};

/// Everything measured on one object.
struct ObjectResult {
  GraspObject object;
  int hypotheses = 0;                              ///< hypotheses run (after sharding)
  std::vector<HumanGrasp> human;                   ///< every demonstration, in id order
  std::vector<MethodSummary> methods;              ///< in options.methods order
  std::vector<std::vector<RobotGrasp>> transfers;  ///< [method][k]: the k-th stable human grasp
  std::vector<int> transferred_ids;                ///< the human grasp id of each k
  [[nodiscard]] int stable_human() const noexcept {
    return static_cast<int>(transferred_ids.size());
  }
};

/// The seed of the shake test of grasp \p id of object \p object by method \p method (-1 for the
/// demonstration): a SplitMix64 mix, so results do not depend on the order or the threads.
[[nodiscard]] inline std::uint64_t grasp_seed(std::uint64_t seed, std::size_t object, int id,
                                              int method) noexcept {
  return detail::splitmix64_mix(seed ^ (0x9e3779b97f4a7c15ull * (object + 1)) ^
                                (0xbf58476d1ce4e5b9ull * static_cast<std::uint64_t>(id + 1)) ^
                                (0x94d049bb133111ebull * static_cast<std::uint64_t>(method + 2)));
}

namespace detail {
// Runs body(i) for i in [0, n) on `jobs` threads; each index once; exceptions are rethrown.
inline void parallel_for(int n, int jobs, const std::function<void(int)>& body) {
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
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::min(jobs, n); ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}
}  // namespace detail

/// Called with a line of progress (no newline) as the experiment runs; may be called from
/// worker threads, one call at a time.
using ProgressFn = std::function<void(std::string_view)>;

/// Runs the experiment described by \p options. Throws topograsp::invalid_argument naming the field
/// for jobs < 1, a bad shard, an empty object or method list, or an invalid object. Results are
/// identical for equal options whatever the number of jobs.
[[nodiscard]] inline std::vector<ObjectResult> run_experiment(const ExperimentOptions& options,
                                                              const ProgressFn& progress = {}) {
  if (options.jobs < 1) detail::throw_invalid_argument("jobs", "expected at least 1");
  if (options.shard_count < 1 || options.shard_index < 0 ||
      options.shard_index >= options.shard_count)
    detail::throw_invalid_argument("shard", "expected 0 <= index < count");
  if (options.objects.empty()) detail::throw_invalid_argument("objects", "expected at least one");
  if (options.methods.empty()) detail::throw_invalid_argument("methods", "expected at least one");
  for (const GraspObject& o : options.objects) o.validate();
  std::mutex progress_mutex;
  const auto say = [&](const std::string& line) {
    if (!progress) return;
    const std::lock_guard lock(progress_mutex);
    progress(line);
  };
  std::vector<ObjectResult> results;
  for (std::size_t oi = 0; oi < options.objects.size(); ++oi) {
    ObjectResult res;
    res.object = options.objects[oi];
    std::vector<GraspHypothesis> hyps = box_hypotheses(res.object);
    std::vector<int> ids;
    for (int i = 0; i < static_cast<int>(hyps.size()); ++i)
      if (i % options.shard_count == options.shard_index &&
          (options.max_hypotheses <= 0 || i < options.max_hypotheses))
        ids.push_back(i);
    res.hypotheses = static_cast<int>(ids.size());
    res.human.resize(ids.size());
    std::atomic<int> done{0};
    detail::parallel_for(static_cast<int>(ids.size()), options.jobs, [&](int k) {
      GraspSimOptions sim = options.transfer.sim;
      const int id = ids[static_cast<std::size_t>(k)];
      sim.shake.seed = grasp_seed(options.seed, oi, id, -1);
      res.human[static_cast<std::size_t>(k)] =
          demonstrate(res.object, hyps[static_cast<std::size_t>(id)], id, sim);
      say("[" + res.object.name + "] human demonstrations " + std::to_string(++done) + "/" +
          std::to_string(ids.size()));
    });
    for (const HumanGrasp& g : res.human)
      if (g.stable()) res.transferred_ids.push_back(g.id);
    std::vector<const HumanGrasp*> stable;
    for (const HumanGrasp& g : res.human)
      if (g.stable()) stable.push_back(&g);
    const std::size_t nm = options.methods.size();
    res.transfers.assign(nm, std::vector<RobotGrasp>(stable.size()));
    done = 0;
    const int total = static_cast<int>(nm * stable.size());
    detail::parallel_for(total, options.jobs, [&](int k) {
      const std::size_t m = static_cast<std::size_t>(k) / std::max<std::size_t>(stable.size(), 1);
      const std::size_t s = static_cast<std::size_t>(k) % std::max<std::size_t>(stable.size(), 1);
      TransferOptions transfer_options = options.transfer;
      const HumanGrasp& g = *stable[s];
      transfer_options.sim.shake.seed =
          grasp_seed(options.seed, oi, g.id, static_cast<int>(options.methods[m]));
      res.transfers[m][s] = transfer(options.methods[m], res.object, g, transfer_options);
      say("[" + res.object.name + "] transfers " + std::to_string(++done) + "/" +
          std::to_string(total));
    });
    for (std::size_t m = 0; m < nm; ++m) {
      MethodSummary summary;
      summary.method = options.methods[m];
      summary.tested = static_cast<int>(stable.size());
      for (const RobotGrasp& r : res.transfers[m]) summary.stable += r.stable() ? 1 : 0;
      res.methods.push_back(summary);
    }
    results.push_back(std::move(res));
  }
  return results;
}

}  // namespace topograsp

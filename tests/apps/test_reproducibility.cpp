// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <map>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/results.hpp>

using namespace topograsp;

namespace {

ExperimentOptions options(std::vector<GraspObject> objects) {
  ExperimentOptions c;
  c.objects = std::move(objects);
  c.methods = {TransferMethod::topological, TransferMethod::transplant};
  c.jobs = 2;
  c.seed = 3;
  c.max_hypotheses = 4;  // small: the sanitizer build runs this too
  return c;
}

// The records of results.json by (object, method, id), plan_ms left out (a time), each with the
// shake test's measured numbers, which depend on the seed even where the verdict does not.
std::map<std::string, std::string> records(const ExperimentOptions& c,
                                           const std::vector<ObjectResult>& results) {
  std::map<std::string, std::string> out;
  Json doc = results_json(c, results);
  for (const Json& g : doc.at("grasps").as_array()) {
    Json r = g;
    r.set("plan_ms", 0.0);
    const std::string key = g.at("object").as_string() + "/" + g.at("method").as_string() + "/" +
                            std::to_string(static_cast<int>(g.at("id").as_number()));
    out[key] = r.dump(0);
  }
  const auto shake = [](const StabilityResult& s) {
    std::string text;
    for (const StabilityRecord& t : s.tests)
      text += std::to_string(t.translation) + " " + std::to_string(t.rotation) + " " +
              std::to_string(t.force_end) + " " + std::to_string(t.contacts) + " ";
    return text;
  };
  for (const ObjectResult& r : results) {
    for (const HumanGrasp& g : r.human)
      out[r.object.name + "/human/" + std::to_string(g.id)] += " shake " + shake(g.stability);
    for (std::size_t m = 0; m < r.transfers.size(); ++m)
      for (std::size_t k = 0; k < r.transfers[m].size(); ++k)
        out[r.object.name + "/" + std::string(to_string(r.methods[m].method)) + "/" +
            std::to_string(r.transferred_ids[k])] += " shake " + shake(r.transfers[m][k].stability);
  }
  return out;
}

std::map<std::string, std::string> of_object(const std::map<std::string, std::string>& all,
                                             const std::string& object) {
  std::map<std::string, std::string> out;
  for (const auto& [key, value] : all)
    if (key.rfind(object + "/", 0) == 0) out.emplace(key, value);
  return out;
}

}  // namespace

TEST_CASE("a grasp's seed depends on what it is, not where it is", "[grasp][experiment]") {
  CHECK(detail::fnv1a_64("") == 0xcbf29ce484222325ull);  // the FNV-1a test vectors
  CHECK(detail::fnv1a_64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(grasp_seed(1, "bottle", 3) != grasp_seed(1, "hammer", 3));
  CHECK(grasp_seed(1, "bottle", 3) != grasp_seed(1, "bottle", 4));
  CHECK(grasp_seed(1, "bottle", 3) != grasp_seed(2, "bottle", 3));
}

TEST_CASE("any split of a run reproduces the whole", "[grasp][experiment][end_to_end]") {
  const ExperimentOptions both = options({objects::hammer(), objects::bottle()});
  const auto whole = records(both, run_experiment(both));
  const auto bottle_records = of_object(whole, "bottle");
  REQUIRE(bottle_records.size() > 4);  // the demonstrations and some transfers

  SECTION("{bottle} alone gives exactly the bottle records of {hammer, bottle}") {
    const ExperimentOptions alone = options({objects::bottle()});
    CHECK(records(alone, run_experiment(alone)) == bottle_records);
  }
  SECTION("the shards 1/2 and 2/2 together give exactly the records of the whole run") {
    std::map<std::string, std::string> joined;
    for (int k = 0; k < 2; ++k) {
      ExperimentOptions shard = both;
      shard.shard_index = k;
      shard.shard_count = 2;
      shard.jobs = 1;
      for (auto& [key, value] : records(shard, run_experiment(shard))) {
        CHECK(joined.count(key) == 0);  // no record in both shards
        joined.emplace(key, value);
      }
    }
    CHECK(joined == whole);
  }
}

TEST_CASE("duplicate objects or methods are refused before any work", "[grasp][bad-input]") {
  ExperimentOptions c = options({objects::hammer(), objects::hammer()});
  CHECK_THROWS_WITH(run_experiment(c), "objects: \"hammer\" is given twice (each object once)");
  c = options({objects::hammer()});
  c.methods = {TransferMethod::transplant, TransferMethod::topological, TransferMethod::transplant};
  CHECK_THROWS_WITH(run_experiment(c), "methods: \"transplant\" is given twice (each method once)");
  c = options({objects::hammer()});
  c.transfer.backoff = 1e300;  // refused up front, by name, not after hours of planning
  CHECK_THROWS_WITH(run_experiment(c), Catch::StartsWith("backoff: must be in [0, 0.3]"));
  c = options({objects::hammer()});
  c.max_hypotheses = -1;
  CHECK_THROWS_WITH(run_experiment(c), Catch::StartsWith("max_hypotheses"));
}

namespace {
// Starts real threads for the first `allowed` calls, then throws as std::thread does when the
// system has no more (EAGAIN).
struct LimitedThreads {
  int allowed;
  std::atomic<int>* started;
  template <class F>
  std::thread operator()(F&& f) const {
    if (started->load() >= allowed)
      throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again),
                              "thread creation");
    ++*started;
    return std::thread(std::forward<F>(f));
  }
};
}  // namespace

TEST_CASE("a failed thread start runs the work on the threads that started",
          "[grasp][experiment][bad-input]") {
  for (const int allowed : {0, 1, 3}) {
    INFO("threads that can start: " << allowed);
    std::atomic<int> started{0};
    std::vector<std::atomic<int>> hits(200);
    std::string error;
    const int ran = detail::parallel_for(
        200, 72, [&](int i) { ++hits[static_cast<std::size_t>(i)]; },
        LimitedThreads{allowed, &started}, &error);
    CHECK(ran == allowed + 1);  // the calling thread always works
    CHECK_THAT(error, Catch::Contains("thread creation"));
    for (const std::atomic<int>& h : hits) CHECK(h.load() == 1);  // each index once
  }
  SECTION("a body's exception still reaches the caller, every thread joined") {
    std::atomic<int> started{0};
    CHECK_THROWS_WITH(detail::parallel_for(
                          50, 8,
                          [](int i) {
                            if (i == 17) throw std::runtime_error("body 17");
                          },
                          LimitedThreads{2, &started}),
                      "body 17");
  }
  SECTION("run_experiment says so once, and its results are those of a full start") {
    ExperimentOptions c = options({objects::can()});
    c.max_hypotheses = 2;
    c.jobs = 4;
    std::vector<std::string> lines;
    std::atomic<int> started{0};
    const auto limited = detail::run_experiment_with<models::schunk_sdh>(
        c, [&](std::string_view line) { lines.emplace_back(line); }, {}, {},
        LimitedThreads{0, &started});
    const auto warnings = std::count_if(lines.begin(), lines.end(), [](const std::string& l) {
      return l.rfind("warning: could start only 1 of 2 threads", 0) == 0;
    });
    CHECK(warnings == 1);
    CHECK(records(c, limited) == records(c, run_experiment(c)));
  }
}

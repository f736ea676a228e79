// SPDX-License-Identifier: BSD-3-Clause
// Runs that scale out: the shards of a run merged (merge_results) and a run resumed from its
// journal (ResultsJournal, read_journal) give the results.json of the whole run.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/results.hpp>

using namespace topograsp;

namespace {

// Eight hypotheses of each object; with seed 3 the bottle's 0 and 6 are stable demonstrations,
// so the methods' paired summaries are exercised.
ExperimentOptions eight_hypotheses() {
  ExperimentOptions c;
  c.objects = {objects::hammer(), objects::bottle()};
  c.methods = {TransferMethod::topological, TransferMethod::transplant};
  c.jobs = 1;
  c.seed = 3;
  c.max_hypotheses = 8;
  return c;
}

// A results.json's text with the timings ("plan_ms") set to 0.
std::string without_timings(Json doc) {
  Json::Array grasps = doc.at("grasps").as_array();
  for (Json& g : grasps) g.set("plan_ms", 0.0);
  doc.set("grasps", Json(std::move(grasps)));
  return doc.dump(0);
}

// A fresh folder for the test's files.
std::filesystem::path scratch_folder(const std::string& name) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() /
                                  ("topograsp_test_" + name + "_" + detail::temporary_file_token());
  std::filesystem::create_directories(p);
  return p;
}

}  // namespace

TEST_CASE("the merged shards of a run give the results.json of the whole run",
          "[grasp][experiment][merge][end_to_end]") {
  const ExperimentOptions whole = eight_hypotheses();
  const Json expected = results_json(whole, run_experiment(whole));
  REQUIRE(expected.at("objects").as_array()[1].at("stable_human").as_number() == 2.0);
  std::vector<Json> shards;
  for (const int k : {1, 0}) {  // any order
    ExperimentOptions shard = whole;
    shard.shard_index = k;
    shard.shard_count = 2;
    shards.push_back(Json::parse(results_json(shard, run_experiment(shard)).dump(2)));
  }
  const Json merged = merge_results(shards);
  CHECK(merged.at("config").at("shard").as_string() == "1/1");
  CHECK(without_timings(merged) == without_timings(expected));

  SECTION("a shard missing, given twice, of another split or of another run is refused") {
    CHECK_THROWS_WITH(merge_results({shards[0]}), "shards: shard 1/2 is missing");
    CHECK_THROWS_WITH(merge_results({shards[0], shards[0]}), "shards: shard 2/2 is given twice");
    Json other = shards[1];
    Json config = other.at("config");
    config.set("seed", "4");
    other.set("config", config);
    CHECK_THROWS_WITH(merge_results({shards[0], other}),
                      Catch::StartsWith("shards: the shards were run with different \"seed\""));
    config = shards[1].at("config");
    config.set("hand", "allegro_hand");  // a shard of grasp_transfer --hand allegro
    other.set("config", config);
    CHECK_THROWS_WITH(merge_results({shards[0], other}),
                      Catch::StartsWith("shards: the shards were run with different \"hand\""));
    config = shards[1].at("config");
    config.set("shard", "1/3");
    other.set("config", config);
    CHECK_THROWS_WITH(merge_results({shards[0], other}), "shards: shards of 2 and of 3 parts");
    config.set("shard", "two");
    other.set("config", config);
    CHECK_THROWS_WITH(merge_results({shards[0], other}), Catch::Contains("is not K/N"));
    CHECK_THROWS_WITH(merge_results({}), "shards: expected at least one");
    CHECK_THROWS_WITH(merge_results({Json::object()}), Catch::Contains("results.json files"));
  }
}

TEST_CASE("a run resumed from its journal gives the results.json of the whole run",
          "[grasp][experiment][resume][end_to_end]") {
  const ExperimentOptions whole = eight_hypotheses();
  const Json expected = results_json(whole, run_experiment(whole));
  const std::filesystem::path dir = scratch_folder("resume");
  const Json config = results_config(whole);

  // The first run fails after five hypotheses were journalled (a full disk, say).
  {
    ResultsJournal journal(dir / journal_file_name, config);
    int done = 0;
    const HypothesisDoneFn on_done = [&](const GraspObject& object, const HumanGrasp& g,
                                         const std::vector<SdhTransfer>& transfers) {
      if (done == 5) throw std::runtime_error("disk full");
      std::vector<const SdhTransfer*> ts;
      for (const SdhTransfer& t : transfers) ts.push_back(&t);
      journal.append({object.name, g.id, hypothesis_records(whole, object, g, ts)});
      ++done;
    };
    CHECK_THROWS_WITH(run_experiment(whole, {}, on_done), "disk full");
  }
  // A sixth line cut off by the kill: not read.
  {
    std::ofstream f(dir / journal_file_name, std::ios::app | std::ios::binary);
    f << "{\"object\": \"hammer\", \"id\": 7, \"rec";
  }
  const std::vector<JournalEntry> entries = read_journal(dir / journal_file_name, config);
  REQUIRE(entries.size() == 5);

  // The second run skips them and runs the rest; its document takes their records.
  ExperimentOptions rest = whole;
  std::vector<ObjectRecords> earlier;
  for (const JournalEntry& e : entries) {
    rest.skip.emplace_back(e.object, e.id);
    if (earlier.empty() || earlier.back().name != e.object) earlier.push_back({e.object, 0, {}});
    ++earlier.back().hypotheses;
    earlier.back().grasps.insert(earlier.back().grasps.end(), e.records.begin(), e.records.end());
  }
  const std::vector<ObjectResult> results = run_experiment(rest);
  CHECK(results[0].hypotheses + results[1].hypotheses == 16 - 5);
  CHECK(without_timings(results_json(rest, results, earlier)) == without_timings(expected));

  SECTION("a journal of other options is refused, naming the option; --jobs may differ") {
    ExperimentOptions other = whole;
    other.jobs = 2;
    CHECK(read_journal(dir / journal_file_name, results_config(other)).size() == 5);
    other.seed = 4;
    CHECK_THROWS_WITH(read_journal(dir / journal_file_name, results_config(other)),
                      Catch::StartsWith("--resume: ") && Catch::Contains("another \"seed\"") &&
                          Catch::Contains("(\"3\" there, \"4\" now)"));
    // A journal of another hand (grasp_transfer --hand) is refused the same way.
    CHECK_THROWS_WITH(read_journal(dir / journal_file_name, results_config(whole, "leap_hand")),
                      Catch::StartsWith("--resume: ") && Catch::Contains("another \"hand\""));
    std::ofstream(dir / "not_a_journal.jsonl") << "[1, 2]\n";
    CHECK_THROWS_WITH(read_journal(dir / "not_a_journal.jsonl", config),
                      Catch::Contains("does not start with a config"));
    CHECK_THROWS_WITH(read_journal(dir / "missing.jsonl", config),
                      Catch::StartsWith("--resume: cannot read"));
  }
  SECTION("a skipped hypothesis of an object not in the run is refused") {
    ExperimentOptions bad = whole;
    bad.skip.emplace_back("teapot", 1);
    CHECK_THROWS_WITH(run_experiment(bad),
                      "skip: object \"teapot\" (hypothesis 1) is not in the run");
  }
  std::filesystem::remove_all(dir);
}

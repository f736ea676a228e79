// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The summaries of results.json, each computed from grasp records (so that the records of a
/// run's shards, or of a resumed run, give the same summaries as one whole run): a set of
/// grasps' stability, the second judge's agreement, and McNemar's test of a method against the
/// topological method on the same demonstrations.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/evaluation/stability_suite.hpp>
#include <topograsp/evaluation/statistics.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp::detail {

// A rate's 95 % Wilson interval as [lower, upper].
inline Json json_interval(int successes, int trials) {
  const RateInterval i = wilson_interval(successes, trials);
  Json::Array a;
  a.emplace_back(i.lower);
  a.emplace_back(i.upper);
  return Json(std::move(a));
}

// A grasp record's verdict by the engine that decided, and by the second judge (false without
// one).
inline bool record_stable(const Json& rec) { return rec.at("stable").as_bool(); }
inline bool record_stable_second(const Json& rec) {
  const Json& j = rec.at("second_judge");
  return !j.is_null() && j.at("stable").as_bool();
}

// The records' second-judge summary: each engine's stable count over the grasps with both
// verdicts, the second engine's rate over the \p tested grasps (those judged by neither count as
// failing) with its Wilson interval, and how often the engines agree: over all judged grasps, and
// over those whose colliders were both exact to k_collider_tolerance when the tests began. Null
// when no grasp has a second verdict.
inline Json agreement_summary(const std::vector<const Json*>& records, int tested) {
  int judged = 0, first = 0, second = 0, agree = 0, exact = 0, agree_exact = 0;
  std::string engine;
  for (const Json* rec : records) {
    const Json& j = rec->at("second_judge");
    if (j.is_null()) continue;
    engine = j.at("engine").as_string();
    const bool a = record_stable(*rec), b = j.at("stable").as_bool();
    const bool e = std::max(rec->at("collider_error").as_number(),
                            j.at("collider_error").as_number()) <= k_collider_tolerance;
    ++judged;
    first += a ? 1 : 0;
    second += b ? 1 : 0;
    agree += a == b ? 1 : 0;
    exact += e ? 1 : 0;
    agree_exact += e && a == b ? 1 : 0;
  }
  if (judged == 0) return Json();
  Json s = Json::object();
  s.set("engine", engine);
  s.set("judged", judged);
  s.set("stable_first", first);
  s.set("stable_second", second);
  s.set("rate_second", tested > 0 ? second / static_cast<double>(tested) : 0.0);
  s.set("interval_second", json_interval(second, tested));
  s.set("agreement", agree / static_cast<double>(judged));
  s.set("judged_exact", exact);
  s.set("agreement_exact", exact > 0 ? Json(agree_exact / static_cast<double>(exact)) : Json());
  return s;
}

// The median of v (0 values: null).
inline Json json_median(std::vector<double> v) { return v.empty() ? Json() : Json(median(v)); }

// The summary of a set of grasp records (one without tests - not simulated - counts in `tested`
// and fails): how many, how many stable, the rate and its Wilson interval, how many closings ended
// touching nothing (no_contact), each test's pass rate
// over the grasps that ran it (null if none did), the median
// over the stable ones of the paper shake's force ratio, and the second judge's summary.
inline Json stability_summary(const std::vector<const Json*>& records) {
  Json s = Json::object();
  const int n = static_cast<int>(records.size());
  int stable = 0, no_contact = 0;
  std::array<int, k_stability_tests> passed{}, run{};
  std::vector<double> ratios;
  for (const Json* rec : records) {
    const Json& closing = rec->at("closing");
    no_contact += closing.is_object() && closing.at("contacts").as_number() == 0.0 ? 1 : 0;
    const Json::Array& tests = rec->at("tests").as_array();
    if (tests.size() != k_stability_tests) continue;
    for (std::size_t i = 0; i < k_stability_tests; ++i) {
      if (tests[i].at("steps").as_number() <= 0.0) continue;
      ++run[i];
      passed[i] += tests[i].at("passed").as_bool() ? 1 : 0;
    }
    if (!record_stable(*rec)) continue;
    ++stable;
    const Json& ratio = tests[0].at("force_ratio");
    if (ratio.is_number()) ratios.push_back(ratio.as_number());
  }
  const auto rate = [n](int k) { return n > 0 ? static_cast<double>(k) / n : 0.0; };
  s.set("tested", n);
  s.set("stable", stable);
  s.set("rate", rate(stable));
  s.set("interval", json_interval(stable, n));
  s.set("no_contact", no_contact);
  Json tests = Json::object();
  for (std::size_t i = 0; i < k_stability_tests; ++i)
    tests.set(std::string(to_string(static_cast<StabilityTest>(i))),
              run[i] > 0 ? Json(static_cast<double>(passed[i]) / run[i]) : Json());
  s.set("test_pass_rate", tests);
  s.set("median_force_ratio_stable", json_median(std::move(ratios)));
  s.set("second_judge", agreement_summary(records, n));
  return s;
}

// The difference in success rate whose power every paired comparison reports (power_15).
inline constexpr double k_power_difference = 0.15;

// A method's records against the topological method's on the same grasps (both in id order):
// McNemar's exact test of the verdicts of the deciding engine or (\p second) the second judge,
// and its power to tell 15 points apart (mcnemar_exact_power).
inline Json paired_summary(const std::vector<const Json*>& records,
                           const std::vector<const Json*>& topological, bool second) {
  if (records.size() != topological.size())
    detail::throw_invalid_argument("grasps", "expected each method's transfers of the same " +
                                                 std::to_string(topological.size()) +
                                                 " demonstrations, got " +
                                                 std::to_string(records.size()));
  std::vector<bool> a, b;
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (records[i]->at("id").as_number() != topological[i]->at("id").as_number())
      detail::throw_invalid_argument("grasps",
                                     "expected each method's transfers of the same "
                                     "demonstrations");
    a.push_back(second ? record_stable_second(*records[i]) : record_stable(*records[i]));
    b.push_back(second ? record_stable_second(*topological[i]) : record_stable(*topological[i]));
  }
  const PairedComparison c = compare_paired(a, b);
  Json j = Json::object();
  j.set("against", "topological");
  j.set("both", c.both);
  j.set("only_this", c.only_first);
  j.set("only_against", c.only_second);
  j.set("neither", c.neither);
  j.set("p_value", c.p_value);
  // The power of the test on these pairs to tell the methods k_power_difference apart, at the
  // disagreement measured between them (at least that difference: a smaller one cannot hold it).
  const int pairs = c.both + c.only_first + c.only_second + c.neither;
  const double discordance =
      pairs > 0 ? static_cast<double>(c.only_first + c.only_second) / pairs : 0.0;
  j.set("power_15",
        mcnemar_exact_power(pairs, std::max(discordance, k_power_difference), k_power_difference));
  return j;
}

}  // namespace topograsp::detail

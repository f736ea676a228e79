// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// grasp_transfer --hands: every hand's rates side by side, from each hand's results.json.
/// hands_summary() gathers them into hands.json, hands_markdown() writes them as the tables of
/// hands.md (docs/transfer.md, "Several hands").
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/io/json.hpp>

namespace topograsp {

/// One hand's run of a --hands run: the hand's name (--hand), its results.json's path relative
/// to the run's folder, and the document.
struct HandRun {
  std::string hand;
  std::string results;
  Json doc;
};

/// hands.json: {"generator": "topograsp grasp_transfer --hands", "schema_version": 1,
/// "hands": [{"hand", "model" (config.hand), "results" (the path), "config" (the run's, of its
/// results.json), "demonstrations" (overall.demonstrations: hypotheses, stable, distinct, in both
/// engines), "methods" (overall.methods: each method's counts, Wilson intervals, the second
/// judge's, and the paired comparisons with the topological method, as results.json has them)},
/// ...]} in the order of \p runs.
/// \throws topograsp::invalid_argument naming the hand and the field for a document that is not
/// a results.json of grasp_transfer (no "config", "overall" with "methods").
[[nodiscard]] inline Json hands_summary(const std::vector<HandRun>& runs) {
  Json hands = Json::array();
  for (const HandRun& r : runs) {
    const auto need = [&](const Json& o, const char* key, const char* where) -> const Json& {
      if (!o.is_object() || !o.contains(key))
        throw invalid_argument("--hands: " + r.hand + ": " + r.results + ": " + where + key +
                               ": missing (not a results.json of grasp_transfer)");
      return o.at(key);
    };
    const Json& overall = need(r.doc, "overall", "");
    Json h = Json::object();
    h.set("hand", r.hand);
    h.set("model", need(need(r.doc, "config", ""), "hand", "config."));
    h.set("results", r.results);
    h.set("config", r.doc.at("config"));
    h.set("demonstrations", need(overall, "demonstrations", "overall."));
    h.set("methods", need(overall, "methods", "overall."));
    hands.push_back(std::move(h));
  }
  Json doc = Json::object();
  doc.set("generator", "topograsp grasp_transfer --hands");
  doc.set("schema_version", 1);
  doc.set("hands", std::move(hands));
  return doc;
}

namespace detail {

// "28/33 = 85 % [69, 93]": a count of a number with its Wilson interval, "-" for none tested.
inline std::string hands_rate(const Json& stable, const Json& tested, const Json& interval) {
  if (!tested.is_number() || tested.as_number() == 0.0 || !interval.is_array()) return "-";
  char buf[80];
  std::snprintf(buf, sizeof buf, "%.0f/%.0f = %.0f %% [%.0f, %.0f]", stable.as_number(),
                tested.as_number(), 100.0 * stable.as_number() / tested.as_number(),
                100.0 * interval.as_array()[0].as_number(),
                100.0 * interval.as_array()[1].as_number());
  return buf;
}

// "1 : 0, p = 1": a paired comparison with the topological method (held by this method only :
// by the topological method only, McNemar's exact p); "" where there is none.
inline std::string hands_paired(const Json& m, const char* key) {
  if (!m.contains(key) || !m.at(key).is_object()) return "";
  const Json& c = m.at(key);
  char buf[64];
  std::snprintf(buf, sizeof buf, "; %.0f : %.0f, p = %.2g", c.at("only_this").as_number(),
                c.at("only_against").as_number(), c.at("p_value").as_number());
  return buf;
}

}  // namespace detail

/// hands.md: the tables of \p summary (hands_summary): one row per hand, one column per method,
/// each cell the built-in count and rate with its 95 % interval and its paired comparison with
/// the topological method (held by this method only : by the topological method only, McNemar's
/// exact p), then the second judge's; then the same on one demonstration per distinct grasp.
[[nodiscard]] inline std::string hands_markdown(const Json& summary) {
  const auto& hands = summary.at("hands").as_array();
  std::vector<std::string> methods;
  for (const Json& h : hands)
    for (const auto& [m, v] : h.at("methods").as_object()) {
      (void)v;
      bool seen = false;
      for (const std::string& n : methods) seen = seen || n == m;
      if (!seen) methods.push_back(m);
    }
  std::string header = "| hand | demonstrations |", rule = "| --- | --- |";
  for (const std::string& m : methods) {
    header += " " + m + " |";
    rule += " --- |";
  }
  const auto table = [&](bool distinct) {
    std::string t = header + "\n" + rule + "\n";
    for (const Json& h : hands) {
      const Json& d = h.at("demonstrations");
      t += "| " + h.at("hand").as_string() + " (" + h.at("model").as_string() + ") | " +
           (distinct ? d.at("distinct").dump(0) : d.at("stable").dump(0)) + " |";
      for (const std::string& name : methods) {
        const Json& all = h.at("methods");
        if (!all.contains(name)) {
          t += " - |";
          continue;
        }
        const Json& m = all.at(name);
        std::string cell(1, '-');  // (assigning "-" trips GCC 12's false -Wrestrict)
        if (!distinct) {
          cell = detail::hands_rate(m.at("stable"), m.at("tested"), m.at("interval")) +
                 detail::hands_paired(m, "paired");
          if (m.contains("second_judge") && m.at("second_judge").is_object()) {
            const Json& s = m.at("second_judge");
            cell +=
                "<br>" + s.at("engine").as_string() + ": " +
                detail::hands_rate(s.at("stable_second"), m.at("tested"), s.at("interval_second")) +
                detail::hands_paired(m, "paired_second");
          }
        } else if (m.contains("distinct") && m.at("distinct").is_object()) {
          const Json& c = m.at("distinct");
          cell = detail::hands_rate(c.at("stable"), c.at("tested"), c.at("interval")) +
                 detail::hands_paired(m, "paired_distinct");
        }
        t += " " + cell + " |";
      }
      t += "\n";
    }
    return t;
  };
  return "Stable transfers of the stable demonstrations (built-in stepper, then the second "
         "judge), with 95 % Wilson intervals; against the topological method on the same "
         "grasps: held by this method only : by the topological method only, McNemar's exact "
         "p.\n\n" +
         table(false) +
         "\nThe same on one demonstration per distinct grasp (built-in stepper).\n\n" + table(true);
}

}  // namespace topograsp

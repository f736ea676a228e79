// SPDX-License-Identifier: BSD-3-Clause
// A Google Benchmark main that also prints, for every benchmark named "<case>/<implementation>",
// how many times slower each peer implementation is than "<case>/topograsp", from the same run.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace topograsp::bench {

/// Console output as usual, plus a table of ratios against topograsp at the end.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration || run.error_occurred) continue;
      const std::string name = run.benchmark_name();
      const std::size_t slash = name.rfind('/');
      if (slash == std::string::npos) continue;
      times_[name.substr(0, slash)][name.substr(slash + 1)] =
          run.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(run.time_unit) * 1e9;
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void print_ratios() const {
    bool header = false;
    for (const auto& [name, impls] : times_) {
      const auto ours = impls.find("topograsp");
      if (ours == impls.end()) continue;
      for (const auto& [impl, ns] : impls) {
        if (impl == "topograsp") continue;
        if (!header) {
          std::printf("\n%-44s %14s %14s %9s\n", "case", "topograsp (ns)", "peer (ns)",
                      "peer/ours");
          header = true;
        }
        std::printf("%-44s %14.1f %14.1f %8.2fx  (%s)\n", name.c_str(), ours->second, ns,
                    ns / ours->second, impl.c_str());
      }
    }
  }

 private:
  std::map<std::string, std::map<std::string, double>> times_;
};

/// Runs the registered benchmarks with the ratio table; use as the body of main().
inline int run_with_ratios(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}

}  // namespace topograsp::bench

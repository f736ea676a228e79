// SPDX-License-Identifier: BSD-3-Clause
// The Wilson interval against Newcombe's published examples, McNemar's exact test against exact
// binomial sums and its power against a sum over every outcome, and what they do with bad input;
// Cohen's kappa; the median.
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <topograsp/evaluation/statistics.hpp>

using namespace topograsp;

TEST_CASE("the Wilson interval matches Newcombe's worked examples", "[evaluation][statistics]") {
  // R. G. Newcombe, Two-sided confidence intervals for the single proportion: comparison of seven
  // methods, Statistics in Medicine 17 (1998) 857-872, Table I, method 3 (score, no correction).
  struct Case {
    int successes, trials;
    double lower, upper;
  };
  for (const Case c : {Case{81, 263, 0.2553, 0.3662}, Case{15, 148, 0.0624, 0.1605},
                       Case{0, 20, 0.0, 0.1611}, Case{1, 29, 0.0061, 0.1718}}) {
    const RateInterval i = wilson_interval(c.successes, c.trials);
    CHECK(i.lower == Approx(c.lower).margin(5e-5));
    CHECK(i.upper == Approx(c.upper).margin(5e-5));
  }
}

TEST_CASE("the Wilson interval is symmetric, inside [0, 1], and exact at the ends",
          "[evaluation][statistics]") {
  const RateInterval half = wilson_interval(5, 10);
  CHECK(half.lower == Approx(0.236593090512564).margin(1e-12));
  CHECK(half.upper == Approx(1.0 - 0.236593090512564).margin(1e-12));
  const RateInterval all = wilson_interval(13, 13), none = wilson_interval(0, 13);
  CHECK(all.upper == 1.0);
  CHECK(none.lower == 0.0);
  CHECK(all.lower == Approx(1.0 - none.upper).margin(1e-12));
  CHECK(all.lower == Approx(0.7719046276458016).margin(1e-12));
  // A wider quantile gives a wider interval; no trials, nothing known.
  const RateInterval wide = wilson_interval(5, 10, 2.576);
  CHECK(wide.lower < half.lower);
  CHECK(wide.upper > half.upper);
  const RateInterval unknown = wilson_interval(0, 0);
  CHECK(unknown.lower == 0.0);
  CHECK(unknown.upper == 1.0);
}

TEST_CASE("the Wilson interval refuses counts that are not a rate", "[evaluation][statistics]") {
  CHECK_THROWS_WITH(wilson_interval(0, -1), Catch::Contains("trials") && Catch::Contains(">= 0"));
  CHECK_THROWS_WITH(wilson_interval(11, 10), Catch::Contains("successes"));
  CHECK_THROWS_WITH(wilson_interval(-1, 10), Catch::Contains("successes"));
  CHECK_THROWS_WITH(wilson_interval(1, 10, 0.0), Catch::Contains("z"));
  CHECK_THROWS_AS(wilson_interval(1, 10, std::numeric_limits<double>::quiet_NaN()),
                  invalid_argument);
}

TEST_CASE("McNemar's exact test is the two-sided binomial tail of the discordant pairs",
          "[evaluation][statistics]") {
  // Exact sums: 2 (1 + 10) / 2^10, 2 / 2^5; 3 against 3 is no evidence at all.
  CHECK(mcnemar_exact_p(1, 9) == Approx(0.021484375).epsilon(1e-12));
  CHECK(mcnemar_exact_p(9, 1) == Approx(0.021484375).epsilon(1e-12));
  CHECK(mcnemar_exact_p(0, 5) == Approx(0.0625).epsilon(1e-12));
  CHECK(mcnemar_exact_p(3, 3) == 1.0);
  CHECK(mcnemar_exact_p(0, 0) == 1.0);
  // Large counts (exact sums in rational arithmetic, computed apart): no overflow or underflow.
  CHECK(mcnemar_exact_p(100, 150) == Approx(0.001883300935076157).epsilon(1e-9));
  CHECK(mcnemar_exact_p(2000, 2200) == Approx(0.0021323556719912346).epsilon(1e-7));
  CHECK_THROWS_WITH(mcnemar_exact_p(-1, 3), Catch::Contains("only_first"));
  CHECK_THROWS_WITH(mcnemar_exact_p(3, -1), Catch::Contains("only_second"));
}

TEST_CASE("McNemar's power is the chance that the test rejects, summed over every outcome",
          "[evaluation][statistics]") {
  // Every outcome of n pairs: b pairs only the better method holds, c only the other, with
  // trinomial probabilities; the power is the mass of those the test itself rejects.
  const auto enumerated = [](int n, double discordance, double difference, double alpha) {
    const double pb = (discordance + difference) / 2.0, pc = (discordance - difference) / 2.0;
    double power = 0.0;
    for (int b = 0; b <= n; ++b)
      for (int c = 0; b + c <= n; ++c) {
        if (mcnemar_exact_p(b, c) > alpha) continue;
        const double log_count = std::lgamma(n + 1.0) - std::lgamma(b + 1.0) -
                                 std::lgamma(c + 1.0) - std::lgamma(n - b - c + 1.0);
        power += std::exp(log_count + b * std::log(pb) + (c > 0 ? c * std::log(pc) : 0.0) +
                          (n - b - c) * std::log1p(-pb - pc));
      }
    return power;
  };
  for (const int n : {1, 7, 25, 40})
    for (const auto& [d, delta] :
         {std::pair{0.17, 0.15}, std::pair{0.4, 0.1}, std::pair{0.3, 0.0}}) {
      CAPTURE(n, d, delta);
      CHECK(mcnemar_exact_power(n, d, delta) ==
            Approx(enumerated(n, d, delta, 0.05)).margin(1e-12));
      CHECK(mcnemar_exact_power(n, d, delta, 0.01) ==
            Approx(enumerated(n, d, delta, 0.01)).margin(1e-12));
    }
  // No difference: the exact test's size, at most alpha; a difference grows with the pairs.
  for (const int n : {10, 70, 300}) CHECK(mcnemar_exact_power(n, 0.2, 0.0) <= 0.05);
  CHECK(mcnemar_exact_power(30, 0.17, 0.15) < 0.5);
  CHECK(mcnemar_exact_power(300, 0.17, 0.15) > 0.999);
  // Every discordant pair one way: only the count of discordant pairs is random.
  CHECK(mcnemar_exact_power(20, 0.5, 0.5) > mcnemar_exact_power(20, 0.5, 0.4));
  CHECK(mcnemar_exact_power(0, 0.2, 0.1) == 0.0);
  CHECK(mcnemar_exact_power(50, 0.0, 0.0) == 0.0);
  // Bad input is named.
  CHECK_THROWS_WITH(mcnemar_exact_power(-1, 0.2, 0.1), Catch::Contains("pairs"));
  CHECK_THROWS_WITH(mcnemar_exact_power(10, 1.5, 0.1), Catch::Contains("discordance"));
  CHECK_THROWS_WITH(mcnemar_exact_power(10, std::nan(""), 0.1), Catch::Contains("discordance"));
  CHECK_THROWS_WITH(mcnemar_exact_power(10, 0.2, -0.1), Catch::Contains("difference"));
  CHECK_THROWS_WITH(mcnemar_exact_power(10, 0.1, 0.2), Catch::Contains("at most the discordance"));
  CHECK_THROWS_WITH(mcnemar_exact_power(10, 0.2, 0.1, 0.0), Catch::Contains("alpha"));
  CHECK_THROWS_WITH(mcnemar_exact_power(10, 0.2, 0.1, 1.0), Catch::Contains("alpha"));
}

TEST_CASE("a paired comparison counts the four kinds of pair", "[evaluation][statistics]") {
  const std::vector<bool> a{true, true, false, false, true, true, true, true, true, true};
  const std::vector<bool> b{true, false, true, false, false, false, false, false, false, false};
  const PairedComparison c = compare_paired(a, b);
  CHECK(c.both == 1);
  CHECK(c.only_first == 7);
  CHECK(c.only_second == 1);
  CHECK(c.neither == 1);
  CHECK(c.p_value == Approx(mcnemar_exact_p(7, 1)));
  CHECK(c.p_value == Approx(2.0 * 9.0 / 256.0));
  CHECK_THROWS_WITH(compare_paired(a, {true}), Catch::Contains("as many outcomes"));
}

TEST_CASE("Cohen's kappa is agreement beyond chance", "[evaluation][statistics]") {
  // The textbook case: 50 items, 20 yes-yes, 5 yes-no, 10 no-yes, 15 no-no: observed agreement
  // 0.7, chance 0.5 (first judge 25 yes, second 30), kappa 0.4.
  CHECK(cohen_kappa({20, 5, 10, 15, 1.0}) == Approx(0.4));
  CHECK(cohen_kappa({12, 0, 0, 30, 1.0}) == Approx(1.0));  // perfect agreement
  // Independent judges (a product table): 0; always disagreeing: negative.
  CHECK(cohen_kappa({6, 14, 9, 21, 1.0}) == Approx(0.0).margin(1e-12));
  CHECK(cohen_kappa({0, 10, 10, 0, 1.0}) == Approx(-1.0));
  // Undefined: no grasps, or both judges giving every grasp the same verdict.
  CHECK(std::isnan(cohen_kappa({})));
  CHECK(std::isnan(cohen_kappa({7, 0, 0, 0, 1.0})));
  // One judge constant, the other not: chance agreement equals observed, kappa 0.
  CHECK(cohen_kappa({3, 0, 5, 0, 1.0}) == Approx(0.0).margin(1e-12));
}

TEST_CASE("the median is the middle value, or the mean of the two middle ones",
          "[evaluation][statistics]") {
  std::vector<double> odd{5.0, 1.0, 3.0};
  CHECK(median(odd) == 3.0);
  std::vector<double> even{4.0, 1.0, 3.0, 2.0};
  CHECK(median(even) == 2.5);
  std::vector<double> none;
  CHECK(std::isnan(median(none)));
}

// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The statistics of a success rate and of a paired comparison, as Table I reports them: the
/// Wilson score interval of a rate, and McNemar's exact test of two methods judged on the same
/// grasps and its power; Cohen's kappa of two judges; and the median of a sample. See
/// docs/evaluation.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <topograsp/core/error.hpp>

namespace topograsp {

/// The normal quantile of a two-sided 95 % interval (z with P(|Z| <= z) = 0.95).
inline constexpr double z_95 = 1.959963984540054;

/// The median of \p values: the middle value, or the mean of the two middle ones for an even
/// count; NaN for none. Reorders \p values; allocates nothing.
[[nodiscard]] inline double median(std::span<double> values) noexcept {
  const std::size_t n = values.size();
  if (n == 0) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(values.begin(), mid, values.end());
  const double hi = *mid;
  if (n % 2 == 1) return hi;
  const double lo = *std::max_element(values.begin(), mid);
  return 0.5 * (lo + hi);
}

/// A closed interval [lower, upper] of a rate, both in [0, 1].
struct RateInterval {
  double lower = 0.0;
  double upper = 1.0;
};

/// The Wilson score interval of \p successes out of \p trials at the normal quantile \p z (the
/// default: 95 %). Unlike the normal approximation (the rate plus or minus z standard errors) it
/// stays inside [0, 1] and keeps its coverage near 0 % and 100 % and for small samples, which is
/// why it is used for success rates of tens of grasps. 0 trials give [0, 1] (nothing is known).
/// \throws topograsp::invalid_argument for trials < 0, successes outside [0, trials], or z not
/// finite and > 0.
[[nodiscard]] inline RateInterval wilson_interval(int successes, int trials, double z = z_95) {
  if (trials < 0) detail::throw_invalid_argument("trials", "expected >= 0");
  if (successes < 0 || successes > trials)
    detail::throw_invalid_argument(
        "successes", "expected a count in [0, trials = " + std::to_string(trials) + "]");
  if (!(std::isfinite(z) && z > 0.0)) detail::throw_invalid_argument("z", "expected finite, > 0");
  if (trials == 0) return {};
  const double n = trials, p = successes / n, z2 = z * z;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = z / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  // At 0 or all successes one end is exactly 0 or 1 (rounding would leave 1e-17).
  return {successes == 0 ? 0.0 : std::max(0.0, centre - half),
          successes == trials ? 1.0 : std::min(1.0, centre + half)};
}

/// The two-sided p-value of McNemar's exact test for \p only_first pairs where only the first
/// method succeeded and \p only_second where only the second did (the discordant pairs; pairs
/// where both or neither succeeded carry no information about the difference). Under the null
/// hypothesis of equal success probabilities each discordant pair goes either way with
/// probability 1/2: p = min(1, 2 P(X <= min(b, c))) for X ~ Binomial(b + c, 1/2). No discordant
/// pairs give 1.
/// \throws topograsp::invalid_argument for a negative count.
[[nodiscard]] inline double mcnemar_exact_p(int only_first, int only_second) {
  if (only_first < 0) detail::throw_invalid_argument("only_first", "expected >= 0");
  if (only_second < 0) detail::throw_invalid_argument("only_second", "expected >= 0");
  const int n = only_first + only_second, k = std::min(only_first, only_second);
  if (n == 0) return 1.0;
  // P(X = i) in logs, summed from the largest term down so that no term underflows first.
  const auto log_pmf = [n](int i) {
    return std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) -
           n * std::log(2.0);
  };
  const double top = log_pmf(k);
  double sum = 0.0;
  for (int i = 0; i <= k; ++i) sum += std::exp(log_pmf(i) - top);
  return std::min(1.0, 2.0 * std::exp(top) * sum);
}

/// The power of McNemar's exact test (mcnemar_exact_p, two-sided, rejecting at p <= \p alpha) to
/// tell two methods apart on \p pairs grasps when they disagree on a fraction \p discordance of
/// the grasps and their success rates differ by \p difference: the probability that the test
/// rejects when, per grasp, only the better method succeeds with probability
/// (discordance + difference) / 2 and only the other with (discordance - difference) / 2. Summed
/// exactly over the number of discordant pairs D ~ Binomial(pairs, discordance) and the split of
/// each D, with the test's own rejection region per D; O(pairs^2). Like every exact test's, it is
/// not monotone in \p pairs (a saw-tooth around the smooth curve), and at difference 0 it is the
/// test's size, at most alpha.
/// \throws topograsp::invalid_argument for pairs < 0, discordance or difference outside [0, 1],
/// difference > discordance (more difference than disagreement is impossible), or alpha outside
/// (0, 1).
[[nodiscard]] inline double mcnemar_exact_power(int pairs, double discordance, double difference,
                                                double alpha = 0.05) {
  if (pairs < 0) detail::throw_invalid_argument("pairs", "expected >= 0");
  if (!(discordance >= 0.0 && discordance <= 1.0))
    detail::throw_invalid_argument("discordance", "expected a fraction in [0, 1]");
  if (!(difference >= 0.0 && difference <= 1.0))
    detail::throw_invalid_argument("difference", "expected a fraction in [0, 1]");
  if (difference > discordance)
    detail::throw_invalid_argument(
        "difference", "expected at most the discordance (" + std::to_string(discordance) +
                          "): two methods differ only where they disagree");
  if (!(alpha > 0.0 && alpha < 1.0))
    detail::throw_invalid_argument("alpha", "expected a level in (0, 1)");
  if (pairs == 0 || discordance == 0.0) return 0.0;
  // log C(n, i) + i log p + (n - i) log(1 - p), with 0 log 0 = 0.
  const auto log_binomial = [](int n, int i, double p) {
    const double a = i > 0 ? i * std::log(p) : 0.0;
    const double b = n - i > 0 ? (n - i) * std::log1p(-p) : 0.0;
    return std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + a + b;
  };
  const double better = std::min(1.0, (discordance + difference) / (2.0 * discordance));
  double power = 0.0;
  for (int d = 1; d <= pairs; ++d) {
    // The largest k with mcnemar_exact_p(k, d - k) <= alpha: the cumulative Binomial(d, 1/2)
    // tail, grown term by term (the p-value of min(b, c) = k is min(1, 2 P(X <= k))).
    int k = -1;
    double tail = 0.0;
    while (k + 1 < d - (k + 1)) {
      tail += std::exp(log_binomial(d, k + 1, 0.5));
      if (2.0 * tail > alpha) break;
      ++k;
    }
    if (k < 0) continue;
    // P(b <= k) + P(b >= d - k) for b ~ Binomial(d, better): either method's win rejects.
    double reject = 0.0;
    for (int i = 0; i <= k; ++i)
      reject += std::exp(log_binomial(d, i, better)) + std::exp(log_binomial(d, d - i, better));
    power += std::exp(log_binomial(pairs, d, discordance)) * reject;
  }
  return std::min(1.0, power);
}

/// Two methods judged on the same grasps: how often only one of them succeeded, and McNemar's
/// exact p-value of the difference.
struct PairedComparison {
  int both = 0;          ///< pairs where both succeeded
  int only_first = 0;    ///< pairs where only the first succeeded
  int only_second = 0;   ///< pairs where only the second succeeded
  int neither = 0;       ///< pairs where neither did
  double p_value = 1.0;  ///< McNemar's exact two-sided p-value (mcnemar_exact_p)
};

/// Compares the paired outcomes \p first[i] and \p second[i] (the same grasp, two methods).
/// \throws topograsp::invalid_argument if the two have different sizes.
[[nodiscard]] inline PairedComparison compare_paired(const std::vector<bool>& first,
                                                     const std::vector<bool>& second) {
  if (first.size() != second.size())
    detail::throw_invalid_argument("second", "expected as many outcomes as first (" +
                                                 std::to_string(first.size()) + "), got " +
                                                 std::to_string(second.size()));
  PairedComparison c;
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (first[i] && second[i]) ++c.both;
    if (first[i] && !second[i]) ++c.only_first;
    if (!first[i] && second[i]) ++c.only_second;
    if (!first[i] && !second[i]) ++c.neither;
  }
  c.p_value = mcnemar_exact_p(c.only_first, c.only_second);
  return c;
}

/// Cohen's kappa of two judges' verdicts on the same grasps (\p c: both, only_first, only_second,
/// neither): how far their agreement p_o = (both + neither) / n exceeds the agreement p_e that two
/// judges with the same stable rates would reach by chance, as a fraction of what could exceed
/// it: (p_o - p_e) / (1 - p_e). 1 is perfect agreement, 0 no better than chance, negative worse.
/// NaN where it is undefined: no grasps, or both judges giving every grasp one and the same
/// verdict (p_e = 1).
[[nodiscard]] inline double cohen_kappa(const PairedComparison& c) noexcept {
  const double n = static_cast<double>(c.both) + c.only_first + c.only_second + c.neither;
  if (!(n > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double first = (c.both + c.only_first) / n, second = (c.both + c.only_second) / n;
  const double observed = (c.both + c.neither) / n;
  const double chance = first * second + (1.0 - first) * (1.0 - second);
  if (!(chance < 1.0)) return std::numeric_limits<double>::quiet_NaN();
  return (observed - chance) / (1.0 - chance);
}

}  // namespace topograsp

// Summaries of a sample and comparisons of two, as a results table needs them: mean, standard
// deviation, a Student-t confidence interval for the mean, and Welch's unequal-variance t-test.
#pragma once

#include <cstddef>
#include <span>

namespace swarmnet::stats {

struct SampleSummary {
  std::size_t n = 0;
  double mean = 0.0;
  double sd = 0.0;       // sample standard deviation (n - 1); NaN when n < 2
  double ci_half = 0.0;  // half-width of the confidence interval; NaN when n < 2
  double ci_low = 0.0;   // mean - ci_half
  double ci_high = 0.0;  // mean + ci_half
};

// `confidence` in (0, 1), e.g. 0.95. n = 0 gives NaN everywhere but n.
SampleSummary summarize(std::span<const double> values, double confidence = 0.95);

struct WelchTest {
  double t = 0.0;   // (mean_a - mean_b) / sqrt(var_a / n_a + var_b / n_b)
  double df = 0.0;  // Welch-Satterthwaite degrees of freedom
  double p = 0.0;   // two-sided
};

// NaN fields when either sample has fewer than two values or both have zero variance.
WelchTest welch_test(std::span<const double> a, std::span<const double> b);

}  // namespace swarmnet::stats

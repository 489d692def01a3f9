// Student's t distribution and Welch's test against published values; Holm's correction and the
// interval for ratios in [0, 1].
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "experiments/stats_command.hpp"
#include "stats/holm_correction.hpp"
#include "stats/proportion_interval.hpp"
#include "stats/sample_statistics.hpp"
#include "stats/student_t.hpp"

namespace swarmnet::stats {
namespace {

TEST(IncompleteBeta, MatchesClosedForms) {
  // I_x(1, 1) = x; I_x(a, 1) = x^a; I_x(1, b) = 1 - (1 - x)^b; I_0.5(a, a) = 0.5.
  for (const double x : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    EXPECT_NEAR(incomplete_beta(x, 1.0, 1.0), x, 1e-14);
    EXPECT_NEAR(incomplete_beta(x, 3.5, 1.0), std::pow(x, 3.5), 1e-13);
    EXPECT_NEAR(incomplete_beta(x, 1.0, 2.5), 1.0 - std::pow(1.0 - x, 2.5), 1e-13);
  }
  EXPECT_NEAR(incomplete_beta(0.5, 7.25, 7.25), 0.5, 1e-13);
  EXPECT_THROW((void)incomplete_beta(1.5, 1.0, 1.0), std::invalid_argument);
}

TEST(StudentT, QuantilesMatchTables) {
  const std::vector<std::pair<double, double>> table = {
      {1, 12.706}, {2, 4.303}, {5, 2.571}, {10, 2.228}, {30, 2.042}};
  for (const auto& [df, q] : table) {
    EXPECT_NEAR(student_t_quantile(0.975, df), q, 5e-4) << "df " << df;
    EXPECT_NEAR(student_t_quantile(0.025, df), -q, 5e-4) << "df " << df;
  }
  // More digits: df 1 is Cauchy, tan(pi (p - 1/2)); df 2 has q = (2p-1) sqrt(2 / (4p(1-p))).
  EXPECT_NEAR(student_t_quantile(0.975, 1), std::tan(M_PI * 0.475), 1e-9);
  const double p = 0.99;
  EXPECT_NEAR(student_t_quantile(p, 2), (2 * p - 1) * std::sqrt(2.0 / (4 * p * (1 - p))), 1e-9);
  EXPECT_NEAR(student_t_quantile(0.995, 1e7), 2.5758293, 1e-5);  // the normal's
  EXPECT_DOUBLE_EQ(student_t_quantile(0.5, 4), 0.0);
}

TEST(StudentT, CdfIsSymmetricAndMonotone) {
  EXPECT_NEAR(student_t_cdf(0.0, 3.0), 0.5, 1e-15);
  EXPECT_NEAR(student_t_cdf(1.0, 1.0), 0.75, 1e-14);  // Cauchy: 1/2 + atan(1)/pi
  EXPECT_NEAR(student_t_cdf(-2.0, 6.5) + student_t_cdf(2.0, 6.5), 1.0, 1e-14);
  double previous = 0.0;
  for (double t = -10; t <= 10; t += 0.25) {
    const double c = student_t_cdf(t, 4.3);
    EXPECT_GT(c, previous);
    previous = c;
  }
  // Two-sided p of t = 2.228 at df 10 is 0.05.
  EXPECT_NEAR(student_t_two_sided_p(2.228, 10), 0.05, 2e-4);
}

TEST(SampleStatistics, SummaryGivesMeanSdAndStudentInterval) {
  const std::vector<double> values = {2, 4, 4, 4, 5, 5, 7, 9};
  const SampleSummary s = summarize(values);
  EXPECT_EQ(s.n, 8U);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.sd, std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_NEAR(s.ci_half, 2.364624 * std::sqrt(32.0 / 7.0) / std::sqrt(8.0), 1e-5);
  EXPECT_NEAR(s.ci_low, s.mean - s.ci_half, 1e-12);
  const SampleSummary one = summarize(std::vector<double>{3.0});
  EXPECT_EQ(one.n, 1U);
  EXPECT_DOUBLE_EQ(one.mean, 3.0);
  EXPECT_TRUE(std::isnan(one.sd));
  EXPECT_TRUE(std::isnan(one.ci_half));
}

// Two samples of 15 with unequal variances (after Wikipedia's Welch's t-test article). Expected
// values computed independently: t and df from their formulas, p by numerically integrating the
// t density (midpoint rule, 2e5 panels over [|t|, 200]): t = -2.455356, df = 24.98853,
// p = 0.0213780.
TEST(SampleStatistics, WelchTestMatchesPublishedExample) {
  const std::vector<double> a = {27.5, 21.0, 19.0, 23.6, 17.0, 17.9, 16.9, 20.1,
                                 21.9, 22.6, 23.1, 19.6, 19.0, 21.7, 21.4};
  const std::vector<double> b = {27.1, 22.0, 20.8, 23.4, 23.4, 23.5, 25.8, 22.0,
                                 24.8, 20.2, 21.9, 22.1, 22.9, 20.5, 24.4};
  const WelchTest w = welch_test(a, b);
  EXPECT_NEAR(w.t, -2.455356, 1e-6);
  EXPECT_NEAR(w.df, 24.98853, 1e-4);
  EXPECT_NEAR(w.p, 0.0213780, 1e-6);
  const WelchTest reversed = welch_test(b, a);
  EXPECT_DOUBLE_EQ(reversed.t, -w.t);
  EXPECT_DOUBLE_EQ(reversed.p, w.p);
  EXPECT_TRUE(std::isnan(welch_test(a, std::vector<double>{1.0}).p));
}

TEST(StatsCommand, ReadsQuotedCsv) {
  std::istringstream in("a,b\n\"x,1\",\"say \"\"hi\"\"\"\n3,\n");
  const auto rows = read_csv(in);
  ASSERT_EQ(rows.size(), 3U);
  EXPECT_EQ(rows[1][0], "x,1");
  EXPECT_EQ(rows[1][1], "say \"hi\"");
  ASSERT_EQ(rows[2].size(), 2U);
  EXPECT_EQ(rows[2][1], "");
}

}  // namespace
}  // namespace swarmnet::stats

namespace swarmnet::stats {
namespace {

TEST(HolmCorrection, StepsDownAndKeepsTheOrderGiven) {
  // Sorted: 0.005 x4 = 0.02, 0.01 x3 = 0.03, 0.03 x2 = 0.06, 0.04 x1 = 0.04 -> max so far 0.06.
  const auto adjusted = holm_adjust({0.01, 0.04, 0.03, 0.005});
  ASSERT_EQ(adjusted.size(), 4U);
  EXPECT_DOUBLE_EQ(adjusted[0], 0.03);
  EXPECT_DOUBLE_EQ(adjusted[1], 0.06);
  EXPECT_DOUBLE_EQ(adjusted[2], 0.06);
  EXPECT_DOUBLE_EQ(adjusted[3], 0.02);
  // A test that could not be computed stays undefined and does not count in m; 1 caps.
  const auto with_nan = holm_adjust({0.5, std::nan(""), 0.2});
  EXPECT_DOUBLE_EQ(with_nan[0], 0.5);
  EXPECT_TRUE(std::isnan(with_nan[1]));
  EXPECT_DOUBLE_EQ(with_nan[2], 0.4);
  EXPECT_DOUBLE_EQ(holm_adjust({0.6, 0.7})[0], 1.0);
}

TEST(ProportionInterval, StaysInsideZeroToOneWhereTheTIntervalDoesNot) {
  const std::vector<double> near_one{0.98, 0.99, 1.0};
  EXPECT_GT(summarize(near_one).ci_high, 1.0) << "the defect: a ratio's t interval above 1";
  const SampleSummary s = summarize_proportions(near_one);
  EXPECT_DOUBLE_EQ(s.mean, 0.99);
  EXPECT_LE(s.ci_high, 1.0);
  EXPECT_GE(s.ci_low, 0.0);
  EXPECT_LT(s.ci_low, s.mean);
  EXPECT_GT(s.ci_high, s.mean);
  const SampleSummary low = summarize_proportions(std::vector<double>{0.0, 0.01, 0.03});
  EXPECT_GE(low.ci_low, 0.0);
  // All equal: no spread, the interval is the point, as the t interval.
  const SampleSummary flat = summarize_proportions(std::vector<double>{1.0, 1.0, 1.0});
  EXPECT_DOUBLE_EQ(flat.ci_low, 1.0);
  EXPECT_DOUBLE_EQ(flat.ci_high, 1.0);
}

TEST(ProportionInterval, AgreesWithTheTIntervalAwayFromTheBounds) {
  std::vector<double> middle;
  for (int i = 0; i < 50; ++i) middle.push_back(0.45 + 0.002 * (i % 10));
  const SampleSummary t = summarize(middle);
  const SampleSummary w = summarize_proportions(middle);
  EXPECT_NEAR(w.ci_low, t.ci_low, 1e-4);
  EXPECT_NEAR(w.ci_high, t.ci_high, 1e-4);
}

}  // namespace
}  // namespace swarmnet::stats

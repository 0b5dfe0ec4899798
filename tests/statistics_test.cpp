// Sizing statistics (statistics/): the order-statistic interval of a quantile, Wilks' tolerance
// limits and the bootstrap, checked for their coverage on samples of known distributions.

#include <gsl/gsl_cdf.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "statistics/bootstrap.h"
#include "statistics/quantile_interval.h"
#include "statistics/wilks.h"
#include "tests/coverage_checks.h"

namespace shockmap {
namespace {

TEST(EstimateQuantile, InterpolatesBetweenOrderStatistics) {
  const std::vector<double> sample = {5.0, 1.0, 4.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(EstimateQuantile(sample, 0.5, 0.5).estimate, 3.0);
  EXPECT_DOUBLE_EQ(EstimateQuantile(sample, 0.95, 0.5).estimate, 4.8);
  EXPECT_DOUBLE_EQ(EstimateQuantile(sample, 0.1, 0.5).estimate, 1.4);
}

// For every n up to 80, the chosen ranks are the tightest admissible pair (checked against all
// pairs), their coverage is the binomial one and meets the confidence.
TEST(EstimateQuantile, RanksAreTheTightestWithEnoughCoverage) {
  for (const double p : {0.5, 0.95, 0.99}) {
    for (int n = 1; n <= 80; ++n) {
      std::vector<double> sample(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) sample[i] = i + 1.0;
      const QuantileInterval interval = EstimateQuantile(sample, p, 0.95);
      auto cdf = [&](int k) { return k < 0 ? 0.0 : k >= n ? 1.0 : gsl_cdf_binomial_P(k, p, n); };
      int tightest = n + 2;
      for (int r = 0; r <= n; ++r) {
        for (int s = r + 1; s <= n + 1; ++s) {
          if (cdf(s - 1) - cdf(r - 1) >= 0.95) tightest = std::min(tightest, s - r);
        }
      }
      const int r = interval.lower_rank;
      const int s = interval.upper_rank;
      SCOPED_TRACE("p " + std::to_string(p) + ", n " + std::to_string(n));
      EXPECT_EQ(s - r, tightest);
      EXPECT_NEAR(interval.coverage, cdf(s - 1) - cdf(r - 1), 1e-12);
      EXPECT_GE(interval.coverage, 0.95);
      EXPECT_EQ(interval.lower_bounded, r >= 1);
      EXPECT_EQ(interval.upper_bounded, s <= n);
      // Sample value i is rank i.
      if (interval.lower_bounded) {
        EXPECT_EQ(interval.lower, r);
      }
      if (interval.upper_bounded) {
        EXPECT_EQ(interval.upper, s);
      }
    }
  }
}

// With 20 members, P(all below the P95) = 0.95^20 = 0.36: no member bounds it from above.
TEST(EstimateQuantile, FlagsTheUnboundedSideOfASmallSample) {
  std::vector<double> sample(20);
  for (int i = 0; i < 20; ++i) sample[i] = i;
  const QuantileInterval interval = EstimateQuantile(sample, 0.95, 0.95);
  EXPECT_FALSE(interval.upper_bounded);
  EXPECT_EQ(interval.upper_rank, 21);
  EXPECT_TRUE(std::isinf(interval.upper));
  EXPECT_TRUE(interval.lower_bounded);
  // The largest r with P(B >= r) >= 0.95, B ~ Binomial(20, 0.95).
  const int r = interval.lower_rank;
  EXPECT_GE(1.0 - gsl_cdf_binomial_P(r - 1, 0.95, 20), 0.95);
  EXPECT_LT(1.0 - gsl_cdf_binomial_P(r, 0.95, 20), 0.95);
}

TEST(EstimateQuantile, RefusesBadInput) {
  const std::vector<double> sample = {1.0, 2.0};
  const std::vector<double> empty;
  const std::vector<double> with_nan = {1.0, std::nan("")};
  EXPECT_THROW(EstimateQuantile(empty, 0.5, 0.9), std::invalid_argument);
  EXPECT_THROW(EstimateQuantile(with_nan, 0.5, 0.9), std::invalid_argument);
  EXPECT_THROW(EstimateQuantile(sample, 1.0, 0.9), std::invalid_argument);
  EXPECT_THROW(EstimateQuantile(sample, 0.5, 0.0), std::invalid_argument);
  // The value refused is written as given, not to six decimals.
  for (const auto& [p, shown] :
       {std::pair{1.0, "quantile p = 1: "}, {-0.5, "quantile p = -0.5: "}}) {
    try {
      EstimateQuantile(sample, p, 0.9);
      ADD_FAILURE() << p << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(shown), std::string::npos) << e.what();
    }
  }
}

class OrderStatisticCoverage : public testing::TestWithParam<int> {};

TEST_P(OrderStatisticCoverage, NormalSamples) {
  CheckOrderStatisticCoverage(StandardNormal(), GetParam(), 2000);
}
TEST_P(OrderStatisticCoverage, GumbelSamples) {
  CheckOrderStatisticCoverage(StandardGumbel(), GetParam(), 2000);
}
INSTANTIATE_TEST_SUITE_P(SampleSizes, OrderStatisticCoverage, testing::Values(59, 100, 200, 1000));

TEST(Wilks, MembersNeededFor95Over95) {
  EXPECT_EQ(WilksMembersNeeded(0.95, 0.95, 1), 59);
  EXPECT_EQ(WilksMembersNeeded(0.95, 0.95, 2), 93);
  EXPECT_EQ(WilksMembersNeeded(0.95, 0.95, 3), 124);
  // First order in closed form: the smallest n with 1 - p^n >= confidence.
  const int n = WilksMembersNeeded(0.99, 0.95, 1);
  EXPECT_GE(1.0 - std::pow(0.99, n), 0.95);
  EXPECT_LT(1.0 - std::pow(0.99, n - 1), 0.95);
}

TEST(Wilks, HighestOrderTheMembersAllow) {
  EXPECT_EQ(WilksHighestOrder(0, 0.95, 0.95), 0);
  EXPECT_EQ(WilksHighestOrder(58, 0.95, 0.95), 0);
  EXPECT_EQ(WilksHighestOrder(59, 0.95, 0.95), 1);
  EXPECT_EQ(WilksHighestOrder(92, 0.95, 0.95), 1);
  EXPECT_EQ(WilksHighestOrder(93, 0.95, 0.95), 2);
  EXPECT_EQ(WilksHighestOrder(124, 0.95, 0.95), 3);
  for (int order = 1; order <= 10; ++order) {
    const int members = WilksMembersNeeded(0.95, 0.95, order);
    EXPECT_EQ(WilksHighestOrder(members, 0.95, 0.95), order);
    EXPECT_EQ(WilksHighestOrder(members - 1, 0.95, 0.95), order - 1);
  }
  EXPECT_THROW(WilksMembersNeeded(0.95, 0.95, 0), std::invalid_argument);
  EXPECT_THROW(WilksHighestOrder(-1, 0.95, 0.95), std::invalid_argument);
}

TEST(Wilks, UpperLimitIsTheOrderThLargestMember) {
  std::vector<double> sample(100);
  for (int i = 0; i < 100; ++i) sample[i] = 100.0 - i;  // rank i + 1 holds i + 1
  const auto limit = WilksUpperLimit(sample, 0.95, 0.95);
  ASSERT_TRUE(limit.has_value());
  EXPECT_EQ(limit->order, 2);
  EXPECT_EQ(limit->rank, 99);
  EXPECT_EQ(limit->value, 99.0);
  EXPECT_FALSE(WilksUpperLimit(std::span(sample).first(58), 0.95, 0.95).has_value());
}

// The largest of 59 normal draws exceeds the true P95 with probability 1 - 0.95^59 = 0.9515:
// measured over 200 000 trials (standard error 0.00048), it must be >= 0.95 and within four
// standard errors of that value.
TEST(Wilks, LargestOf59ExceedsTheP95WithTheStatedConfidence) {
  const int trials = 200000;
  const Distribution normal = StandardNormal();
  const double truth = normal.quantile(0.95);
  const Rng rng = MakeRng(59);
  int exceeded = 0;
  for (int i = 0; i < trials; ++i) {
    const auto limit = WilksUpperLimit(Draw(normal, rng.get(), 59), 0.95, 0.95);
    ASSERT_TRUE(limit.has_value());
    exceeded += limit->value >= truth;
  }
  const double measured = static_cast<double>(exceeded) / trials;
  const double expected = 1.0 - std::pow(0.95, 59);
  std::printf("largest of 59 above the true P95: measured %.5f, expected %.5f\n", measured,
              expected);
  EXPECT_GE(measured, 0.95);
  EXPECT_NEAR(measured, expected, 4.0 / 3.0 * ThreeSigma(expected, trials));
}

TEST(Bootstrap, ReproducibleFromTheSeed) {
  const Rng rng = MakeRng(7);
  const std::vector<double> sample = Draw(StandardNormal(), rng.get(), 100);
  const Interval a = BootstrapQuantileInterval(sample, 0.95, 0.95, 500, 42);
  const Interval b = BootstrapQuantileInterval(sample, 0.95, 0.95, 500, 42);
  const Interval c = BootstrapQuantileInterval(sample, 0.95, 0.95, 500, 43);
  EXPECT_EQ(a.lower, b.lower);
  EXPECT_EQ(a.upper, b.upper);
  EXPECT_TRUE(a.lower != c.lower || a.upper != c.upper);
  EXPECT_LE(a.lower, a.upper);
  EXPECT_THROW(BootstrapQuantileInterval(sample, 0.95, 0.95, 0, 42), std::invalid_argument);
}

TEST(Bootstrap, CoverageOfTheP95) { CheckBootstrapCoverage(StandardNormal(), 200, 400, 400, 0.88); }

}  // namespace
}  // namespace shockmap

// The coverage checks of statistics_test on more and larger samples (label `long`): the
// order-statistic interval of the P95 over 10 000 samples, and the bootstrap's coverage for
// each sample size.

#include <gtest/gtest.h>

#include "tests/coverage_checks.h"

namespace shockmap {
namespace {

class LongCoverage : public testing::TestWithParam<int> {};

TEST_P(LongCoverage, OrderStatisticIntervalNormal) {
  CheckOrderStatisticCoverage(StandardNormal(), GetParam(), 10000);
}
TEST_P(LongCoverage, OrderStatisticIntervalGumbel) {
  CheckOrderStatisticCoverage(StandardGumbel(), GetParam(), 10000);
}
// The percentile bootstrap of a tail quantile under-covers on small samples (measured 82 % to
// 89 % below 200 members): held to 80 % there and 90 % from 200 members on.
double BootstrapFloor(int n) { return n >= 200 ? 0.90 : 0.80; }

TEST_P(LongCoverage, BootstrapNormal) {
  CheckBootstrapCoverage(StandardNormal(), GetParam(), 1000, 500, BootstrapFloor(GetParam()));
}
TEST_P(LongCoverage, BootstrapGumbel) {
  CheckBootstrapCoverage(StandardGumbel(), GetParam(), 1000, 500, BootstrapFloor(GetParam()));
}
INSTANTIATE_TEST_SUITE_P(SampleSizes, LongCoverage, testing::Values(59, 100, 200, 1000));

}  // namespace
}  // namespace shockmap

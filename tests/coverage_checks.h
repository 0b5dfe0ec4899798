#pragma once
// Samples of known distributions and the coverage checks of statistics/ shared by
// statistics_test (fast) and statistics_long_test (label `long`).

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "statistics/bootstrap.h"
#include "statistics/quantile_interval.h"

namespace shockmap {

using Rng = std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)>;

inline Rng MakeRng(unsigned long seed) {
  Rng rng(gsl_rng_alloc(gsl_rng_mt19937), &gsl_rng_free);
  gsl_rng_set(rng.get(), seed);
  return rng;
}

// A distribution to draw from, with its true quantile function.
struct Distribution {
  std::string name;
  std::function<double(gsl_rng*)> draw;
  std::function<double(double)> quantile;
};

inline Distribution StandardNormal() {
  return {"normal", [](gsl_rng* r) { return gsl_ran_ugaussian(r); },
          [](double p) { return gsl_cdf_ugaussian_Pinv(p); }};
}

// Type-I Gumbel with a = b = 1: F(x) = exp(-exp(-x)), the law of maxima of light tails.
inline Distribution StandardGumbel() {
  return {"Gumbel", [](gsl_rng* r) { return gsl_ran_gumbel1(r, 1.0, 1.0); },
          [](double p) { return gsl_cdf_gumbel1_Pinv(p, 1.0, 1.0); }};
}

inline std::vector<double> Draw(const Distribution& distribution, gsl_rng* rng, int n) {
  std::vector<double> sample(static_cast<std::size_t>(n));
  for (double& value : sample) value = distribution.draw(rng);
  return sample;
}

// Three binomial standard errors of a proportion measured in `repetitions` trials.
inline double ThreeSigma(double proportion, int repetitions) {
  return 3.0 * std::sqrt(proportion * (1.0 - proportion) / repetitions);
}

// Coverage of the true P95 by the 95 % order-statistic interval over `repetitions` samples of
// size n: it must match the interval's exact binomial coverage (>= 95 %, conservative by
// construction because ranks are discrete) within three binomial standard errors.
inline void CheckOrderStatisticCoverage(const Distribution& distribution, int n, int repetitions) {
  const double p = 0.95;
  const double truth = distribution.quantile(p);
  const Rng rng = MakeRng(20261201 + n);
  int covered = 0;
  double exact = 0.0;
  for (int i = 0; i < repetitions; ++i) {
    const QuantileInterval interval = EstimateQuantile(Draw(distribution, rng.get(), n), p, 0.95);
    covered += interval.lower <= truth && truth <= interval.upper;
    exact = interval.coverage;
  }
  const double measured = static_cast<double>(covered) / repetitions;
  std::printf("order-statistic interval of P95, %s, n = %d: measured coverage %.4f, exact %.4f\n",
              distribution.name.c_str(), n, measured, exact);
  EXPECT_GE(exact, 0.95);
  EXPECT_NEAR(measured, exact, ThreeSigma(exact, repetitions));
  EXPECT_GE(measured, 0.93);
}

// Coverage of the true P95 by the 95 % percentile-bootstrap interval; the percentile bootstrap
// of a tail quantile is known to under-cover on small samples, so it is reported and held to
// `at_least`.
inline void CheckBootstrapCoverage(const Distribution& distribution, int n, int repetitions,
                                   int resamples, double at_least) {
  const double truth = distribution.quantile(0.95);
  const Rng rng = MakeRng(1000 + n);
  int covered = 0;
  for (int i = 0; i < repetitions; ++i) {
    const Interval interval =
        BootstrapQuantileInterval(Draw(distribution, rng.get(), n), 0.95, 0.95, resamples, 17 + i);
    covered += interval.lower <= truth && truth <= interval.upper;
  }
  const double measured = static_cast<double>(covered) / repetitions;
  std::printf(
      "bootstrap interval of P95, %s, n = %d, %d resamples: measured coverage %.4f "
      "over %d samples\n",
      distribution.name.c_str(), n, resamples, measured, repetitions);
  EXPECT_GE(measured, at_least);
}

}  // namespace shockmap

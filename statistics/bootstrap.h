#pragma once
// Percentile bootstrap of a quantile (docs/statistics.md, "Bootstrap cross-check").

#include <cstdint>
#include <span>

namespace shockmap {

struct Interval {
  double lower = 0.0;
  double upper = 0.0;
};

// The percentile-bootstrap interval of the empirical p-quantile (the estimator of
// EstimateQuantile): `resamples` resamples of the sample with replacement, each giving its
// p-quantile; the interval is the (1 - confidence)/2 and (1 + confidence)/2 quantiles of those.
// Reproducible: the same sample, settings and seed give the same interval on every platform
// (GSL's MT19937 generator). A cross-check, not a guarantee: its coverage of tail quantiles
// falls below `confidence` for small samples (docs/statistics.md).
// Throws std::invalid_argument when the sample is empty or holds a non-finite value, p or
// confidence is not in (0, 1), or resamples < 1.
Interval BootstrapQuantileInterval(std::span<const double> sample, double p, double confidence,
                                   int resamples, std::uint64_t seed);

}  // namespace shockmap

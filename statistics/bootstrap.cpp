#include "statistics/bootstrap.h"

#include <gsl/gsl_rng.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "statistics/sorted_sample.h"

namespace shockmap {
namespace {

// SortedQuantile of the sample once sorted, in linear time: only the two order statistics
// around position (n - 1) p are placed. Reorders `values`.
double UnsortedQuantile(std::vector<double>& values, double p) {
  const double position = (values.size() - 1) * p;
  const auto below = static_cast<std::size_t>(position);
  std::nth_element(values.begin(), values.begin() + below, values.end());
  const double lower = values[below];
  if (below + 1 == values.size()) return lower;
  const double upper = *std::min_element(values.begin() + below + 1, values.end());
  const double delta = position - below;  // as GSL forms it, so both agree to the bit
  return (1.0 - delta) * lower + delta * upper;
}

}  // namespace

Interval BootstrapQuantileInterval(std::span<const double> sample, double p, double confidence,
                                   int resamples, std::uint64_t seed) {
  CheckOpenUnit(p, "quantile p");
  CheckOpenUnit(confidence, "confidence");
  if (resamples < 1) {
    throw std::invalid_argument("bootstrap resamples = " + std::to_string(resamples) +
                                ": must be >= 1");
  }
  const std::vector<double> sorted = SortedSample(sample);
  const std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)> rng(gsl_rng_alloc(gsl_rng_mt19937),
                                                              &gsl_rng_free);
  // GSL's MT19937 keeps 32 bits of its seed: fold the high half in.
  gsl_rng_set(rng.get(), static_cast<unsigned long>((seed ^ (seed >> 32)) & 0xffffffffULL));
  std::vector<double> resample(sorted.size());
  std::vector<double> estimates;
  estimates.reserve(static_cast<std::size_t>(resamples));
  for (int b = 0; b < resamples; ++b) {
    for (double& value : resample) value = sorted[gsl_rng_uniform_int(rng.get(), sorted.size())];
    estimates.push_back(UnsortedQuantile(resample, p));
  }
  std::sort(estimates.begin(), estimates.end());
  return {SortedQuantile(estimates, (1.0 - confidence) / 2.0),
          SortedQuantile(estimates, (1.0 + confidence) / 2.0)};
}

}  // namespace shockmap

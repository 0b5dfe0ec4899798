#include "statistics/sorted_sample.h"

#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace shockmap {

void CheckOpenUnit(double value, std::string_view name) {
  if (!(value > 0.0 && value < 1.0)) {
    std::array<char, 32> shortest{};  // The value as given: the shortest text that reads back.
    const auto written = std::to_chars(shortest.data(), shortest.data() + shortest.size(), value);
    throw std::invalid_argument(std::string(name) + " = " +
                                std::string(shortest.data(), written.ptr) + ": must be in (0, 1)");
  }
}

std::vector<double> SortedSample(std::span<const double> sample) {
  if (sample.empty()) throw std::invalid_argument("the sample is empty");
  for (std::size_t i = 0; i < sample.size(); ++i) {
    if (!std::isfinite(sample[i])) {
      throw std::invalid_argument("sample value " + std::to_string(i) + " is not finite");
    }
  }
  std::vector<double> sorted(sample.begin(), sample.end());
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

double SortedQuantile(std::span<const double> sorted, double p) {
  return gsl_stats_quantile_from_sorted_data(sorted.data(), 1, sorted.size(), p);
}

}  // namespace shockmap

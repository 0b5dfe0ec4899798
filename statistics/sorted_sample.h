#pragma once
// What the estimators of statistics/ share: the checked, sorted copy of a sample and the
// empirical quantile of a sorted sample.

#include <span>
#include <string_view>
#include <vector>

namespace shockmap {

// Throws std::invalid_argument naming `name` and the value unless 0 < value < 1.
void CheckOpenUnit(double value, std::string_view name);

// The sample sorted ascending. Throws std::invalid_argument when it is empty or holds a
// non-finite value (naming its index).
std::vector<double> SortedSample(std::span<const double> sample);

// The p-quantile of an ascending, non-empty sample by linear interpolation between order
// statistics at position (n - 1) p (Hyndman–Fan type 7, GSL's gsl_stats_quantile_from_sorted_data).
double SortedQuantile(std::span<const double> sorted, double p);

}  // namespace shockmap

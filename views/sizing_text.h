#pragma once
// Sizing numbers as the tables and plots write them: a probability as a percentage ("95" for
// 0.95), a number to 4 significant digits, a quantile with its interval as
// "estimate [lower, upper]" in those digits, an unbounded side as "-".

#include <string>

#include "statistics/quantile_interval.h"

namespace shockmap {

std::string PercentText(double probability);
std::string SignificantText(double value);
std::string IntervalText(const QuantileInterval& q);

}  // namespace shockmap

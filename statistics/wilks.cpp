#include "statistics/wilks.h"

#include <gsl/gsl_cdf.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "statistics/sorted_sample.h"

namespace shockmap {
namespace {

// P(X_(n-m+1) >= x_p) for n members and order m <= n.
double UpperLimitConfidence(int members, int order, double p) {
  return gsl_cdf_binomial_P(static_cast<unsigned>(members - order), p,
                            static_cast<unsigned>(members));
}

}  // namespace

int WilksMembersNeeded(double p, double confidence, int order) {
  CheckOpenUnit(p, "quantile p");
  CheckOpenUnit(confidence, "confidence");
  if (order < 1) {
    throw std::invalid_argument("Wilks order = " + std::to_string(order) + ": must be >= 1");
  }
  int members = order;
  while (UpperLimitConfidence(members, order, p) < confidence) ++members;
  return members;
}

int WilksHighestOrder(int members, double p, double confidence) {
  CheckOpenUnit(p, "quantile p");
  CheckOpenUnit(confidence, "confidence");
  if (members < 0) {
    throw std::invalid_argument("member count = " + std::to_string(members) + ": must be >= 0");
  }
  int order = 0;
  while (order < members && UpperLimitConfidence(members, order + 1, p) >= confidence) ++order;
  return order;
}

std::optional<ToleranceLimit> WilksUpperLimit(std::span<const double> sample, double p,
                                              double confidence) {
  CheckOpenUnit(p, "quantile p");
  CheckOpenUnit(confidence, "confidence");
  if (sample.empty()) return std::nullopt;
  const std::vector<double> sorted = SortedSample(sample);
  const int n = static_cast<int>(sorted.size());
  const int order = WilksHighestOrder(n, p, confidence);
  if (order == 0) return std::nullopt;
  const int rank = n - order + 1;
  return ToleranceLimit{order, rank, sorted[rank - 1]};
}

}  // namespace shockmap

#pragma once
// Wilks' one-sided upper tolerance limit, as used in best-estimate-plus-uncertainty analyses
// (docs/statistics.md, "Wilks' tolerance limits"): with n members, the order-m limit is the
// m-th largest member X_(n-m+1); it exceeds the true p-quantile with probability
// P(Binomial(n, p) <= n - m) = 1 - sum_{j<m} C(n, j) (1-p)^j p^(n-j).

#include <optional>
#include <span>

namespace shockmap {

// The fewest members whose order-`order` upper limit covers the p-quantile with probability
// >= confidence: 59 for order 1 at 95 %/95 %, 93 for order 2, 124 for order 3.
// Throws std::invalid_argument unless p and confidence are in (0, 1) and order >= 1.
int WilksMembersNeeded(double p, double confidence, int order);

// The highest order whose upper limit `members` members allow at (p, confidence); 0 when
// none (fewer members than WilksMembersNeeded(p, confidence, 1)).
// Throws std::invalid_argument unless p and confidence are in (0, 1) and members >= 0.
int WilksHighestOrder(int members, double p, double confidence);

// An upper tolerance limit: the order m, its 1-based rank n - m + 1 in the sorted sample, and
// the member's value.
struct ToleranceLimit {
  int order = 0;
  int rank = 0;
  double value = 0.0;
};

// The upper tolerance limit of the highest order the sample allows (WilksHighestOrder);
// std::nullopt when the sample is too small for order 1.
// Throws std::invalid_argument when a value is not finite, or p, confidence not in (0, 1).
std::optional<ToleranceLimit> WilksUpperLimit(std::span<const double> sample, double p,
                                              double confidence);

}  // namespace shockmap

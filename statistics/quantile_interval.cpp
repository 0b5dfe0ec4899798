#include "statistics/quantile_interval.h"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "statistics/sorted_sample.h"

namespace shockmap {
namespace {

// F(k) = P(Binomial(n, p) <= k) for k in [-1, n], with F(-1) = 0 and F(n) = 1. Away from
// n p by more than 12 standard deviations (plus 10 ranks) F is 0 or 1 to below 1e-30, so
// only the window is evaluated; the whole range when n is small.
class BinomialCdf {
 public:
  BinomialCdf(int n, double p) : n_(n), p_(p) {
    const double spread = 12.0 * std::sqrt(n * p * (1.0 - p)) + 10.0;
    first_ = std::max(0, static_cast<int>(std::floor(n * p - spread)));
    last_ = std::min(n - 1, static_cast<int>(std::ceil(n * p + spread)));
    for (int k = first_; k <= last_; ++k) values_.push_back(gsl_cdf_binomial_P(k, p_, n_));
  }
  double operator()(int k) const {
    if (k < first_) return 0.0;
    if (k > last_) return 1.0;
    return values_[k - first_];
  }

 private:
  int n_;
  double p_;
  int first_ = 0;
  int last_ = 0;
  std::vector<double> values_;
};

struct Ranks {
  int lower = 0;  // 0: unbounded below
  int upper = 0;  // n + 1: unbounded above
  double coverage = 0.0;
};

// The pair r < s (r in [0, n], s in [1, n + 1]) with F(s-1) - F(r-1) >= confidence and the
// smallest s - r, ties to the highest coverage. For each r the smallest admissible s grows
// with r, so one sweep finds it.
Ranks TightestRanks(int n, double p, double confidence) {
  const BinomialCdf cdf(n, p);
  Ranks best{0, n + 1, 1.0};
  int s = 1;
  for (int r = 0; r <= n; ++r) {
    s = std::max(s, r + 1);
    while (s <= n + 1 && cdf(s - 1) - cdf(r - 1) < confidence) ++s;
    if (s > n + 1) break;
    const double coverage = cdf(s - 1) - cdf(r - 1);
    const int width = s - r;
    const int best_width = best.upper - best.lower;
    if (width < best_width || (width == best_width && coverage > best.coverage)) {
      best = {r, s, coverage};
    }
  }
  return best;
}

}  // namespace

QuantileInterval EstimateQuantile(std::span<const double> sample, double p, double confidence) {
  CheckOpenUnit(p, "quantile p");
  CheckOpenUnit(confidence, "confidence");
  const std::vector<double> sorted = SortedSample(sample);
  const int n = static_cast<int>(sorted.size());
  const Ranks ranks = TightestRanks(n, p, confidence);
  const double infinity = std::numeric_limits<double>::infinity();
  QuantileInterval result;
  result.p = p;
  result.confidence = confidence;
  result.estimate = SortedQuantile(sorted, p);
  result.lower_rank = ranks.lower;
  result.upper_rank = ranks.upper;
  result.lower_bounded = ranks.lower >= 1;
  result.upper_bounded = ranks.upper <= n;
  result.lower = result.lower_bounded ? sorted[ranks.lower - 1] : -infinity;
  result.upper = result.upper_bounded ? sorted[ranks.upper - 1] : infinity;
  result.coverage = ranks.coverage;
  return result;
}

}  // namespace shockmap

#pragma once
// Empirical quantile of a sample and its distribution-free confidence interval from order
// statistics (docs/statistics.md, "Quantiles and their intervals").

#include <span>

namespace shockmap {

// The p-quantile of a sample with its two-sided interval [X_(lower_rank), X_(upper_rank)].
// Ranks are 1-based order statistics of the sorted sample (X_(1) <= ... <= X_(n)); an
// unbounded side has rank 0 (lower, value -inf) or n + 1 (upper, value +inf) and its
// *_bounded flag false: the sample is too small for that side at this confidence.
struct QuantileInterval {
  double p = 0.0;           // the quantile's probability, in (0, 1)
  double confidence = 0.0;  // the requested coverage, in (0, 1)
  double estimate = 0.0;    // the empirical quantile (linear interpolation, Hyndman–Fan type 7)
  double lower = 0.0;
  double upper = 0.0;
  int lower_rank = 0;
  int upper_rank = 0;
  bool lower_bounded = false;
  bool upper_bounded = false;
  // The exact coverage of the interval for any continuous distribution,
  // P(X_(r) <= x_p < X_(s)) = F(s - 1) - F(r - 1) with F the Binomial(n, p) CDF; >= confidence.
  double coverage = 0.0;
};

// The empirical p-quantile of `sample` and the tightest order-statistic interval (fewest ranks
// between its ends; of equally tight ones, the highest coverage) that covers the true
// p-quantile with probability >= `confidence` whatever the (continuous) distribution.
// Throws std::invalid_argument when the sample is empty or holds a non-finite value, or p or
// confidence is not in (0, 1).
QuantileInterval EstimateQuantile(std::span<const double> sample, double p, double confidence);

}  // namespace shockmap

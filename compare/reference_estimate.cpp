#include "compare/reference_estimate.h"

#include <algorithm>
#include <cmath>

#include "validation/psd.h"
#include "validation/spectral_error.h"

namespace shockmap {
namespace {

// An order below this is not regular: the finer truncation's own error is then not known to be
// the smaller.
constexpr double kRegularOrder = 0.5;

// `other`'s tip on `level`'s output grid.
UniformSignal TipOn(const ReferenceLevel& level, const ReferenceLevel& other, double window_s) {
  return other.solution.SampleTipDisplacement(level.histories.tip_m.dt_s, window_s);
}

// max_t |u - v| / max_t |u|.
double TipDifference(const UniformSignal& u, const UniformSignal& v) {
  double diff = 0.0, amplitude = 0.0;
  for (std::size_t i = 0; i < u.values.size(); ++i) {
    diff = std::max(diff, std::abs(u.values[i] - v.values[i]));
    amplitude = std::max(amplitude, std::abs(u.values[i]));
  }
  return amplitude > 0.0 ? diff / amplitude : 0.0;
}

// |I - I_finer| / I_finer of the first shocks; 1 when only one of them has a shock.
double ImpulseDifference(const std::vector<Shock>& shocks, const std::vector<Shock>& finer) {
  if (shocks.empty() && finer.empty()) return 0.0;
  if (shocks.empty() || finer.empty()) return 1.0;
  return std::abs(shocks.front().impulse_n_s - finer.front().impulse_n_s) /
         finer.front().impulse_n_s;
}

}  // namespace

ReferenceLevel SolveReferenceLevel(const CantileverImpact& problem, const ReferenceOptions& options,
                                   double r_fref, double window_s,
                                   const ShockSegmentationOptions& shocks) {
  ReferenceOptions o = options;
  o.r_fref = r_fref;
  o.end_time_s = window_s;
  ReferenceSolution solution = SolveReference(problem, o);
  // The output step, shortened so that the last sample falls on the window's end.
  const double dt = window_s / std::ceil(window_s / solution.OutputStep());
  ReferenceHistories histories = solution.SampleHistories(dt, window_s);
  std::vector<Shock> segmented = SegmentShocks(histories.force_n, shocks, window_s);
  return {r_fref, std::move(solution), std::move(histories), std::move(segmented)};
}

ReferenceConvergence EstimateReferenceError(const ReferenceLevel& level,
                                            const ReferenceLevel& finer,
                                            const ReferenceLevel* coarser, double window_s,
                                            double tolerance) {
  ReferenceConvergence c;
  c.r_fref = level.r_fref;
  c.r_fref_check = finer.r_fref;
  const UniformSignal& tip = level.histories.tip_m;
  const UniformSignal finer_tip = TipOn(level, finer, window_s);
  const double tip_difference = TipDifference(tip, finer_tip);
  if (coarser != nullptr) {
    const double coarser_difference = TipDifference(tip, TipOn(level, *coarser, window_s));
    if (coarser_difference > 0.0 && tip_difference > 0.0) {
      c.order = std::log(coarser_difference / tip_difference) / std::log(kReferenceCheckRatio);
    }
  }
  const bool regular = c.order && *c.order > kRegularOrder;
  // |u_R - u_inf| <= d(R, 3R) + |u_3R - u_inf|, and |u_3R - u_inf| <= d(R, 3R) / (3^p - 1) at a
  // regular order p: the difference is doubled (enough from p = log_3 2 on, and for a quantity
  // that converges more slowly than the tip), or multiplied by 3^p / (3^p - 1) below that.
  const double richardson = regular ? std::pow(kReferenceCheckRatio, *c.order) /
                                          (std::pow(kReferenceCheckRatio, *c.order) - 1.0)
                                    : 0.0;
  const double factor = std::max(2.0, richardson);
  c.tip_error = factor * tip_difference;
  c.impulse_error = factor * ImpulseDifference(level.shocks, finer.shocks);
  c.induced_err = factor * SpectralError(tip, finer_tip, 0.0, window_s, PsdOptions{});
  c.difference = std::max({c.tip_error, c.impulse_error, c.induced_err});
  if (regular && tolerance > 0.0 && c.difference > tolerance) {
    c.r_fref_needed = level.r_fref * std::pow(c.difference / tolerance, 1.0 / *c.order);
  }
  return c;
}

}  // namespace shockmap

#include "compare/reference_estimate.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "compare/reference_shocks.h"
#include "validation/psd.h"
#include "validation/spectral_error.h"

namespace shockmap {
namespace {

// max_t |u - v| / max_t |scale| on a common grid.
double TipDifference(const UniformSignal& u, const UniformSignal& v, const UniformSignal& scale) {
  double diff = 0.0, amplitude = 0.0;
  for (std::size_t i = 0; i < u.values.size(); ++i) {
    diff = std::max(diff, std::abs(u.values[i] - v.values[i]));
    amplitude = std::max(amplitude, std::abs(scale.values[i]));
  }
  return amplitude > 0.0 ? diff / amplitude : 0.0;
}

double FirstImpulse(const ReferenceLevel& level) {
  return level.shocks.empty() ? 0.0 : level.shocks.front().impulse_n_s;
}

// The differences X(ladder[k + 1]) - X(ladder[k]) of one quantity X between successive levels.
template <typename Difference>
std::vector<double> Differences(const std::vector<const ReferenceLevel*>& ladder,
                                const Difference& difference) {
  std::vector<double> d;
  for (std::size_t k = 0; k + 1 < ladder.size(); ++k)
    d.push_back(difference(*ladder[k], *ladder[k + 1]));
  return d;
}

}  // namespace

double OutputGridStep(const ReferenceSolution& solution, double window_s) {
  return window_s / std::ceil(window_s / solution.OutputStep());
}

void ResampleLevel(ReferenceLevel& level, double window_s, const ShockSegmentationOptions& shocks,
                   double dt_s) {
  if (dt_s > 0.0) {  // A check: its tip alone.
    level.histories = {level.solution.SampleTipDisplacement(dt_s, window_s), {}};
  } else {
    level.histories =
        level.solution.SampleHistories(OutputGridStep(level.solution, window_s), window_s);
  }
  level.shocks = ReferenceShocks(level.solution, level.histories.force_n, shocks, window_s);
}

ReferenceLevel SolveReferenceLevel(const CantileverImpact& problem, const ReferenceOptions& options,
                                   double r_fref, double window_s,
                                   const ShockSegmentationOptions& shocks, double dt_s) {
  ReferenceOptions o = options;
  o.r_fref = r_fref;
  o.end_time_s = window_s;
  ReferenceLevel level{r_fref, SolveReference(problem, o), {}, {}};
  ResampleLevel(level, window_s, shocks, dt_s);
  return level;
}

ReferenceConvergence EstimateReferenceError(const std::vector<const ReferenceLevel*>& ladder,
                                            double window_s, double tolerance) {
  assert(ladder.size() >= 2);
  const ReferenceLevel& level = *ladder[ladder.size() - 2];
  const ReferenceLevel& finer = *ladder.back();
  ReferenceConvergence c;
  c.r_fref = level.r_fref;
  c.r_fref_check = finer.r_fref;
  const UniformSignal& tip = level.histories.tip_m;
  c.tip = GridConvergenceIndex(
      Differences(ladder, [&](const ReferenceLevel& a, const ReferenceLevel& b) {
        return TipDifference(a.histories.tip_m, b.histories.tip_m, tip);
      }));
  // Relative to the finest impulse, signed; 1 where only one of two truncations has a shock.
  c.impulse = GridConvergenceIndex(
      Differences(ladder, [&](const ReferenceLevel& a, const ReferenceLevel& b) {
        if (a.shocks.empty() != b.shocks.empty()) return 1.0;
        return a.shocks.empty() ? 0.0 : (FirstImpulse(b) - FirstImpulse(a)) / FirstImpulse(finer);
      }));
  c.induced_err = GridConvergenceIndex(
      Differences(ladder, [&](const ReferenceLevel& a, const ReferenceLevel& b) {
        return SpectralError(a.histories.tip_m, b.histories.tip_m, 0.0, window_s, PsdOptions{});
      }));
  const QuantityConvergence& deciding = c.Deciding();
  c.difference = deciding.error;
  if (deciding.order && tolerance > 0.0 && c.difference > tolerance) {
    c.r_fref_needed = level.r_fref * std::pow(c.difference / tolerance, 1.0 / *deciding.order);
  }
  return c;
}

ReferenceConvergence DifferenceFromCoarser(const ReferenceLevel& coarser,
                                           const ReferenceLevel& level, double window_s) {
  auto as_is = [](double difference) {
    QuantityConvergence q;
    q.difference = std::abs(difference);
    q.error = q.difference;
    return q;
  };
  ReferenceConvergence c;
  c.r_fref = level.r_fref;
  c.r_fref_check = coarser.r_fref;
  c.tip =
      as_is(TipDifference(level.histories.tip_m, coarser.histories.tip_m, level.histories.tip_m));
  if (level.shocks.empty() != coarser.shocks.empty()) {
    c.impulse = as_is(1.0);
  } else if (!level.shocks.empty()) {
    c.impulse = as_is((FirstImpulse(level) - FirstImpulse(coarser)) / FirstImpulse(level));
  }
  c.induced_err = as_is(
      SpectralError(coarser.histories.tip_m, level.histories.tip_m, 0.0, window_s, PsdOptions{}));
  c.difference = c.Deciding().error;
  return c;
}

}  // namespace shockmap

#include "compare/reference_run.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "compare/reference_estimate.h"
#include "core/cpu_timer.h"
#include "reference/reference_cost.h"

namespace shockmap {

double ReferenceTruncationRule::For(double r_k) const {
  return std::max(r_fref_min, r_fref_per_sqrt_rk * std::sqrt(r_k));
}

ReferenceRun ComputeReferenceRun(const CantileverImpact& problem, const ReferenceOptions& options,
                                 double window_s, const ShockSegmentationOptions& shocks) {
  const CpuTimer timer;
  auto solve = [&](double r) { return SolveReferenceLevel(problem, options, r, window_s, shocks); };
  const double r0 = options.r_fref;
  std::optional<ReferenceLevel> coarser;
  if (CoarserTruncation(r0) < r0) coarser.emplace(solve(CoarserTruncation(r0)));
  ReferenceLevel level = solve(r0);
  ReferenceLevel finer = solve(FinerTruncation(r0));
  auto estimate = [&] {
    return EstimateReferenceError(level, finer, coarser ? &*coarser : nullptr, window_s,
                                  options.target_error);
  };
  ReferenceConvergence convergence = estimate();
  // Raise the truncation while the estimate misses the target and the next one fits the budget.
  while (options.target_error > 0.0 && convergence.difference > options.target_error) {
    ReferenceOptions next = options;
    next.r_fref = finer.r_fref;
    if (!ReferenceBudgetExcess(problem, next, window_s).empty()) break;
    coarser.emplace(std::move(level));
    level = std::move(finer);
    finer = solve(FinerTruncation(level.r_fref));
    convergence = estimate();
  }
  ReferenceRun run;
  run.summary = level.solution.Summary();
  run.tip_m = std::move(level.histories.tip_m);
  run.force_n = std::move(level.histories.force_n);
  run.shocks = std::move(level.shocks);
  run.convergence = convergence;
  run.wall_s = timer.WallSeconds();
  run.convergence.wall_check_s = run.wall_s - run.summary.wall_s;
  return run;
}

ReferenceRun WithTipSpectrum(ReferenceRun run, const PsdOptions& options, double window_s) {
  try {
    run.tip_spectrum =
        ReferenceSpectrum{options, window_s, OneSidedPsd(run.tip_m, 0.0, window_s, options)};
  } catch (const std::invalid_argument&) {
    // Left unset: each point scored against it meets the same error and reports it.
  }
  return run;
}

}  // namespace shockmap

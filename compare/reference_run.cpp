#include "compare/reference_run.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "compare/coarser_checked_reference.h"
#include "compare/reference_decision.h"
#include "compare/reference_estimate.h"
#include "core/cpu_timer.h"
#include "reference/reference_cost.h"

namespace shockmap {
namespace {

// The truncations below the reference solved for its observed orders.
constexpr std::size_t kCoarserLevels = 2;

}  // namespace

double ReferenceTruncationRule::For(double r_k) const {
  return std::max(r_fref_min, r_fref_per_sqrt_rk * std::sqrt(r_k));
}

ReferenceRun ComputeReferenceRun(const CantileverImpact& problem, const ReferenceOptions& options,
                                 double window_s, const ShockSegmentationOptions& shocks) {
  if (options.check == ReferenceCheck::kCoarser)
    return ComputeCoarserCheckedReferenceRun(problem, options, window_s, shocks);
  const CpuTimer timer;
  // The reference on its own output grid; the truncations of its estimate on the same grid:
  // up to two coarser ones (r_fref / 9, r_fref / 3) for the orders, and the finer check.
  ReferenceLevel level = SolveReferenceLevel(problem, options, options.r_fref, window_s, shocks);
  auto check = [&](double r) {
    return SolveReferenceLevel(problem, options, r, window_s, shocks, level.histories.tip_m.dt_s);
  };
  std::deque<ReferenceLevel> coarser;
  for (double r = level.r_fref; coarser.size() < kCoarserLevels && CoarserTruncation(r) < r;) {
    r = CoarserTruncation(r);
    coarser.push_front(check(r));
  }
  ReferenceLevel finer = check(FinerTruncation(level.r_fref));
  auto estimate = [&] {
    std::vector<const ReferenceLevel*> ladder;
    for (const ReferenceLevel& l : coarser) ladder.push_back(&l);
    ladder.push_back(&level);
    ladder.push_back(&finer);
    return EstimateReferenceError(ladder, window_s, options.target_error);
  };
  ReferenceConvergence convergence = estimate();
  // Raise the truncation while the estimate misses the target, a part it leaves undecided
  // converges toward a truncation the budget affords, and the next one fits the budget.
  const ReferenceProblem budget{problem, options, window_s};
  while (options.target_error > 0.0 && convergence.difference > options.target_error) {
    if (!RaiseCanDecide(budget, convergence, options.target_error)) break;
    ReferenceOptions next = options;
    next.r_fref = finer.r_fref;
    if (!ReferenceBudgetExcess(problem, next, window_s).empty()) break;
    coarser.push_back(std::move(level));
    if (coarser.size() > kCoarserLevels) coarser.pop_front();
    level = std::move(finer);
    ResampleLevel(level, window_s, shocks);
    for (ReferenceLevel& l : coarser)
      ResampleLevel(l, window_s, shocks, level.histories.tip_m.dt_s);
    finer = check(FinerTruncation(level.r_fref));
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

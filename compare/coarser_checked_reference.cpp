#include "compare/coarser_checked_reference.h"

#include "compare/reference_estimate.h"
#include "core/cpu_timer.h"

namespace shockmap {

ReferenceRun ComputeCoarserCheckedReferenceRun(const CantileverImpact& problem,
                                               const ReferenceOptions& options, double window_s,
                                               const ShockSegmentationOptions& shocks) {
  const CpuTimer timer;
  ReferenceLevel level = SolveReferenceLevel(problem, options, options.r_fref, window_s, shocks);
  const ReferenceLevel coarser =
      SolveReferenceLevel(problem, options, CoarserTruncation(options.r_fref), window_s, shocks,
                          level.histories.tip_m.dt_s);
  ReferenceRun run;
  run.summary = level.solution.Summary();
  run.convergence = DifferenceFromCoarser(coarser, level, window_s);
  run.tip_m = std::move(level.histories.tip_m);
  run.force_n = std::move(level.histories.force_n);
  run.shocks = std::move(level.shocks);
  run.wall_s = timer.WallSeconds();
  run.convergence.wall_check_s = run.wall_s - run.summary.wall_s;
  return run;
}

}  // namespace shockmap

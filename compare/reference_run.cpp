#include "compare/reference_run.h"

#include <cmath>
#include <stdexcept>

#include "core/cpu_timer.h"

namespace shockmap {

ReferenceRun ComputeReferenceRun(const CantileverImpact& problem, const ReferenceOptions& options,
                                 double window_s, const ShockSegmentationOptions& shocks) {
  const CpuTimer timer;
  ReferenceOptions solve_options = options;
  solve_options.end_time_s = window_s;
  const ReferenceSolution solution = SolveReference(problem, solve_options);
  ReferenceRun run;
  run.summary = solution.Summary();
  // The output step, shortened so that the last sample falls on the window's end.
  const double dt = window_s / std::ceil(window_s / solution.OutputStep());
  ReferenceHistories histories = solution.SampleHistories(dt, window_s);
  run.tip_m = std::move(histories.tip_m);
  run.force_n = std::move(histories.force_n);
  run.convergence = MeasureReferenceConvergence(problem, solve_options, run.tip_m, window_s);
  run.shocks = SegmentShocks(run.force_n, shocks, window_s);
  run.wall_s = timer.WallSeconds();
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

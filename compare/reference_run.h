#pragma once
// A trusted reference for one problem and observation window: the piecewise-modal solution,
// its sampled signals, its shocks and its own convergence. Computed once and scored against
// every numerical run of the same problem.

#include <vector>

#include "reference/reference_convergence.h"
#include "reference/reference_solver.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

struct ReferenceRun {
  UniformSignal tip_m;    // Sampled at the reference's output step over [0, window].
  UniformSignal force_n;  // Same samples.
  std::vector<Shock> shocks;
  ReferenceSummary summary;
  ReferenceConvergence convergence;
  double wall_s = 0.0;  // Solution, its check at the coarser truncation, and sampling.
};

// Throws InputError when the reference cannot represent the problem.
ReferenceRun ComputeReferenceRun(const CantileverImpact& problem, const ReferenceOptions& options,
                                 double window_s, const ShockSegmentationOptions& shocks);

}  // namespace shockmap

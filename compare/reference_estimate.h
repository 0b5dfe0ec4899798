#pragma once
// The error of a truncated reference estimated from finer truncations of the same problem
// (docs/physics.md §2), on what the reference is used for: the tip history, the first-shock
// impulse and the Err its own error induces.

#include <optional>
#include <vector>

#include "reference/reference_convergence.h"
#include "reference/reference_solver.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

// One truncation solved over [0, window]: its histories on its own output grid (shortened to end
// on the window) and its shocks.
struct ReferenceLevel {
  double r_fref = 0.0;
  ReferenceSolution solution;
  ReferenceHistories histories;
  std::vector<Shock> shocks;
};

ReferenceLevel SolveReferenceLevel(const CantileverImpact& problem, const ReferenceOptions& options,
                                   double r_fref, double window_s,
                                   const ShockSegmentationOptions& shocks);

// The estimate of `level`'s error from `finer` (3 r_fref) and, when given, `coarser`
// (r_fref / 3) for the order; `tolerance` > 0 sets r_fref_needed from a regular order. The
// wall_check_s field is left to the caller.
ReferenceConvergence EstimateReferenceError(const ReferenceLevel& level,
                                            const ReferenceLevel& finer,
                                            const ReferenceLevel* coarser, double window_s,
                                            double tolerance);

}  // namespace shockmap

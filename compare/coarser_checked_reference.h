#pragma once
// A reference checked against a coarser truncation alone (ReferenceCheck::kCoarser,
// scoring.reference.check = "coarser"): the check a script does, for studies that trade the
// bound of the default estimate for its cost (docs/physics.md §2).

#include "compare/reference_run.h"

namespace shockmap {

// The reference at options.r_fref on its own output grid and the same problem at r_fref / 3
// sampled on that grid, the estimate their difference (DifferenceFromCoarser); never raised.
// Throws InputError when the reference cannot represent the problem.
ReferenceRun ComputeCoarserCheckedReferenceRun(const CantileverImpact& problem,
                                               const ReferenceOptions& options, double window_s,
                                               const ShockSegmentationOptions& shocks);

}  // namespace shockmap

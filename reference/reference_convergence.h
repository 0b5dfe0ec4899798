#pragma once
// Self-convergence of the truncated reference (docs/physics.md §2): the same problem at two
// truncations.

#include "reference/reference_solver.h"

namespace shockmap {

struct ReferenceConvergence {
  double r_fref = 0.0;        // The reference scored against.
  double r_fref_check = 0.0;  // The coarser one it is checked with.
  // max_t |u_ref(t) - u_check(t)| / max_t |u_ref(t)| of the tip over [0, window].
  double difference = 0.0;
  double wall_check_s = 0.0;
};

inline constexpr double kReferenceCheckRatio = 3.0;

// The truncation a reference at r_fref is checked against: r_fref / ratio, at least 1.
double CheckTruncation(double r_fref, double ratio = kReferenceCheckRatio);

// The coarser truncation is CheckTruncation(r_fref, ratio); its error dominates the difference,
// so the figure
// is an upper estimate of the finer reference's own error. `tip`: the reference's tip over
// [0, window_s], as sampled for its output; the check is sampled at the same instants, so the
// reference is not sampled twice.
ReferenceConvergence MeasureReferenceConvergence(const CantileverImpact& problem,
                                                 const ReferenceOptions& options,
                                                 const UniformSignal& tip, double window_s,
                                                 double ratio = kReferenceCheckRatio);

}  // namespace shockmap

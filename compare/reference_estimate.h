#pragma once
// The error of a truncated reference estimated from finer truncations of the same problem
// (docs/physics.md §2), on what the reference is used for: the tip history, the first-shock
// impulse and the Err its own error induces, each by its grid convergence index
// (reference/reference_convergence.h).

#include <optional>
#include <vector>

#include "reference/reference_convergence.h"
#include "reference/reference_solver.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

// One truncation solved over [0, window]: its histories on the grid of the reference being
// estimated and its shocks (ReferenceShocks). The reference itself, on its own output grid,
// has its tip and force and its shocks' peaks; a check, on the reference's grid, has its tip
// alone (force_n empty) and its shocks' impulses, each peak then the force at the middle of
// the shock's first contact (its memory and time go to what the estimate reads).
struct ReferenceLevel {
  double r_fref = 0.0;
  ReferenceSolution solution;
  ReferenceHistories histories;
  std::vector<Shock> shocks;
};

// A reference's own output grid over [0, window_s]: its output step shortened so that the last
// sample falls on the window's end.
double OutputGridStep(const ReferenceSolution& solution, double window_s);

// Solves truncation r_fref over [0, window_s] and samples it every dt_s as a check, or
// (dt_s = 0) on its own output grid as the reference.
ReferenceLevel SolveReferenceLevel(const CantileverImpact& problem, const ReferenceOptions& options,
                                   double r_fref, double window_s,
                                   const ShockSegmentationOptions& shocks, double dt_s = 0.0);

// Samples `level` again every dt_s as a check, or (dt_s = 0) on its own output grid as the
// reference.
void ResampleLevel(ReferenceLevel& level, double window_s, const ShockSegmentationOptions& shocks,
                   double dt_s = 0.0);

// The estimate of a reference's error from a ladder of truncations three apart, ascending and
// all sampled on the reference's grid: ..., r_fref / 9, r_fref / 3, the reference (r_fref),
// then its check (3 r_fref) last. With four levels the orders of two successive triples are
// observed (GridConvergenceIndex). `tolerance` > 0 sets r_fref_needed from an observed order.
// The wall_check_s field is left to the caller. Precondition: ladder.size() >= 2.
ReferenceConvergence EstimateReferenceError(const std::vector<const ReferenceLevel*>& ladder,
                                            double window_s, double tolerance);

// The check of ReferenceCheck::kCoarser: `level` against `coarser` (its truncation / 3, sampled
// on level's grid), each quantity's error the difference d(R / 3, R) itself (no order, no factor
// of safety): the tip's max_t |u_R - u_R/3| / max_t |u_R|, the first-shock impulses'
// |I_R - I_R/3| / I_R (1 where only one has a shock), the Err of u_R/3 scored against u_R.
// No bound on the reference's error (docs/physics.md §2). The wall_check_s field is left to the
// caller.
ReferenceConvergence DifferenceFromCoarser(const ReferenceLevel& coarser,
                                           const ReferenceLevel& level, double window_s);

}  // namespace shockmap

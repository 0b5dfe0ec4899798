#pragma once
// What a reference's estimate decides (docs/fidelity.md, "What the reference decides"): each
// score reads one part of the reference (validation/scores.h, ReferencePart) and is decided
// when that part's estimate is within the tolerance; once the first shock is decided, raising
// the truncation is worth it only while the order its truncations showed on the window's tip
// predicts a truncation within the reference budget.

#include <optional>
#include <string>

#include "core/cantilever_impact.h"
#include "reference/reference_convergence.h"
#include "reference/reference_solver.h"
#include "validation/scores.h"

namespace shockmap {

// The estimate of one part of the reference: for the window's tip the larger index of the tip
// and of the Err it induces, for the first shock its impulse's index.
double PartEstimate(const ReferenceConvergence& c, ReferencePart part);

// Whether reference c decides a score reading `part` at `tolerance`: the part's estimate is
// within it.
bool DecidesPart(const ReferenceConvergence& c, ReferencePart part, double tolerance);

// The order a quantity's truncations showed: the asymptotic one when observed, else the order
// of their progress (QuantityConvergence::progress_order); nullopt when finer truncations did
// not reduce its difference.
std::optional<double> ExpectedOrder(const QuantityConvergence& q);

// The truncation the orders of `part` predict would bring it within `tolerance`: over its
// quantities above the tolerance, the largest r_fref (index / tolerance)^(1 / p), p the
// quantity's ExpectedOrder; r_fref when the part is within it; nullopt when one of those
// quantities has none.
std::optional<double> PredictedTruncation(const ReferenceConvergence& c, ReferencePart part,
                                          double tolerance);

// The problem a reference solves, its settings and its window: what its budget depends on.
struct ReferenceProblem {
  const CantileverImpact& problem;
  const ReferenceOptions& options;
  double window_s = 0.0;

  // Whether the reference budget (reference/reference_cost.h) affords a reference at r_fref.
  bool Affords(double r_fref) const;
};

// Whether raising the truncation of reference c of `reference` can decide what it leaves
// undecided at `tolerance`. Before its first shock is decided the raise goes on (within the
// budget, which the caller checks): the ladder's orders are not yet meaningful there, and
// references whose first shock converges late still converge over the window (docs/fidelity.md,
// "Knowing early": R_k = 10^6.5 over 0.03 s shows no progress from 2000 to 17 800 f1 and
// converges at 1.44e6). Once the first shock is decided, only the window's tip is left, and it
// is raised only while the order its truncations showed (PredictedTruncation) predicts a
// truncation the budget affords: at R_k = 1e6 over 0.06 s, where the chatter after the first
// shock does not converge, the reference stops at once with that prediction.
bool RaiseCanDecide(const ReferenceProblem& reference, const ReferenceConvergence& c,
                    double tolerance);

// Why `part` of reference c is not decided at `tolerance`: its estimate and quantities, the
// tolerance's key and what truncation would do, e.g. "the reference's estimate on the window's
// tip is 0.156 (tip 0.156 of the amplitude, induced Err 0.0085; R_fref = 10000 checked against
// 30000), above scoring.reference.tolerance = 0.02; R_fref = 2.1e+09 would do by the order its
// truncations showed, beyond the reference budget", or "...; finer truncations did not reduce
// its difference: R_fref above 30000 is needed".
std::string UndecidedPartMessage(const ReferenceProblem& reference, const ReferenceConvergence& c,
                                 ReferencePart part, double tolerance);

}  // namespace shockmap

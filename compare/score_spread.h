#pragma once
// How much a point's scores owe to rounding (docs/physics.md §4.5): at stiff contact a single
// trajectory's Err and SRf move under perturbations of the size of rounding, so a score is a
// sample; the spread over a few such runs says whether a threshold's verdict is decided.

#include <memory>
#include <vector>

#include "compare/comparison.h"

namespace shockmap {

// The smallest and largest value of every registered score (validation/scores.h) over the runs
// that were scored; a score none of them has a value for has none in either.
struct ScoreSpread {
  int runs = 0;  // Runs that ended ok and were scored.
  ScoreValues low, high;

  // high - low of score `name`, 0 when it has no value.
  double Width(std::string_view name) const;
};

// Relative perturbations of the release amplitude the spread is taken over (the nominal one
// first): with g = 0 the problem is homogeneous in it, so the scores differ only by rounding
// and by its amplification; the time step is not perturbed, since a run shortens its step to
// end on the window.
inline const std::vector<double> kRoundingPerturbations = {0.0, 1e-12, -1e-12, 1e-9, -1e-9};

// Runs the point's numerical run with the release amplitude scaled by (1 + p) for each p of
// `perturbations`, each scored against `reference` (the nominal amplitude's: a relative change
// of 1e-9 moves the reference by 1e-9 of itself, below any spread that decides a verdict).
// Runs that do not end ok (unstable, diverged) are left out.
ScoreSpread SpreadAgainstReference(
    const CantileverImpact& problem, const ComparisonOptions& options,
    const std::shared_ptr<const ReferenceRun>& reference,
    const std::vector<double>& perturbations = kRoundingPerturbations);

// As SpreadAgainstReference, against the point's own reference (RunComparison).
ScoreSpread ScoreUnderPerturbations(
    const CantileverImpact& problem, const ComparisonOptions& options,
    const std::vector<double>& perturbations = kRoundingPerturbations);

}  // namespace shockmap

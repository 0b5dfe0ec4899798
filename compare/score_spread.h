#pragma once
// How much a point's scores owe to rounding (docs/physics.md §4): at stiff contact a single
// trajectory's Err and SRf move under perturbations of the size of rounding, so a score is a
// sample; the spread over a few such runs says whether a threshold's verdict is decided.

#include <vector>

#include "compare/comparison.h"

namespace shockmap {

struct ScoreSpread {
  int runs = 0;  // Runs that reached their end and were scored.
  double err_min = 0.0, err_max = 0.0;
  double srf_min = 0.0, srf_max = 0.0;
  // The spread holds values on both sides of the threshold: the verdict is not decided.
  bool err_straddles = false;
  bool srf_straddles = false;

  double ErrWidth() const { return err_max - err_min; }
  double SrfWidth() const { return srf_max - srf_min; }
};

// Relative perturbations of the release amplitude the spread is taken over (the nominal one
// first): with g = 0 the problem is homogeneous in it, so the scores differ only by rounding
// and by its amplification; the time step is not perturbed, since a run shortens its step to
// end on the window.
inline const std::vector<double> kRoundingPerturbations = {0.0, 1e-12, -1e-12, 1e-9, -1e-9};

// Runs the point (RunComparison: its reference solved for each run) with the release amplitude
// scaled by (1 + p) for each p of `perturbations`, and the spread of Err and SRf against
// err_max and srf_min. Runs that are not scored (diverged, reference unconverged) are left out.
ScoreSpread ScoreUnderPerturbations(
    const CantileverImpact& problem, const ComparisonOptions& options, double err_max,
    double srf_min, const std::vector<double>& perturbations = kRoundingPerturbations);

}  // namespace shockmap

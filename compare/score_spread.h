#pragma once
// How much a point's scores owe to perturbations that leave the setting what it is
// (docs/physics.md §4.5): at stiff contact a single trajectory's Err and SRf move under a
// rounding-level change of the release and under an equally valid finite-element
// eigensolution, so a score is a sample; the spread over a few such runs says whether a
// threshold's verdict is decided.

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

// One perturbed run of a point: its release amplitude scaled by (1 + amplitude), and its mesh
// refined by `mesh` (elements = ceil(mesh n), n the point's elements). With g = 0 the problem
// is homogeneous in the amplitude, so a rounding-level scale differs only by rounding and its
// amplification; a finer mesh keeps every retained mode within the default mesh's accuracy, so
// its eigensolution is as valid. The time step is not perturbed, since a run shortens its step
// to end on the window.
struct Perturbation {
  double amplitude = 0.0;
  double mesh = 1.0;

  bool IsNominal() const { return amplitude == 0.0 && mesh == 1.0; }
};

// The nominal run first, then rounding-level scales of the release and two finer meshes:
// measured at R_k = 10^5.5, 10 modes, a mesh of 50, 55, 58, 61 or 66 elements gives Err 0.099,
// 0.140, 0.046, 0.087 or 0.018 where the release's 1 +- 1e-12 moves it by 1e-7
// (docs/fidelity.md, "Spreads stored with the points").
inline const std::vector<Perturbation> kScorePerturbations = {
    {0.0, 1.0}, {1e-12, 1.0}, {-1e-12, 1.0}, {1e-9, 1.0}, {-1e-9, 1.0}, {0.0, 1.1}, {0.0, 1.25}};

// Runs the point's numerical run under each of `perturbations`, each scored against the
// reference of `nominal`, the point's own run already scored (the nominal amplitude's: a
// relative change of 1e-9 moves the reference by 1e-9 of itself, below any spread that decides
// a verdict; it does not depend on the mesh); the nominal perturbation takes `nominal`'s scores
// instead of running again. Runs that do not end ok (unstable, diverged) are left out.
ScoreSpread SpreadAgainstReference(
    const CantileverImpact& problem, const ComparisonOptions& options,
    const ComparisonResult& nominal,
    const std::vector<Perturbation>& perturbations = kScorePerturbations);

// As SpreadAgainstReference, against the point's own reference (RunComparison).
ScoreSpread ScoreUnderPerturbations(
    const CantileverImpact& problem, const ComparisonOptions& options,
    const std::vector<Perturbation>& perturbations = kScorePerturbations);

}  // namespace shockmap

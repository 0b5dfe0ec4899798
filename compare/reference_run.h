#pragma once
// A trusted reference for one problem and observation window: the piecewise-modal solution,
// its sampled signals, its shocks and its estimated error against finer truncations. Computed
// once and scored against every numerical run of the same problem.

#include <optional>
#include <vector>

#include "reference/reference_convergence.h"
#include "reference/reference_solver.h"
#include "validation/psd.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

// The tip's spectrum over [0, window_s] with `options` (OneSidedPsd), for eq. (8).
struct ReferenceSpectrum {
  PsdOptions options;
  double window_s = 0.0;
  PowerSpectrum psd;
};

struct ReferenceRun {
  UniformSignal tip_m;    // Sampled at the reference's output step over [0, window].
  UniformSignal force_n;  // Same samples.
  std::vector<Shock> shocks;
  ReferenceSummary summary;
  ReferenceConvergence convergence;
  double wall_s = 0.0;  // CPU time of the solution, the truncations of its estimate and sampling.
  // Set by WithTipSpectrum: every point scored with the same PSD options and window reuses it.
  std::optional<ReferenceSpectrum> tip_spectrum;
};

// The truncation a reference starts from, shared by `compare` and studies (docs/physics.md §2):
// the shock frequency sqrt(R_k) f1 (paper eq. 10) well inside it, r_fref = max(r_fref_min,
// r_fref_per_sqrt_rk sqrt(R_k)); ComputeReferenceRun raises it until its estimated error meets
// the tolerance.
struct ReferenceTruncationRule {
  double r_fref_min = 3000.0;
  double r_fref_per_sqrt_rk = 10.0;  // Ten times the shock frequency.

  double For(double r_k) const;
};

// The reference at options.r_fref, its error estimated against 3 r_fref (and the order from
// r_fref / 3; docs/physics.md §2); with options.target_error > 0, r_fref is raised threefold
// until the estimate meets it, while a raise can decide a part of the reference left undecided
// (RaiseCanDecide, compare/reference_decision.h: its convergence regular and its predicted
// truncation within the reference budget) and the next truncation fits that budget. With
// options.check = ReferenceCheck::kCoarser, ComputeCoarserCheckedReferenceRun instead.
// Throws InputError when the reference cannot represent the problem.
ReferenceRun ComputeReferenceRun(const CantileverImpact& problem, const ReferenceOptions& options,
                                 double window_s, const ShockSegmentationOptions& shocks);

// `run` with its tip's spectrum for scoring with `options` over [0, window_s], computed once
// for every point scored against it; without one when OneSidedPsd refuses the signal (each
// point then reports that error).
ReferenceRun WithTipSpectrum(ReferenceRun run, const PsdOptions& options, double window_s);

}  // namespace shockmap

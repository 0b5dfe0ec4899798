#pragma once
// A trusted reference for one problem and observation window: the piecewise-modal solution,
// its sampled signals, its shocks and its own convergence. Computed once and scored against
// every numerical run of the same problem.

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
  double wall_s = 0.0;  // Solution, its check at the coarser truncation, and sampling.
  // Set by WithTipSpectrum: every point scored with the same PSD options and window reuses it.
  std::optional<ReferenceSpectrum> tip_spectrum;
};

// Throws InputError when the reference cannot represent the problem.
ReferenceRun ComputeReferenceRun(const CantileverImpact& problem, const ReferenceOptions& options,
                                 double window_s, const ShockSegmentationOptions& shocks);

// `run` with its tip's spectrum for scoring with `options` over [0, window_s], computed once
// for every point scored against it; without one when OneSidedPsd refuses the signal (each
// point then reports that error).
ReferenceRun WithTipSpectrum(ReferenceRun run, const PsdOptions& options, double window_s);

}  // namespace shockmap

#pragma once
// What a reference costs before it is computed, from its truncation and window alone, and the
// budget a run may spend on it (about a minute of one core, as a run's eigenproblems in
// core/modal_basis.h, and 2 GB), so that a truncation or a window typed too large is refused
// with the estimate instead of exhausting the memory.

#include <string>

#include "core/cantilever_impact.h"
#include "reference/reference_solver.h"

namespace shockmap {

// Upper estimates of the solution and its sampling (reference/reference_solver.cpp): modes below
// f_ref, output samples at the shortest period / 8 over the window, the memory of the largest
// truncation solved, and the mode-samples of the crossing search and the output, the
// convergence estimate's truncations f_ref / 3 and 3 f_ref included.
struct ReferenceCost {
  double modes = 0.0;
  double samples = 0.0;
  double bytes = 0.0;
  double mode_samples = 0.0;
};

// Over [0, window_s] (options.end_time_s is not read). Preconditions: problem.IsValid(),
// options.IsValid() but for end_time_s, window_s > 0.
ReferenceCost EstimateReferenceCost(const CantileverImpact& problem,
                                    const ReferenceOptions& options, double window_s);

inline constexpr double kReferenceBudgetBytes = 2e9;
// About a minute of one core at the measured ~0.6 ns per mode-sample, everything included.
inline constexpr double kReferenceBudgetModeSamples = 1e11;

// Empty when the reference fits the budget; otherwise the estimate against it, e.g. "the
// reference would need about 72 GB and 3.1e+16 mode-samples (18 900 modes, 1.1e+11 output
// samples); at most 2 GB and 1e+11 mode-samples (about a minute of one core) are allowed".
std::string ReferenceBudgetExcess(const CantileverImpact& problem, const ReferenceOptions& options,
                                  double window_s);

}  // namespace shockmap

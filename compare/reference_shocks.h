#pragma once
// The shocks of a reference from its exact contact phases (docs/physics.md §2), grouped as
// SegmentShocks groups sampled contacts (validation/shock_segmentation.h): a contact starting
// less than the rest duration after the previous one ended is a rebound of its shock. Each
// impulse is the integral of the force in closed form, so that a reference's first-shock
// impulse carries no quadrature error and differs between truncations only by their
// truncation.

#include <vector>

#include "core/uniform_signal.h"
#include "reference/reference_solver.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

// The shocks of `solution` over [0, window_s]; each peak is the largest sample of `force` (the
// solution's force on any grid, or none) within the shock, or the force at the middle of its
// first contact when no sample falls inside. Preconditions: options.IsValid(),
// options.force_threshold_n == 0 (contact means a positive force), window_s within the
// solution.
std::vector<Shock> ReferenceShocks(const ReferenceSolution& solution, const UniformSignal& force,
                                   const ShockSegmentationOptions& options, double window_s);

}  // namespace shockmap

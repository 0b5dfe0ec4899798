#pragma once
// Shock impulse ratio SRf, paper eq. (9) (§2.4): how well a numerical model reproduces the
// impulse of the first shock of the reference.

#include <optional>
#include <vector>

#include "validation/shock_segmentation.h"

namespace shockmap {

// SRf = min(I_a, I_b) / max(I_a, I_b)   (paper eq. 9), dimensionless in [0, 1], symmetric.
// Both impulses in the same unit (N s), finite and >= 0; 1 when both are 0 (they agree).
// Throws std::invalid_argument otherwise.
double ImpulseRatio(double impulse_a_n_s, double impulse_b_n_s);

// SRf of the first shocks of two segmentations (SegmentShocks, same options):
// std::nullopt when neither has a shock (nothing to score); 0 when exactly one has a shock
// (one model impacts, the other does not); else ImpulseRatio of the two first shocks.
std::optional<double> FirstShockImpulseRatio(const std::vector<Shock>& numerical,
                                             const std::vector<Shock>& reference);

}  // namespace shockmap

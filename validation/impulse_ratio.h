#pragma once
// Shock impulse ratio SRf, paper eq. (9) (§2.4): how well a numerical model reproduces the
// impulse of the first shock of the reference.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/uniform_signal.h"

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

// The readings of the paper's "contact forces integrated on the first shock time" (eq. 9):
// - kFirstShock: each model's first shock, contacts grouped with the rest duration (the default);
// - kFirstContact: each model's first contact alone, up to its first separation;
// - kReferenceWindow: both forces integrated over the same interval, the reference's first
//   shock [start, end].
enum class SrfDefinition { kFirstShock, kFirstContact, kReferenceWindow };

// "first_shock", "first_contact", "reference_window".
std::string ToString(SrfDefinition definition);
// Inverse of ToString; std::nullopt for any other string (case-sensitive).
std::optional<SrfDefinition> SrfDefinitionFromString(std::string_view name);

// Integral of the piecewise-linear force over [t_begin_s, t_end_s] clipped to the record (N s):
// 0 when the interval misses it. Throws std::invalid_argument unless t_begin_s <= t_end_s are
// finite and the signal has dt_s > 0 when it has >= 2 samples.
double ImpulseOver(const UniformSignal& force, double t_begin_s, double t_end_s);

// SRf under `definition` of two contact forces over [0, t_end_s], each segmented with `shocks`
// into the given shock lists (SegmentShocks): std::nullopt when neither model touches; 0 when
// exactly one does (for kReferenceWindow: when the reference has no shock, or the numerical
// force is zero over its window); else ImpulseRatio of the two impulses.
std::optional<double> DefinedImpulseRatio(SrfDefinition definition,
                                          const UniformSignal& numerical_force,
                                          const std::vector<Shock>& numerical_shocks,
                                          const UniformSignal& reference_force,
                                          const std::vector<Shock>& reference_shocks,
                                          const ShockSegmentationOptions& shocks, double t_end_s);

}  // namespace shockmap

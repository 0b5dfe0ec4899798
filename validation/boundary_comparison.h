#pragma once
// Whether two boundaries at one R_k, each found on its own grid, tell of a different validity:
// a grid resolves a boundary only to the span between the studied value that decides it and
// its studied neighbour (`shockmap diff` and `criteria check` ask this of two studies).

#include <optional>

#include "validation/validity_criteria.h"

namespace shockmap {

enum class BoundaryComparison {
  kAlike,          // The same value.
  kDiffers,        // Spans that do not meet: the points that decide them say they differ.
  kNotComparable,  // Different values whose spans meet: the grids differ where it is decided.
};

// Where a grid puts a boundary: the value it finds (nullopt: none, e.g. no studied truncation
// passes) and the span [low, high) or (low, high] the true value lies in, high infinite when
// nothing studied bounds it.
struct ResolvedBoundary {
  std::optional<double> value;
  double low = 0.0, high = 0.0;
};

// The smallest passing truncation: in (r_ftrunc_below, r_ftrunc_min], above the largest studied
// truncation when none passes. A baseline written before r_ftrunc_below was recorded leaves the
// lower end to `below_when_unknown`.
ResolvedBoundary TruncationBoundary(const RkBoundary& b, double below_when_unknown);
// The largest passing dt / dt_sharp: in [dt_ratio_max, dt_ratio_above).
ResolvedBoundary DtBoundary(const RkBoundary& b);

// Alike within 1e-9 (relative), else differing or not comparable as their spans meet.
BoundaryComparison Compare(const ResolvedBoundary& a, const ResolvedBoundary& b);

}  // namespace shockmap

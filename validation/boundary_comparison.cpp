#include "validation/boundary_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shockmap {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Within 1e-9 (relative); an infinite end is close to itself only.
bool Close(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) return x == y;
  return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y));
}

// Two half-open spans meet unless one ends where or before the other begins.
bool Disjoint(const ResolvedBoundary& a, const ResolvedBoundary& b) {
  auto at_or_below = [](double end, double begin) { return end <= begin || Close(end, begin); };
  return at_or_below(a.high, b.low) || at_or_below(b.high, a.low);
}

}  // namespace

ResolvedBoundary TruncationBoundary(const RkBoundary& b, double below_when_unknown) {
  const double below = b.r_ftrunc_below.value_or(below_when_unknown);
  return {b.r_ftrunc_min, below, b.r_ftrunc_min.value_or(kInfinity)};
}

ResolvedBoundary DtBoundary(const RkBoundary& b) {
  return {b.dt_ratio_max, b.dt_ratio_max.value_or(0.0), b.dt_ratio_above.value_or(kInfinity)};
}

BoundaryComparison Compare(const ResolvedBoundary& a, const ResolvedBoundary& b) {
  if (a.value.has_value() == b.value.has_value() && (!a.value || Close(*a.value, *b.value))) {
    return BoundaryComparison::kAlike;
  }
  return Disjoint(a, b) ? BoundaryComparison::kDiffers : BoundaryComparison::kNotComparable;
}

}  // namespace shockmap

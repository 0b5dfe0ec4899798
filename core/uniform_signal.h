#pragma once
// A uniformly sampled scalar history, the common currency between solvers and scores.

#include <cstddef>
#include <vector>

namespace shockmap {

// Sample i is the value at time t0_s + i * dt_s. Units of the values are the caller's
// (metres for displacements, newtons for forces).
struct UniformSignal {
  double t0_s = 0.0;
  double dt_s = 0.0;
  std::vector<double> values;

  double TimeAt(std::size_t i) const { return t0_s + static_cast<double>(i) * dt_s; }
  // Time of the last sample; t0_s for an empty or single-sample signal.
  double EndTime() const { return values.empty() ? t0_s : TimeAt(values.size() - 1); }
  // Linear interpolation; clamps to the first / last sample outside [t0_s, EndTime()].
  double At(double t_s) const;
};

}  // namespace shockmap

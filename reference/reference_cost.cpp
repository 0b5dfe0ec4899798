#include "reference/reference_cost.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "reference/reference_convergence.h"
#include "reference/tip_modes.h"

namespace shockmap {
namespace {

// The cost of one solution at f_ref over the window.
ReferenceCost OneSolution(const CantileverImpact& problem, double r_fref, double window_s,
                          int crossing_samples_per_period) {
  const double f_ref_hz = r_fref * problem.F1Hz();
  // The roots lie ~pi apart from (i - 1/2) pi on, below f_ref's.
  ReferenceCost c;
  const double b_max = std::sqrt(2.0 * std::numbers::pi * f_ref_hz / problem.beam.OmegaOf(1.0));
  c.modes = b_max / std::numbers::pi + 1.0;
  // On the spring the highest frequency is at most sqrt(omega_ref^2 + k_eff |t|^2), with
  // |t|^2 = 4 n / m and k_eff = k_s / (1 + k_s R) (reference/reference_solver.h).
  const double k_s = problem.SpringStiffness();
  const double r = ResidualTipFlexibility(problem.beam, static_cast<int>(c.modes));
  const double k_eff = k_s / (1.0 + k_s * r);
  const double omega_ref = 2.0 * std::numbers::pi * f_ref_hz;
  const double omega_top =
      std::sqrt(omega_ref * omega_ref + k_eff * 4.0 * c.modes / problem.beam.Mass());
  const double periods = omega_top / (2.0 * std::numbers::pi) * window_s;
  c.samples = 8.0 * periods + 1.0;
  // The change of coordinates and its transpose, and per output sample the tip, the force and
  // the spectrum's arrays.
  c.bytes = 8.0 * (2.0 * c.modes * c.modes + 6.0 * c.samples);
  c.mode_samples = (crossing_samples_per_period * periods + c.samples) * c.modes;
  return c;
}

}  // namespace

ReferenceCost EstimateReferenceCost(const CantileverImpact& problem,
                                    const ReferenceOptions& options, double window_s) {
  ReferenceCost c =
      OneSolution(problem, options.r_fref, window_s, options.crossing_samples_per_period);
  for (double r : {CoarserTruncation(options.r_fref), FinerTruncation(options.r_fref)}) {
    const ReferenceCost level =
        OneSolution(problem, r, window_s, options.crossing_samples_per_period);
    c.mode_samples += level.mode_samples;
    c.bytes = std::max(c.bytes, level.bytes);  // Solved one after the other.
  }
  return c;
}

std::string ReferenceBudgetExcess(const CantileverImpact& problem, const ReferenceOptions& options,
                                  double window_s) {
  const ReferenceCost c = EstimateReferenceCost(problem, options, window_s);
  if (c.bytes <= kReferenceBudgetBytes && c.mode_samples <= kReferenceBudgetModeSamples) return "";
  char text[300];
  std::snprintf(text, sizeof text,
                "the reference would need about %.2g GB and %.2g mode-samples (%.0f modes, %.2g "
                "output samples over %g s); at most %.2g GB and %.2g mode-samples (about a "
                "minute of one core) are allowed",
                c.bytes / 1e9, c.mode_samples, c.modes, c.samples, window_s,
                kReferenceBudgetBytes / 1e9, kReferenceBudgetModeSamples);
  return text;
}

}  // namespace shockmap

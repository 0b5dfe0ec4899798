#include "reference/reference_cost.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "reference/analytic_basis.h"
#include "reference/reference_convergence.h"

namespace shockmap {
namespace {

// The cost of one solution at f_ref over the window, without the check.
ReferenceCost OneSolution(const CantileverImpact& problem, double r_fref, double window_s,
                          int crossing_samples_per_period) {
  const double f_ref_hz = r_fref * problem.F1Hz();
  // The roots lie ~pi apart from (i - 1/2) pi on, below f_ref's.
  ReferenceCost c;
  c.modes = RootOfFrequency(problem.beam, f_ref_hz) / std::numbers::pi + 1.0;
  c.nodes = BeamQuadratureNodes(ReferenceQuadratureRoot(problem, r_fref));
  // The shortest retained period is at least 1 / f_ref.
  const double periods = f_ref_hz * window_s;
  c.samples = 8.0 * periods + 1.0;
  // Two bases on the nodes, two projections between them, and per output sample the tip, the
  // force, the check's tip and the spectrum's arrays.
  c.bytes = 8.0 * (2.0 * c.nodes * c.modes + 2.0 * c.modes * c.modes + 6.0 * c.samples);
  c.mode_samples = (crossing_samples_per_period * periods + c.samples) * c.modes;
  return c;
}

}  // namespace

ReferenceCost EstimateReferenceCost(const CantileverImpact& problem,
                                    const ReferenceOptions& options, double window_s) {
  ReferenceCost c =
      OneSolution(problem, options.r_fref, window_s, options.crossing_samples_per_period);
  const ReferenceCost check = OneSolution(problem, CheckTruncation(options.r_fref), window_s,
                                          options.crossing_samples_per_period);
  c.mode_samples += check.mode_samples;
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

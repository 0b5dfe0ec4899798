#include "reference/reference_convergence.h"

#include <algorithm>
#include <cmath>

namespace shockmap {

double CheckTruncation(double r_fref, double ratio) { return std::max(1.0, r_fref / ratio); }

ReferenceConvergence MeasureReferenceConvergence(const CantileverImpact& problem,
                                                 const ReferenceOptions& options,
                                                 const UniformSignal& tip, double window_s,
                                                 double ratio) {
  ReferenceOptions check_options = options;
  check_options.r_fref = CheckTruncation(options.r_fref, ratio);
  check_options.end_time_s = window_s;
  const ReferenceSolution check = SolveReference(problem, check_options);

  const UniformSignal b = check.SampleTipDisplacement(tip.dt_s, tip.EndTime());
  double max_diff = 0.0, max_abs = 0.0;
  for (std::size_t i = 0; i < tip.values.size(); ++i) {
    max_diff = std::max(max_diff, std::abs(tip.values[i] - b.values[i]));
    max_abs = std::max(max_abs, std::abs(tip.values[i]));
  }
  return {options.r_fref, check_options.r_fref, max_abs > 0.0 ? max_diff / max_abs : 0.0,
          check.Summary().wall_s};
}

}  // namespace shockmap

#include "compare/score_spread.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace shockmap {

ScoreSpread ScoreUnderPerturbations(const CantileverImpact& problem,
                                    const ComparisonOptions& options, double err_max,
                                    double srf_min, const std::vector<double>& perturbations) {
  ScoreSpread s;
  s.err_min = s.srf_min = std::numeric_limits<double>::infinity();
  s.err_max = s.srf_max = -std::numeric_limits<double>::infinity();
  for (double p : perturbations) {
    CantileverImpact perturbed = problem;
    perturbed.initial_tip_m *= 1.0 + p;
    const ComparisonResult r = RunComparison(perturbed, options);
    const std::optional<double> err = r.scores["err"];
    if (!err) continue;
    ++s.runs;
    s.err_min = std::min(s.err_min, *err);
    s.err_max = std::max(s.err_max, *err);
    const double srf = r.scores["srf"].value_or(1.0);
    s.srf_min = std::min(s.srf_min, srf);
    s.srf_max = std::max(s.srf_max, srf);
  }
  if (s.runs == 0) return ScoreSpread{};
  s.err_straddles = s.err_min <= err_max && s.err_max > err_max;
  s.srf_straddles = s.srf_min < srf_min && s.srf_max >= srf_min;
  return s;
}

}  // namespace shockmap

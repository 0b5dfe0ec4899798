#include "compare/score_spread.h"

#include <algorithm>

namespace shockmap {

double ScoreSpread::Width(std::string_view name) const {
  const auto l = low[name], h = high[name];
  return l && h ? *h - *l : 0.0;
}

ScoreSpread SpreadAgainstReference(const CantileverImpact& problem,
                                   const ComparisonOptions& options,
                                   const std::shared_ptr<const ReferenceRun>& reference,
                                   const std::vector<double>& perturbations) {
  ScoreSpread s;
  for (double p : perturbations) {
    CantileverImpact perturbed = problem;
    perturbed.initial_tip_m *= 1.0 + p;
    const ComparisonResult r =
        ScoreAgainstReference(perturbed, options, reference, RecordedHistories::kScored);
    if (r.status != RunStatus::kOk) continue;
    ++s.runs;
    for (const ScoreDefinition& score : Scores()) {
      const auto value = r.scores[score.name];
      if (!value) continue;
      const auto l = s.low[score.name], h = s.high[score.name];
      s.low.Set(score.name, l ? std::min(*l, *value) : *value);
      s.high.Set(score.name, h ? std::max(*h, *value) : *value);
    }
  }
  return s;
}

ScoreSpread ScoreUnderPerturbations(const CantileverImpact& problem,
                                    const ComparisonOptions& options,
                                    const std::vector<double>& perturbations) {
  return SpreadAgainstReference(problem, options, RunComparison(problem, options).reference,
                                perturbations);
}

}  // namespace shockmap

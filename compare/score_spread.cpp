#include "compare/score_spread.h"

#include <algorithm>
#include <cmath>

#include "core/modal_basis.h"

namespace shockmap {

double ScoreSpread::Width(std::string_view name) const {
  const auto l = low[name], h = high[name];
  return l && h ? *h - *l : 0.0;
}

namespace {

// Widens `s` by the scores of one run that ended ok.
void Include(ScoreSpread& s, const ScoreValues& scores) {
  ++s.runs;
  for (const ScoreDefinition& score : Scores()) {
    const auto value = scores[score.name];
    if (!value) continue;
    const auto l = s.low[score.name], h = s.high[score.name];
    s.low.Set(score.name, l ? std::min(*l, *value) : *value);
    s.high.Set(score.name, h ? std::max(*h, *value) : *value);
  }
}

}  // namespace

ScoreSpread SpreadAgainstReference(const CantileverImpact& problem,
                                   const ComparisonOptions& options,
                                   const ComparisonResult& nominal,
                                   const std::vector<Perturbation>& perturbations) {
  ScoreSpread s;
  const int elements =
      options.n_elements > 0 ? options.n_elements : DefaultElementCount(options.r_ftrunc);
  for (const Perturbation& p : perturbations) {
    if (p.IsNominal()) {
      if (nominal.status == RunStatus::kOk) Include(s, nominal.scores);
      continue;
    }
    CantileverImpact perturbed = problem;
    perturbed.initial_tip_m *= 1.0 + p.amplitude;
    ComparisonOptions refined = options;
    if (p.mesh != 1.0) {
      // Within the eigensolution's budget; a mesh the budget cannot refine adds nothing.
      refined.n_elements =
          std::min(static_cast<int>(std::ceil(p.mesh * elements)), kEigenBudgetElements);
      if (refined.n_elements <= elements) continue;
    }
    const ComparisonResult r =
        ScoreAgainstReference(perturbed, refined, nominal.reference, RecordedHistories::kScored);
    if (r.status == RunStatus::kOk) Include(s, r.scores);
  }
  return s;
}

ScoreSpread ScoreUnderPerturbations(const CantileverImpact& problem,
                                    const ComparisonOptions& options,
                                    const std::vector<Perturbation>& perturbations) {
  return SpreadAgainstReference(problem, options, RunComparison(problem, options), perturbations);
}

}  // namespace shockmap

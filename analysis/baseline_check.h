#pragma once
// The regression check of a study's criteria against a baseline (formats/criteria_json.h).

#include <string>
#include <vector>

#include "formats/criteria_json.h"
#include "validation/validity_criteria.h"

namespace shockmap {

// What a baseline's check found: contradictions (exit 1), each naming the criterion with its old
// and new values, or the offending point; and where the study's grid and the baseline's differ
// where a criterion is decided, so that they cannot contradict each other there ("not
// comparable: grids differ at R_ftrunc ..."), said but no failure.
struct BaselineCheck {
  std::vector<std::string> contradictions;
  std::vector<std::string> not_comparable;
};

// The new criteria against the baseline within its tolerances: the fit (p, C, the knee) and
// dt/dt_sharp max where both were derived over the same R_k and smallest truncation, each R_k's
// smallest passing truncation where the points that decide it tell them apart
// (validation/boundary_comparison.h), and the stored points that meet the baseline's criteria
// but fail, at the R_k it was derived over.
BaselineCheck CheckAgainstBaseline(const ValidityCriteria& baseline,
                                   const CriteriaTolerances& tolerances,
                                   const ValidityCriteria& current,
                                   const std::vector<ScoredPoint>& points);

}  // namespace shockmap

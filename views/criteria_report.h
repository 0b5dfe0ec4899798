#pragma once
// Validity criteria as a human summary set against the paper's rules (their JSON is
// formats/criteria_json.h, their check against a baseline analysis/baseline_check.h).

#include <string>
#include <vector>

#include "validation/validity_criteria.h"

namespace shockmap {

// A few lines per criterion, saying where the data agrees or disagrees with the paper:
// R_ftrunc > sqrt(R_k) (eq. 10), 1/(4 dt f1) > R_ftrunc and R_ftrunc > 300 for R_k > 1e2
// (eq. 11).
std::string CriteriaSummary(const std::string& study, const ValidityCriteria& criteria,
                            const std::vector<ScoredPoint>& points);

// The lines of CriteriaSummary after its table (the fit, the paper's rules, the time step),
// unindented: "paper eq. 10  R_ftrunc > sqrt(R_k), ...", its label first.
std::vector<std::string> CriteriaRuleLines(const ValidityCriteria& criteria,
                                           const std::vector<ScoredPoint>& points);

}  // namespace shockmap

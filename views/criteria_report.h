#pragma once
// Validity criteria as JSON (the baseline format), as a human summary set against the paper's
// rules, and the regression check of a database against a baseline.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "validation/validity_criteria.h"

namespace shockmap {

// Tolerances a baseline states for its criteria (written into it, read back by the check).
struct CriteriaTolerances {
  double p = 0.10;                 // Absolute, on the exponent.
  double c_envelope_factor = 1.5;  // Ratio either way.
  double dt_ratio_factor = 1.5;    // Ratio either way, on dt_ratio_max.
};

nlohmann::json CriteriaToJson(const std::string& study, const ValidityCriteria& criteria,
                              const CriteriaTolerances& tolerances = {});
// Throws InputError naming `file` and the key when the baseline is malformed.
ValidityCriteria CriteriaFromJson(const nlohmann::json& json, const std::string& file,
                                  CriteriaTolerances* tolerances);

// A few lines per criterion, saying where the data agrees or disagrees with the paper:
// R_ftrunc > sqrt(R_k) (eq. 10), 1/(4 dt f1) > R_ftrunc and R_ftrunc > 300 for R_k > 1e2
// (eq. 11).
std::string CriteriaSummary(const std::string& study, const ValidityCriteria& criteria,
                            const std::vector<ScoredPoint>& points);

// The lines of CriteriaSummary after its table (the fit, the paper's rules, the time step),
// unindented: "paper eq. 10  R_ftrunc > sqrt(R_k), ...", its label first.
std::vector<std::string> CriteriaRuleLines(const ValidityCriteria& criteria,
                                           const std::vector<ScoredPoint>& points);

// Empty when the new criteria agree with the baseline within its tolerances and no stored point
// contradicts the baseline's criteria; else one line per disagreement, naming the criterion,
// the old and new values, or the offending point.
std::vector<std::string> CheckAgainstBaseline(const ValidityCriteria& baseline,
                                              const CriteriaTolerances& tolerances,
                                              const ValidityCriteria& current,
                                              const std::vector<ScoredPoint>& points);

}  // namespace shockmap

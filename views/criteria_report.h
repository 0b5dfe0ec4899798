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

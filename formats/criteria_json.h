#pragma once
// Validity criteria as JSON: the baseline format `criteria derive --out` writes and `criteria
// check`, `advise` and `check-advice` read, with the tolerances a baseline states for them.

#include <nlohmann/json.hpp>
#include <string>

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

}  // namespace shockmap

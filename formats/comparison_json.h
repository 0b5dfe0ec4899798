#pragma once
// A comparison as one JSON object: the same figures `shockmap compare` prints.

#include <nlohmann/json.hpp>

#include "compare/comparison.h"

namespace shockmap {

// A shock as one JSON object, a member per column of kShockColumns (compare/output_columns.h).
nlohmann::json ShockToJson(const Shock& shock);

// A member per column of kComparisonColumns (compare/output_columns.h), one per score of the
// registry (err, srf, ...; null when not scored), reference_undecided (the names of the scores
// the reference leaves undecided), first_shock_num and first_shock_ref (null when none).
nlohmann::json ComparisonToJson(const CantileverImpact& problem, const ComparisonOptions& options,
                                const ComparisonResult& result);

}  // namespace shockmap

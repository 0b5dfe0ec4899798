#pragma once
// The outcome of a scored point as maps, reports and diffs name it, in legend order: "passes",
// "fails thresholds" and "undecided" (status ok, split by the thresholds and by
// CriteriaOptions::Undecided), then every other status of kAllRunStatuses (core/run_status.h) by
// its stored name, read with spaces ("reference unconverged"). How each is drawn is
// views/map_grid.h's OutcomeCategories().

#include <string>
#include <vector>

#include "validation/validity_criteria.h"

namespace shockmap {

const std::vector<std::string>& OutcomeLabels();
// The index of p's category in OutcomeLabels().
int OutcomeCategoryOf(const ScoredPoint& p, const CriteriaOptions& thresholds);

}  // namespace shockmap

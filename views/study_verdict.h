#pragma once
// The verdict of a canonical study, at the top of its report: one paragraph an engineer can
// paste into a sizing note (the validity rule, the R_k range it covers, the time-step margin,
// what failed and why), and the criteria per R_k as a table.

#include <string>
#include <vector>

#include "db/read_only_query.h"
#include "validation/validity_criteria.h"

namespace shockmap {

// Plain text (escape it for HTML). `criteria` derived from `points` (the explicit-modal points
// of `study`); `results`: the study's rows of the results view, for the messages of failed
// runs.
std::string StudyVerdict(const std::string& study, const ValidityCriteria& criteria,
                         const std::vector<ScoredPoint>& points, const Table& results);

// One row per studied R_k: the smallest passing truncation, its ratio to sqrt(R_k) (paper
// eq. 10), the largest passing dt / dt_sharp, where stability held and was lost, and the
// passing points of the points; an empty cell where there is none.
Table CriteriaTable(const ValidityCriteria& criteria);

}  // namespace shockmap

#pragma once
// A diff of two studies (analysis/study_diff.h) as `shockmap diff` shows it: its text, its JSON
// and its tables. The overlaid boundary map is views/study_diff_map.h.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/study_diff.h"
#include "records/table.h"

namespace shockmap {

// "R_k 3162.28, R_ftrunc 30, dt 0.1 dt_sharp", led by the scheme when not explicit modal and
// followed by the mass damping when not zero.
std::string PointLabel(const DiffPoint& p);

// The human report: settings, the criteria table, the fit and dt margin of each, the points
// whose outcome changed and the points of one study only.
std::string DiffText(const DiffedStudy& a, const DiffedStudy& b, const StudyDiff& diff);
// Everything DiffText shows, as one JSON object.
nlohmann::json DiffToJson(const DiffedStudy& a, const DiffedStudy& b, const StudyDiff& diff);
// One row per point of either study: its parameters, then its outcome and scores in A and B
// (empty where it was not studied) and whether the outcome changed.
Table DiffPointTable(const DiffedStudy& a, const DiffedStudy& b, const StudyDiff& diff);
// One row per R_k: each study's smallest passing truncation and largest passing dt / dt_sharp.
Table DiffCriteriaTable(const StudyDiff& diff);

}  // namespace shockmap

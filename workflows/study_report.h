#pragma once
// The HTML report of a stored study (views/html_report.h), with the runs it shows beside the
// stored results computed here: the Fig. 3 of chosen points (each run again against its stored
// reference) and a scene study's contact-force maps. `shockmap report` and Python's
// shockmap.report() both run it.

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "workflows/workflow_log.h"

namespace shockmap {

struct StudyReportRequest {
  std::string database_path;
  std::string study;  // "": the database's only study.
  // Thresholds over the study's own, by score name (analysis/study_thresholds.h).
  std::map<std::string, double, std::less<>> thresholds;
  std::filesystem::path out;
  // How the caller's user spells `out`, for its refusals ("--out", "out").
  std::string_view out_name = "--out";
};

// Writes the report into request.out and returns its index page. A report refused half-way (a
// corrupt stored row, a full disk) leaves no folder it created; a corrupt stored reference
// spoils only its points' Fig. 3, told through log.warn. log.progress gets ("Fig. 3", done,
// total) per point drawn. Throws InputError for a study the database does not hold.
std::filesystem::path WriteStudyReport(const StudyReportRequest& request, const WorkflowLog& log);

}  // namespace shockmap

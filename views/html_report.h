#pragma once
// One self-contained HTML page for a study: validity maps, the Fig. 4 plots, the criteria with
// their fit and the paper's rules, the cost front and the study's provenance.

#include <filesystem>
#include <string>

#include "validation/validity_criteria.h"

namespace shockmap {

// Draws every figure into `dir` and writes dir/report.html with the figures embedded (data
// URIs), so the page can be moved alone. Returns the page's path. When it has loaded, the page
// sets data-images-loaded="LOADED/TOTAL" on <body> (checked by the test suite).
std::filesystem::path WriteHtmlReport(const std::string& database_path, const std::string& study,
                                      const CriteriaOptions& thresholds,
                                      const std::filesystem::path& dir);

}  // namespace shockmap

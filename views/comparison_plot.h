#pragma once
// The paper's Fig. 3 for one comparison: tip displacement and contact force, numerical against
// reference.

#include <filesystem>

#include "compare/comparison.h"

namespace shockmap {

// Draws DIR/fig3.png from the CSV files WriteComparisonCsv put in DIR; returns its path.
std::filesystem::path PlotComparison(const ComparisonResult& result,
                                     const CantileverImpact& problem,
                                     const ComparisonOptions& options,
                                     const std::filesystem::path& dir);

}  // namespace shockmap

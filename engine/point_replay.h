#pragma once
// A stored point of a study of the paper's problem computed again, for its histories: points
// store their scores, not their signals (docs/database.md), so `shockmap export point` reruns
// the point's numerical scheme against its stored reference. The run is deterministic: its
// scores equal the stored ones.

#include <cstdint>
#include <string>

#include "compare/comparison.h"

namespace shockmap {

struct ReplayedPoint {
  ComparisonResult result;  // Histories of the numerical run and the stored reference.
  CantileverImpact problem;
  ComparisonOptions options;
};

// Throws InputError naming the study and the point when the study is not of the paper's
// problem, or the point is unknown or not scored; DbError as the read-only queries do.
ReplayedPoint ReplayCanonicalPoint(const std::string& database_path, const std::string& study,
                                   std::int64_t point_id);

}  // namespace shockmap

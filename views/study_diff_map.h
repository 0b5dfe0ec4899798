#pragma once
// The picture of `shockmap diff`: the validity of two studies of the paper's problem on one map
// over log R_k by log R_ftrunc, each cell coloured by where it passes (both, A only, B only,
// neither), with each study's boundary (its smallest passing R_ftrunc at each R_k) and the
// paper's sqrt(R_k) drawn over it (gnuplot).

#include <filesystem>

#include "analysis/study_diff.h"

namespace shockmap {

// Draws the map into `file` (.png or .svg), with its gnuplot script and data beside it, as
// views/validity_map.h does. Each cell shows its finest studied dt in each study. Throws
// InputError for a bad extension or a file that cannot be written, PlotError when gnuplot fails.
void DrawDiffMap(const DiffedStudy& a, const DiffedStudy& b, const std::filesystem::path& file);

}  // namespace shockmap

#pragma once
// Validity maps: a metric (a score, the cost or the outcome) over log R_k by log R_ftrunc (or by
// dt / dt_sharp), with diverged points marked and the derived boundary and the paper's rules
// drawn over it (gnuplot).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "validation/validity_criteria.h"
#include "views/map_grid.h"

namespace shockmap {

// What a map's colour may show: each score of the registry (validation/scores.h) by its name,
// then "status" (the outcome category) and "cost" (the CPU time of the numerical run).
std::vector<std::string> MapMetrics();
bool IsMapMetric(std::string_view name);

struct MapOptions {
  std::string metric = "err";  // One of MapMetrics().
  // kRFtrunc: each (R_k, R_ftrunc) cell shows its finest time step. kDt: dt / dt_sharp
  // against R_k at one truncation (the largest studied unless `r_ftrunc` is set).
  MapAxis y = MapAxis::kRFtrunc;
  std::optional<double> r_ftrunc;
};

// Draws the map into `file` (.png or .svg, from the extension), with its gnuplot script and
// data beside it; the script names its data relative to its own folder, so it runs from there.
// The axes tick the studied values, the title states the dt shown, the status map has one
// legend entry per outcome category present (views/map_grid.h). The boundary drawn is the
// metric's own: a score's map judges by that score's threshold alone (the title and legend say
// when it has none, and its colours then span the values shown); the status and cost maps by
// all of `criteria`. The dt map draws the stability bound when it lies within its range. Throws
// InputError when there is nothing to draw or the file cannot be written.
void DrawValidityMap(const std::string& study, const std::vector<ScoredPoint>& points,
                     const ValidityCriteria& criteria, const MapOptions& options,
                     const std::filesystem::path& file);

}  // namespace shockmap

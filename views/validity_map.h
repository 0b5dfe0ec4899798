#pragma once
// Validity maps: a metric over log R_k by log R_ftrunc (or by dt / dt_sharp), with diverged
// points marked and the derived boundary and the paper's rules drawn over it (gnuplot).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "validation/validity_criteria.h"
#include "views/map_grid.h"

namespace shockmap {

enum class MapMetric { kErr, kSrf, kCost, kStatus };
std::string ToString(MapMetric m);
std::optional<MapMetric> MapMetricFromString(std::string_view s);

struct MapOptions {
  MapMetric metric = MapMetric::kErr;
  // kRFtrunc: each (R_k, R_ftrunc) cell shows its finest time step. kDt: dt / dt_sharp
  // against R_k at one truncation (the largest studied unless `r_ftrunc` is set).
  MapAxis y = MapAxis::kRFtrunc;
  std::optional<double> r_ftrunc;
};

// Draws the map into `file` (.png or .svg, from the extension), with its gnuplot script and
// data beside it; the script names its data relative to its own folder, so it runs from there.
// The axes tick the studied values, the title states the dt shown, the status map has one
// legend entry per outcome category present (views/map_grid.h). Throws InputError when there is
// nothing to draw or the file cannot be written.
void DrawValidityMap(const std::string& study, const std::vector<ScoredPoint>& points,
                     const ValidityCriteria& criteria, const MapOptions& options,
                     const std::filesystem::path& file);

}  // namespace shockmap

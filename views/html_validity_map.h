#pragma once
// The report's interactive validity map: an inline SVG of the map's cells (views/map_grid.h)
// coloured by outcome category, each cell carrying its point's values (hovering shows R_k,
// R_ftrunc, dt, the scores and status) and linking to that point's page; and the same cells
// coloured by each metric (Err, SRf, ..., cost) with a switch that shows one map at a time.

#include <filesystem>
#include <functional>
#include <string>

#include "validation/validity_criteria.h"
#include "views/map_grid.h"

namespace shockmap {

// The page of a stored point, relative to the report's index.html: points/point_ID.html.
std::filesystem::path PointPagePath(std::int64_t point_id);

// Every <rect class="cell"> has data-point-id, data-rk, data-rftrunc, data-dt (s),
// data-dt-ratio (dt / dt_sharp), one data-<name> per score of the registry (data-err, data-srf,
// ...; "not scored" when absent), data-status (the stored status) and data-outcome (its
// category), and a <title> with the same. On the
// R_ftrunc map the derived boundary (the criteria's envelope) is drawn over the cells.
std::string HtmlValidityMap(const MapGrid& grid, MapAxis y, const ValidityCriteria& criteria,
                            const std::string& id);

// The grid's cells coloured by one metric per map: each score of the registry that any cell
// has (Err, SRf, PFr, ...), then cost (CPU time, log scale). Each map sits in a
// <div class="metric-map" data-metric="NAME"> with its colour scale; its cells carry what
// HtmlValidityMap's do, their <title> opening with the metric's value ("Err = 0.0123; ...").
// A score's map draws the boundary of its own threshold (MetricCriteria, from `points`), none
// without one; the cost map that of `criteria`.
// A <select class="metric-switch" data-maps="ID"> lists the metrics; the page's script shows the
// chosen map only (views/report_page.h).
std::string HtmlMetricMaps(const std::vector<ScoredPoint>& points, const MapGrid& grid,
                           const ValidityCriteria& criteria, const std::string& id);

}  // namespace shockmap

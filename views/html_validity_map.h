#pragma once
// The report's interactive validity map: an inline SVG of the map's cells (views/map_grid.h)
// coloured by outcome category, each cell carrying its point's values (hovering shows R_k,
// R_ftrunc, dt, the scores and status) and linking to that point's page.

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

}  // namespace shockmap

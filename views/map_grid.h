#pragma once
// The cells of a validity map: which stored point each (R_k, y) cell shows, where its box lies
// on the log axes, and the outcome category it is coloured by. Shared by the gnuplot maps
// (views/validity_map.h) and the report's interactive maps (views/html_validity_map.h).

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/outcome_category.h"
#include "validation/validity_criteria.h"

namespace shockmap {

enum class MapAxis { kRFtrunc, kDt };
std::string ToString(MapAxis a);
std::optional<MapAxis> MapAxisFromString(std::string_view s);

// The glyph drawn over a cell whose run did not end well or whose verdict is not decided,
// whatever the map's metric: a cell's colour alone never tells a run that blew up from a
// finished bad one, nor a score rounding can move across its threshold from a settled one.
enum class CellMarker { kNone, kCross, kSquare, kCircle, kDiamond };

// The outcome categories of analysis/outcome_category.h as the status map draws them, in
// legend order: "undecided" is an open diamond over a yellow cell; diverged (x), unstable (open
// square) and failed (open circle) cells are white under their marker, which no score palette
// uses; cells whose reference did not converge are grey, unmarked (nothing was judged there).
struct OutcomeCategory {
  std::string label;   // "passes", "fails thresholds", "diverged", ...
  std::string colour;  // "#rrggbb": the cell's fill where the map has no value for it.
  CellMarker marker = CellMarker::kNone;
};
// OutcomeCategories()[OutcomeCategoryOf(p, thresholds)] is p's.
const std::vector<OutcomeCategory>& OutcomeCategories();

struct MapCell {
  const ScoredPoint* point = nullptr;
  double r_k = 0.0, y = 0.0;  // y: R_ftrunc, or dt / dt_sharp rounded (see MapAxis).
  // The box: geometric halves around R_k and R_ftrunc. A dt / dt_sharp cell reaches from the
  // next finer studied dt up to its own dt, never across dt_sharp (see BuildMapGrid).
  double x_low = 0.0, x_high = 0.0, y_low = 0.0, y_high = 0.0;
};

struct MapGrid {
  std::vector<MapCell> cells;                // By R_k, then y.
  std::vector<double> r_k_values, y_values;  // The studied values, ascending.
  double fixed_r_ftrunc = 0.0;               // kDt: the truncation shown.
};

// kRFtrunc: each (R_k, R_ftrunc) cell shows its finest time step. kDt: dt / dt_sharp against
// R_k at truncation `r_ftrunc` (the largest studied when 0); a dt cell's top edge is its own
// dt, so that nothing is painted beyond a studied step and no cell straddles the sharp bound
// dt = dt_sharp (a cell above it starts at the bound, leaving unstudied ground blank). Throws
// InputError when no point matches.
MapGrid BuildMapGrid(const std::vector<ScoredPoint>& points, MapAxis y, double r_ftrunc = 0.0);

// The dt / dt_sharp of the cells, as the map's title states it: "dt = 0.1 dt_sharp" when every
// cell shows the same ratio, else "dt = 0.1 to 0.5 dt_sharp (the finest studied per cell)".
std::string DtShown(const MapGrid& grid);

// What the map of `metric` (a score's name, "status" or "cost") judges by: a score's map by that
// score's threshold alone, derived again from `points`; nullopt when the score has no threshold
// (its map draws no boundary, and no cell fails); the status and cost maps by `criteria`.
std::optional<ValidityCriteria> MetricCriteria(const std::vector<ScoredPoint>& points,
                                               const ValidityCriteria& criteria,
                                               std::string_view metric);

// The colour range of a score's map: its map range (validation/scores.h) when a threshold
// judges by it (the threshold tells pass from fail); without one every value counts, so the
// range widens to the values the grid's cells show, in steps of 0.1.
std::pair<double, double> ScoreColourRange(const MapGrid& grid, const ScoreDefinition& score,
                                           bool thresholded);

}  // namespace shockmap

#include "views/map_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/input_error.h"

namespace shockmap {

std::string ToString(MapAxis a) { return a == MapAxis::kRFtrunc ? "rftrunc" : "dt"; }

std::optional<MapAxis> MapAxisFromString(std::string_view s) {
  for (auto a : {MapAxis::kRFtrunc, MapAxis::kDt}) {
    if (ToString(a) == s) return a;
  }
  return std::nullopt;
}

namespace {

// A non-ok status's look: a white cell under a marker for runs that ended badly, grey for a
// reference that did not converge.
OutcomeCategory StatusCategory(RunStatus s, const std::string& label) {
  switch (s) {
    case RunStatus::kDiverged:
      return {label, "#ffffff", CellMarker::kCross};
    case RunStatus::kUnstable:
      return {label, "#ffffff", CellMarker::kSquare};
    case RunStatus::kFailed:
      return {label, "#ffffff", CellMarker::kCircle};
    case RunStatus::kReferenceUnconverged:
    case RunStatus::kOk:
      break;
  }
  return {label, "#bdbdbd", CellMarker::kNone};
}

// Each of OutcomeLabels() with its look, in its order.
std::vector<OutcomeCategory> MakeCategories() {
  const std::vector<std::string>& labels = OutcomeLabels();
  std::vector<OutcomeCategory> categories = {
      {labels[0], "#1a9850"}, {labels[1], "#fdae61"}, {labels[2], "#fee08b", CellMarker::kDiamond}};
  for (RunStatus s : kAllRunStatuses) {
    if (s != RunStatus::kOk) categories.push_back(StatusCategory(s, labels[categories.size()]));
  }
  return categories;
}

// Geometric half-cell around each value: the box of value v spans [v / a, v * b].
std::map<double, std::pair<double, double>> LogCells(const std::vector<double>& values) {
  std::map<double, std::pair<double, double>> cells;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double below = i > 0 ? std::sqrt(values[i] / values[i - 1])
                               : (values.size() > 1 ? std::sqrt(values[1] / values[0]) : 1.5);
    const double above = i + 1 < values.size() ? std::sqrt(values[i + 1] / values[i]) : below;
    cells[values[i]] = {values[i] / below, values[i] * above};
  }
  return cells;
}

// The dt / dt_sharp cells: each from the next finer studied ratio (the finest: a geometric
// step below it) up to its own; a cell above the sharp bound starts at the bound.
std::map<double, std::pair<double, double>> DtCells(const std::vector<double>& ratios) {
  std::map<double, std::pair<double, double>> cells;
  for (std::size_t i = 0; i < ratios.size(); ++i) {
    double low = i > 0 ? ratios[i - 1]
                       : ratios[0] / (ratios.size() > 1 ? std::sqrt(ratios[1] / ratios[0]) : 1.5);
    if (ratios[i] > 1.0) low = std::max(low, 1.0);
    cells[ratios[i]] = {low, ratios[i]};
  }
  return cells;
}

// Rounds a dt ratio so points asked at the same factor share a row.
double RatioKey(double r) { return std::round(r * 1e6) / 1e6; }

std::vector<double> Sorted(std::vector<double> values) {
  std::ranges::sort(values);
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

}  // namespace

const std::vector<OutcomeCategory>& OutcomeCategories() {
  static const std::vector<OutcomeCategory> categories = MakeCategories();
  return categories;
}

MapGrid BuildMapGrid(const std::vector<ScoredPoint>& points, MapAxis y_axis, double r_ftrunc) {
  MapGrid grid;
  for (const auto& p : points) grid.fixed_r_ftrunc = std::max(grid.fixed_r_ftrunc, p.r_ftrunc);
  if (r_ftrunc > 0.0) grid.fixed_r_ftrunc = r_ftrunc;
  std::map<std::pair<double, double>, const ScoredPoint*> chosen;
  for (const auto& p : points) {
    double y = p.r_ftrunc;
    if (y_axis == MapAxis::kDt) {
      if (std::abs(p.r_ftrunc - grid.fixed_r_ftrunc) > 1e-9 * grid.fixed_r_ftrunc) continue;
      y = RatioKey(p.DtRatio());
    }
    auto& slot = chosen[{p.r_k, y}];
    if (slot == nullptr || p.DtRatio() < slot->DtRatio()) slot = &p;
  }
  if (chosen.empty()) throw InputError("nothing to draw: no stored point matches the map's axes");
  std::vector<double> xs, ys;
  for (const auto& [key, p] : chosen) xs.push_back(key.first), ys.push_back(key.second);
  grid.r_k_values = Sorted(xs);
  grid.y_values = Sorted(ys);
  const auto xcells = LogCells(grid.r_k_values);
  const auto ycells = y_axis == MapAxis::kDt ? DtCells(grid.y_values) : LogCells(grid.y_values);
  for (const auto& [key, p] : chosen) {
    const auto [xl, xh] = xcells.at(key.first);
    const auto [yl, yh] = ycells.at(key.second);
    grid.cells.push_back({p, key.first, key.second, xl, xh, yl, yh});
  }
  return grid;
}

std::string DtShown(const MapGrid& grid) {
  double low = INFINITY, high = 0.0;
  for (const MapCell& c : grid.cells) {
    low = std::min(low, RatioKey(c.point->DtRatio()));
    high = std::max(high, RatioKey(c.point->DtRatio()));
  }
  if (low == high) return fmt::format("dt = {:g} dt_sharp", low);
  return fmt::format("dt = {:g} to {:g} dt_sharp (the finest studied per cell)", low, high);
}

std::optional<ValidityCriteria> MetricCriteria(const std::vector<ScoredPoint>& points,
                                               const ValidityCriteria& criteria,
                                               std::string_view metric) {
  if (!FindScore(metric)) return criteria;
  const auto threshold = criteria.options.thresholds.find(metric);
  if (threshold == criteria.options.thresholds.end()) return std::nullopt;
  CriteriaOptions own = criteria.options;
  own.thresholds = {*threshold};
  return DeriveCriteria(points, own);
}

std::pair<double, double> ScoreColourRange(const MapGrid& grid, const ScoreDefinition& score,
                                           bool thresholded) {
  double low = score.map_low, high = score.map_high;
  if (thresholded) return {low, high};
  for (const MapCell& c : grid.cells) {
    if (const auto v = c.point->scores[score.name]; v && std::isfinite(*v)) {
      low = std::min(low, std::floor(*v * 10.0) / 10.0);
      high = std::max(high, std::ceil(*v * 10.0) / 10.0);
    }
  }
  return {low, high};
}

}  // namespace shockmap

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

// Colours of the categories in order: passes, fails thresholds, then the other statuses; a
// status added to kAllRunStatuses takes the next colour.
constexpr const char* kCategoryColours[] = {"#1a9850", "#fdae61", "#d73027", "#000000",
                                            "#bdbdbd", "#7b3294", "#2166ac", "#8c510a"};

std::vector<OutcomeCategory> MakeCategories() {
  std::vector<OutcomeCategory> categories = {{"passes", kCategoryColours[0]},
                                             {"fails thresholds", kCategoryColours[1]}};
  for (RunStatus s : kAllRunStatuses) {
    if (s == RunStatus::kOk) continue;
    const std::size_t i = categories.size() % std::size(kCategoryColours);
    std::string label = ToString(s);
    std::ranges::replace(label, '_', ' ');
    categories.push_back({label, kCategoryColours[i]});
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

int OutcomeCategoryOf(const ScoredPoint& p, const CriteriaOptions& thresholds) {
  if (p.status == RunStatus::kOk) return thresholds.Passes(p) ? 0 : 1;
  int index = 2;
  for (RunStatus s : kAllRunStatuses) {
    if (s == p.status) return index;
    if (s != RunStatus::kOk) ++index;
  }
  return index;  // Unreachable: every status is in kAllRunStatuses.
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
  const auto ycells = LogCells(grid.y_values);
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

}  // namespace shockmap

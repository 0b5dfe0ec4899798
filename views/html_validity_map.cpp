#include "views/html_validity_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "views/html_text.h"
#include "views/outcome_glyphs.h"

namespace shockmap {

std::filesystem::path PointPagePath(std::int64_t point_id) {
  return std::filesystem::path("points") / fmt::format("point_{}.html", point_id);
}

namespace {

// The drawing area in SVG units, and the log axes' ranges.
struct Frame {
  double left = 90, top = 15, width = 800, height = 470;
  double x_min, x_max, y_min, y_max;

  double X(double v) const { return left + width * std::log(v / x_min) / std::log(x_max / x_min); }
  double Y(double v) const {
    return top + height * (1.0 - std::log(v / y_min) / std::log(y_max / y_min));
  }
};

Frame FrameOf(const MapGrid& grid) {
  Frame f;
  f.x_min = grid.cells.front().x_low, f.x_max = grid.cells.back().x_high;
  f.y_min = INFINITY, f.y_max = 0.0;
  for (const MapCell& c : grid.cells) {
    f.y_min = std::min(f.y_min, c.y_low), f.y_max = std::max(f.y_max, c.y_high);
  }
  return f;
}

std::string Scored(const ScoredPoint& p, std::string_view score) {
  if (const std::optional<double> v = p.scores[score]) return fmt::format("{:.4f}", *v);
  return p.ReferenceUndecides(score) ? "undecided by the reference" : "not scored";
}

// One cell: filled with `fill`; its <title> opens with `shown` (the value the fill shows, or
// nothing on the outcome maps) before the point's R_k, R_ftrunc, dt, scores and status.
std::string CellRect(const MapCell& c, const Frame& f, const CriteriaOptions& th,
                     const std::string& fill, const std::string& shown) {
  const ScoredPoint& p = *c.point;
  const OutcomeCategory& category = OutcomeCategories()[OutcomeCategoryOf(p, th)];
  const std::string status = ToString(p.status);
  std::string scores, data;
  for (const ScoreDefinition& score : Scores()) {
    scores += fmt::format("{} = {}, ", score.label, Scored(p, score.name));
    data += fmt::format("data-{}=\"{}\" ", score.name, Scored(p, score.name));
  }
  const std::string spread = th.Undecided(p) ? "; " + th.Straddling(p) : "";
  const std::string tip = fmt::format(
      "{}R_k = {:.6g}, R_ftrunc = {:.6g}, dt = {:.4g} s ({:.3g} dt_sharp), {}status {} ({}{})",
      shown, p.r_k, p.r_ftrunc, p.dt_s, p.DtRatio(), scores, status, category.label, spread);
  const double x = f.X(c.x_low), y = f.Y(c.y_high), w = f.X(c.x_high) - x, h = f.Y(c.y_low) - y;
  return fmt::format(
      "<a href=\"{href}\"><rect class=\"cell\" x=\"{x:.2f}\" y=\"{y:.2f}\" width=\"{w:.2f}\" "
      "height=\"{h:.2f}\" fill=\"{fill}\" data-point-id=\"{id}\" data-rk=\"{rk:.6g}\" "
      "data-rftrunc=\"{rft:.6g}\" data-dt=\"{dt:.4g}\" data-dt-ratio=\"{ratio:.3g}\" "
      "{scores}data-status=\"{status}\" data-outcome=\"{outcome}\">"
      "<title>{tip}</title></rect>{marker}</a>\n",
      fmt::arg("href", PointPagePath(p.point_id).generic_string()), fmt::arg("x", x),
      fmt::arg("y", y), fmt::arg("w", w), fmt::arg("h", h), fmt::arg("fill", fill),
      fmt::arg("marker", MarkerShape(category.marker, x, y, w, h)), fmt::arg("id", p.point_id),
      fmt::arg("rk", p.r_k), fmt::arg("rft", p.r_ftrunc), fmt::arg("dt", p.dt_s),
      fmt::arg("ratio", p.DtRatio()), fmt::arg("scores", data),
      fmt::arg("status", HtmlEscaped(status)), fmt::arg("outcome", HtmlEscaped(category.label)),
      fmt::arg("tip", HtmlEscaped(tip)));
}

std::string AxesSvg(const MapGrid& grid, const Frame& f, const std::string& ylabel) {
  std::string svg;
  for (double v : grid.r_k_values) {
    svg += fmt::format(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\" transform=\"rotate(-35 {:.1f} "
        "{:.1f})\">{:.4g}</text>\n",
        f.X(v), f.top + f.height + 16, f.X(v), f.top + f.height + 16, v);
  }
  for (double v : grid.y_values) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:.4g}</text>\n",
                       f.left - 6, f.Y(v) + 4, v);
  }
  svg += fmt::format(
      "<text class=\"axis\" x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">R_k = k_s / K_bend "
      "(studied values)</text>\n<text class=\"axis\" x=\"16\" y=\"{:.1f}\" text-anchor=\"middle\" "
      "transform=\"rotate(-90 16 {:.1f})\">{}</text>\n",
      f.left + f.width / 2, f.top + f.height + 62, f.top + f.height / 2, f.top + f.height / 2,
      HtmlEscaped(ylabel));
  return svg;
}

// The line over the cells: on the R_ftrunc map the envelope C R_k^p above the knee (none
// without a fit), on the dt map the sharp stability bound dt = dt_sharp; clipped to the frame.
std::string Boundary(const ValidityCriteria& criteria, const Frame& f, MapAxis y) {
  if (y == MapAxis::kDt) {
    if (f.y_min > 1.0 || f.y_max < 1.0) return "";
    return fmt::format(
        "<line class=\"boundary\" x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" "
        "stroke=\"#000\" stroke-width=\"3\" pointer-events=\"none\"/>\n",
        f.left, f.Y(1.0), f.left + f.width, f.Y(1.0));
  }
  if (!criteria.fit) return "";
  std::string points;
  const double from = std::max(criteria.fit->knee_r_k, f.x_min);
  for (int i = 0; i <= 60; ++i) {
    const double x = from * std::pow(f.x_max / from, i / 60.0);
    const double y = criteria.fit->c_envelope * std::pow(x, criteria.fit->p);
    if (y < f.y_min || y > f.y_max) continue;
    points += fmt::format("{:.1f},{:.1f} ", f.X(x), f.Y(y));
  }
  return fmt::format(
      "<polyline class=\"boundary\" points=\"{}\" fill=\"none\" stroke=\"#000\" "
      "stroke-width=\"3\" pointer-events=\"none\"/>\n",
      points);
}

std::string Legend(const MapGrid& grid, const ValidityCriteria& criteria, MapAxis y) {
  std::vector<bool> present(OutcomeCategories().size(), false);
  for (const MapCell& c : grid.cells) present[OutcomeCategoryOf(*c.point, criteria.options)] = true;
  std::string items = OutcomeLegendItems(present);
  if (y == MapAxis::kRFtrunc && criteria.fit) {
    items += fmt::format(
        "<span>black line: derived boundary R_ftrunc = {:.3g} R_k^{:.3f} above the knee R_k = "
        "{:.4g}, raised to cover the smallest passing R_ftrunc of every R_k</span>",
        criteria.fit->c_envelope, criteria.fit->p, criteria.fit->knee_r_k);
  }
  if (y == MapAxis::kDt) {
    items += "<span>black line: the sharp stability bound dt = 2 / ω<sub>max</sub></span>";
  }
  return "<p class=\"legend\">" + items + "</p>\n";
}

// The <svg> of a map: its cells, the line over them and its axes.
std::string Svg(const MapGrid& grid, MapAxis y, const ValidityCriteria& criteria, const Frame& f,
                const std::string& cells, const std::string& id) {
  const std::string ylabel = y == MapAxis::kRFtrunc ? "R_ftrunc = f_trunc / f_1" : "dt / dt_sharp";
  return fmt::format(
      "<svg class=\"map\" id=\"{id}\" viewBox=\"0 0 {w:.0f} {h:.0f}\" "
      "xmlns=\"http://www.w3.org/2000/svg\">\n{cells}{boundary}{axes}</svg>\n",
      fmt::arg("id", HtmlEscaped(id)), fmt::arg("w", f.left + f.width + 20),
      fmt::arg("h", f.top + f.height + 75), fmt::arg("cells", cells),
      fmt::arg("boundary", Boundary(criteria, f, y)), fmt::arg("axes", AxesSvg(grid, f, ylabel)));
}

// A colour scale: colour stops over [0, 1] and how a value maps there (linear or log between
// `low` and `high`, clamped), as the gnuplot maps colour (views/validity_map.cpp).
struct ColourScale {
  std::string metric, label;  // "err", "Err"; "cost", "CPU time (s)".
  double low = 0.0, high = 1.0;
  bool log = false;
  std::vector<std::pair<double, std::string>> stops;  // Ascending positions, "#rrggbb".
  std::string note;                                   // The threshold, or what cost means.

  double Position(double v) const {
    if (!(high > low)) return 0.5;
    const double t = log ? std::log(v / low) / std::log(high / low) : (v - low) / (high - low);
    return std::clamp(t, 0.0, 1.0);
  }
  std::string ColourOf(double v) const {
    const double t = Position(v);
    auto next = std::ranges::find_if(stops, [&](const auto& s) { return s.first > t; });
    if (next == stops.begin()) return stops.front().second;
    if (next == stops.end()) return stops.back().second;
    const auto& [t0, c0] = *(next - 1);
    const auto& [t1, c1] = *next;
    const double w = (t - t0) / (t1 - t0);
    std::string mixed = "#";
    for (int k = 1; k < 7; k += 2) {
      const int a = std::stoi(c0.substr(k, 2), nullptr, 16);
      const int b = std::stoi(c1.substr(k, 2), nullptr, 16);
      mixed += fmt::format("{:02x}", static_cast<int>(std::lround(a + w * (b - a))));
    }
    return mixed;
  }
};

// A score's scale: bad red to good green over its colour range (ScoreColourRange), split at its
// threshold when the criteria judge by it.
ColourScale ScoreScale(const MapGrid& grid, const ScoreDefinition& score,
                       const CriteriaOptions& th) {
  const bool smaller = score.better == Better::kSmaller;
  const std::string good = "#1a9850", bad = "#d73027";
  ColourScale s;
  const auto threshold = th.thresholds.find(score.name);
  s.metric = score.name, s.label = score.label;
  std::tie(s.low, s.high) = ScoreColourRange(grid, score, threshold != th.thresholds.end());
  if (threshold == th.thresholds.end()) {
    s.stops = {{0.0, smaller ? good : bad}, {0.5, "#ffffbf"}, {1.0, smaller ? bad : good}};
    s.note = fmt::format("{} ({}), no threshold: no boundary drawn", score.label, score.source);
    return s;
  }
  const double t = s.Position(threshold->second);
  s.stops = {{0.0, smaller ? good : bad},
             {t, smaller ? "#a6d96a" : "#fdae61"},
             {t, smaller ? "#fdae61" : "#a6d96a"},
             {1.0, smaller ? bad : good}};
  s.note = fmt::format("{} ({}), threshold {:g}", score.label, score.source, threshold->second);
  return s;
}

// CPU time on a log scale over the cells' range.
ColourScale CostScale(const MapGrid& grid) {
  ColourScale s;
  s.metric = "cost", s.label = "CPU time (s)", s.low = INFINITY, s.high = 0.0, s.log = true;
  for (const MapCell& c : grid.cells) {
    if (c.point->cpu_s > 0.0) {
      s.low = std::min(s.low, c.point->cpu_s), s.high = std::max(s.high, c.point->cpu_s);
    }
  }
  s.stops = {{0.0, "#f7fbff"}, {0.5, "#6baed6"}, {1.0, "#08306b"}};
  s.note = "CPU time of the numerical run, log scale";
  return s;
}

std::optional<double> ValueOf(const ScoredPoint& p, const ColourScale& s) {
  if (s.metric != "cost") return p.scores[s.metric];
  if (p.cpu_s > 0.0) return p.cpu_s;
  return std::nullopt;
}

// The scale as a gradient bar between its ends, its note, and the categories of the cells
// without a value (drawn in their outcome colour).
std::string ScaleLegend(const MapGrid& grid, const ColourScale& s, const CriteriaOptions& th) {
  std::string gradient;
  for (const auto& [t, colour] : s.stops) gradient += fmt::format(", {} {:.1f}%", colour, 100 * t);
  std::string items = fmt::format(
      "<span class=\"scale\">{:.4g} <i style=\"width:12em;background:linear-gradient(to "
      "right{})\"></i> {:.4g}</span><span>{}</span>",
      s.low, gradient, s.high, HtmlEscaped(s.note));
  std::vector<bool> present(OutcomeCategories().size(), false);
  for (const MapCell& c : grid.cells) {
    if (!ValueOf(*c.point, s)) present[OutcomeCategoryOf(*c.point, th)] = true;
  }
  for (std::size_t i = 0; i < present.size(); ++i) {
    if (!present[i]) continue;
    items += fmt::format("<span><i style=\"background:{}\"></i>{} (no value)</span>",
                         OutcomeCategories()[i].colour, HtmlEscaped(OutcomeCategories()[i].label));
  }
  return "<p class=\"legend\">" + items + "</p>\n";
}

// One metric's map in a <div class="metric-map" data-metric="NAME">.
std::string MetricMap(const MapGrid& grid, const ColourScale& s, const ValidityCriteria& criteria,
                      const std::string& id) {
  const Frame f = FrameOf(grid);
  std::string cells;
  for (const MapCell& c : grid.cells) {
    const auto value = ValueOf(*c.point, s);
    const std::string fill =
        value ? s.ColourOf(*value)
              : OutcomeCategories()[OutcomeCategoryOf(*c.point, criteria.options)].colour;
    const std::string shown = value ? fmt::format("{} = {:.6g}; ", s.label, *value)
                                    : fmt::format("{}: no value; ", s.label);
    cells += CellRect(c, f, criteria.options, fill, shown);
  }
  return fmt::format("<div class=\"metric-map\" data-metric=\"{0}\">\n{1}{2}</div>\n",
                     HtmlEscaped(s.metric),
                     Svg(grid, MapAxis::kRFtrunc, criteria, f, cells, id + "-" + s.metric),
                     ScaleLegend(grid, s, criteria.options));
}

}  // namespace

std::string HtmlValidityMap(const MapGrid& grid, MapAxis y, const ValidityCriteria& criteria,
                            const std::string& id) {
  const Frame f = FrameOf(grid);
  std::string cells;
  for (const MapCell& c : grid.cells) {
    cells +=
        CellRect(c, f, criteria.options,
                 OutcomeCategories()[OutcomeCategoryOf(*c.point, criteria.options)].colour, "");
  }
  return Svg(grid, y, criteria, f, cells, id) + Legend(grid, criteria, y);
}

std::string HtmlMetricMaps(const std::vector<ScoredPoint>& points, const MapGrid& grid,
                           const ValidityCriteria& criteria, const std::string& id) {
  // Each scale with the criteria its map judges and draws by (MetricCriteria); without a
  // threshold, none: no cell fails and no boundary is drawn.
  std::vector<std::pair<ColourScale, ValidityCriteria>> scales;
  for (const ScoreDefinition& score : Scores()) {
    const bool scored = std::ranges::any_of(
        grid.cells, [&](const MapCell& c) { return c.point->scores[score.name].has_value(); });
    if (!scored) continue;
    ValidityCriteria unjudged;  // Without a threshold no cell fails.
    unjudged.options.thresholds = {};
    const ValidityCriteria own =
        MetricCriteria(points, criteria, score.name).value_or(std::move(unjudged));
    scales.emplace_back(ScoreScale(grid, score, own.options), own);
  }
  scales.emplace_back(CostScale(grid), criteria);
  std::string options, maps;
  for (const auto& [s, judged] : scales) {
    options += fmt::format("<option value=\"{}\">{}</option>", HtmlEscaped(s.metric),
                           HtmlEscaped(s.label));
    maps += MetricMap(grid, s, judged, id);
  }
  return fmt::format(
      "<div class=\"metric-maps\" id=\"{0}\"><p><label>Metric shown: <select "
      "class=\"metric-switch\" data-maps=\"{0}\">{1}</select></label></p>\n{2}</div>\n",
      HtmlEscaped(id), options, maps);
}

}  // namespace shockmap

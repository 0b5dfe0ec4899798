#include "views/html_validity_map.h"

#include <fmt/format.h>

#include <cmath>

#include "views/html_text.h"

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

std::string Scored(const std::optional<double>& v) {
  return v ? fmt::format("{:.4f}", *v) : "not scored";
}

// The category's marker centred on the cell (x, y, w, h in SVG units), drawn in black and
// transparent to the pointer so that hovering reaches the cell; "" without a marker.
std::string MarkerShape(CellMarker marker, double x, double y, double w, double h) {
  const double cx = x + w / 2, cy = y + h / 2, r = std::min(9.0, 0.3 * std::min(w, h));
  const char* style = "fill=\"none\" stroke=\"#000\" stroke-width=\"2\" pointer-events=\"none\"";
  switch (marker) {
    case CellMarker::kCross:
      return fmt::format(
          "<path class=\"marker\" d=\"M{:.1f} {:.1f}L{:.1f} {:.1f}M{:.1f} {:.1f}L{:.1f} "
          "{:.1f}\" {}/>",
          cx - r, cy - r, cx + r, cy + r, cx - r, cy + r, cx + r, cy - r, style);
    case CellMarker::kSquare:
      return fmt::format(
          "<rect class=\"marker\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
          "{}/>",
          cx - r, cy - r, 2 * r, 2 * r, style);
    case CellMarker::kCircle:
      return fmt::format("<circle class=\"marker\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\" {}/>",
                         cx, cy, r, style);
    case CellMarker::kNone:
      break;
  }
  return "";
}

// The legend's sample of a category: its marker as a character, or its fill.
std::string LegendSample(const OutcomeCategory& category) {
  switch (category.marker) {
    case CellMarker::kCross:
      return "<b class=\"marker\">&#215;</b>";
    case CellMarker::kSquare:
      return "<b class=\"marker\">&#9633;</b>";
    case CellMarker::kCircle:
      return "<b class=\"marker\">&#9675;</b>";
    case CellMarker::kNone:
      break;
  }
  return fmt::format("<i style=\"background:{}\"></i>", category.colour);
}

std::string CellRect(const MapCell& c, const Frame& f, const CriteriaOptions& th) {
  const ScoredPoint& p = *c.point;
  const OutcomeCategory& category = OutcomeCategories()[OutcomeCategoryOf(p, th)];
  const std::string status = ToString(p.status);
  std::string scores, data;
  for (const ScoreDefinition& score : Scores()) {
    scores += fmt::format("{} = {}, ", score.label, Scored(p.scores[score.name]));
    data += fmt::format("data-{}=\"{}\" ", score.name, Scored(p.scores[score.name]));
  }
  const std::string tip = fmt::format(
      "R_k = {:.6g}, R_ftrunc = {:.6g}, dt = {:.4g} s ({:.3g} dt_sharp), {}status {} ({})", p.r_k,
      p.r_ftrunc, p.dt_s, p.DtRatio(), scores, status, category.label);
  const double x = f.X(c.x_low), y = f.Y(c.y_high), w = f.X(c.x_high) - x, h = f.Y(c.y_low) - y;
  return fmt::format(
      "<a href=\"{href}\"><rect class=\"cell\" x=\"{x:.2f}\" y=\"{y:.2f}\" width=\"{w:.2f}\" "
      "height=\"{h:.2f}\" fill=\"{fill}\" data-point-id=\"{id}\" data-rk=\"{rk:.6g}\" "
      "data-rftrunc=\"{rft:.6g}\" data-dt=\"{dt:.4g}\" data-dt-ratio=\"{ratio:.3g}\" "
      "{scores}data-status=\"{status}\" data-outcome=\"{outcome}\">"
      "<title>{tip}</title></rect>{marker}</a>\n",
      fmt::arg("href", PointPagePath(p.point_id).generic_string()), fmt::arg("x", x),
      fmt::arg("y", y), fmt::arg("w", w), fmt::arg("h", h), fmt::arg("fill", category.colour),
      fmt::arg("marker", MarkerShape(category.marker, x, y, w, h)), fmt::arg("id", p.point_id),
      fmt::arg("rk", p.r_k), fmt::arg("rft", p.r_ftrunc), fmt::arg("dt", p.dt_s),
      fmt::arg("ratio", p.DtRatio()), fmt::arg("scores", data),
      fmt::arg("status", HtmlEscaped(status)), fmt::arg("outcome", HtmlEscaped(category.label)),
      fmt::arg("tip", HtmlEscaped(tip)));
}

std::string Axes(const MapGrid& grid, const Frame& f, const std::string& ylabel) {
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
  std::string items;
  for (std::size_t i = 0; i < present.size(); ++i) {
    if (!present[i]) continue;
    items += fmt::format("<span>{}{}</span>", LegendSample(OutcomeCategories()[i]),
                         HtmlEscaped(OutcomeCategories()[i].label));
  }
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

}  // namespace

std::string HtmlValidityMap(const MapGrid& grid, MapAxis y, const ValidityCriteria& criteria,
                            const std::string& id) {
  const Frame f = FrameOf(grid);
  std::string cells;
  for (const MapCell& c : grid.cells) cells += CellRect(c, f, criteria.options);
  const std::string ylabel = y == MapAxis::kRFtrunc ? "R_ftrunc = f_trunc / f_1" : "dt / dt_sharp";
  return fmt::format(
      "<svg class=\"map\" id=\"{id}\" viewBox=\"0 0 {w:.0f} {h:.0f}\" "
      "xmlns=\"http://www.w3.org/2000/svg\">\n{cells}{boundary}{axes}</svg>\n"
      "{legend}",
      fmt::arg("id", HtmlEscaped(id)), fmt::arg("w", f.left + f.width + 20),
      fmt::arg("h", f.top + f.height + 75), fmt::arg("cells", cells),
      fmt::arg("boundary", Boundary(criteria, f, y)), fmt::arg("axes", Axes(grid, f, ylabel)),
      fmt::arg("legend", Legend(grid, criteria, y)));
}

}  // namespace shockmap

#include "views/validity_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "core/input_error.h"
#include "formats/output_file.h"
#include "views/gnuplot.h"

namespace shockmap {

std::vector<std::string> MapMetrics() {
  std::vector<std::string> metrics;
  for (const ScoreDefinition& score : Scores()) metrics.emplace_back(score.name);
  metrics.emplace_back("status");
  metrics.emplace_back("cost");
  return metrics;
}

bool IsMapMetric(std::string_view name) { return std::ranges::count(MapMetrics(), name) > 0; }

namespace {

double CellValue(const ScoredPoint& p, const std::string& metric) {
  if (metric == "cost") return p.cpu_s;
  if (metric == "status") return NAN;
  return p.scores[metric].value_or(NAN);
}

// Index 0, one line per cell: r_k y x_low x_high y_low y_high value category (the index in
// OutcomeCategories()) valued (1 when value is a number; gnuplot skips a line whose used
// column reads NaN). Index 1: the smallest passing R_ftrunc of each R_k (the criteria's
// boundary points).
void WriteMapData(const MapGrid& grid, const ValidityCriteria& criteria, const std::string& metric,
                  const std::filesystem::path& data_file) {
  AtomicFile file(data_file);
  std::ostream& data = file.Stream();
  data << "# r_k y x_low x_high y_low y_high value category valued\n";
  for (const MapCell& c : grid.cells) {
    const double value = CellValue(*c.point, metric);
    data << fmt::format("{} {} {} {} {} {} {} {} {}\n", c.r_k, c.y, c.x_low, c.x_high, c.y_low,
                        c.y_high, std::isfinite(value) ? fmt::format("{}", value) : "NaN",
                        OutcomeCategoryOf(*c.point, criteria.options),
                        std::isfinite(value) ? 1 : 0);
  }
  data << "\n\n# r_k smallest_passing_r_ftrunc\n";
  for (const RkBoundary& b : criteria.boundary) {
    if (b.r_ftrunc_min) data << fmt::format("{} {}\n", b.r_k, *b.r_ftrunc_min);
  }
  file.Commit();
}

// How a metric is coloured: the palette commands, the colour bar's label, the title.
struct MetricStyle {
  std::string palette, cb, title;
};

// A score's colours: from bad (red) to good (green) over `range` (ScoreColourRange), split at
// its threshold when it has one.
MetricStyle ScoreStyle(const ScoreDefinition& score, const CriteriaOptions& th,
                       std::pair<double, double> range) {
  const bool smaller = score.better == Better::kSmaller;
  const char* low_colour = smaller ? "'#1a9850'" : "'#d73027'";
  const char* high_colour = smaller ? "'#d73027'" : "'#1a9850'";
  const auto threshold = th.thresholds.find(score.name);
  const std::string name = fmt::format("{} ({})", score.label, score.source);
  if (threshold == th.thresholds.end()) {
    const auto [low, high] = range;
    return {fmt::format("set palette defined ({} {}, {} '#ffffbf', {} {})\nset cbrange [{}:{}]\n",
                        low, low_colour, 0.5 * (low + high), high, high_colour, low, high),
            std::string(score.label), fmt::format("{}, no threshold: no boundary drawn", name)};
  }
  return {fmt::format("set palette defined ({lo} {lc}, {t} {lt}, {t} {ht}, {hi} {hc})\n"
                      "set cbrange [{lo}:{hi}]\nset cbtics add ('{t:g}' {t})\n",
                      fmt::arg("lo", range.first), fmt::arg("lc", low_colour),
                      fmt::arg("t", threshold->second),
                      fmt::arg("lt", smaller ? "'#a6d96a'" : "'#fdae61'"),
                      fmt::arg("ht", smaller ? "'#fdae61'" : "'#a6d96a'"),
                      fmt::arg("hi", range.second), fmt::arg("hc", high_colour)),
          std::string(score.label), fmt::format("{}, threshold {:g}", name, threshold->second)};
}

MetricStyle StyleOf(const MapGrid& grid, const std::string& metric, const CriteriaOptions& th) {
  if (metric == "cost") {
    return {
        "set palette defined (0 '#f7fbff', 0.5 '#6baed6', 1 '#08306b')\nset logscale cb\n"
        "set format cb '10^{%L}'\n",
        "CPU time (s)", "CPU time of the numerical run"};
  }
  if (metric == "status") return {"unset colorbox\n", "", "outcome"};
  const ScoreDefinition& score = *FindScore(metric);
  return ScoreStyle(score, th, ScoreColourRange(grid, score, th.thresholds.contains(metric)));
}

// gnuplot's point type of a marker: 2 a cross, 4 an open square, 6 an open circle, 12 an open
// diamond.
int PointType(CellMarker m) {
  switch (m) {
    case CellMarker::kCross:
      return 2;
    case CellMarker::kSquare:
      return 4;
    case CellMarker::kCircle:
      return 6;
    case CellMarker::kDiamond:
      return 12;
    case CellMarker::kNone:
      break;
  }
  return 0;
}

// Which categories the map's cells hold: any cell, and cells without a value.
struct PresentCategories {
  std::vector<bool> any, unvalued;
};

PresentCategories Present(const MapGrid& grid, const std::string& metric,
                          const CriteriaOptions& th) {
  PresentCategories present{std::vector<bool>(OutcomeCategories().size(), false),
                            std::vector<bool>(OutcomeCategories().size(), false)};
  for (const MapCell& c : grid.cells) {
    const int i = OutcomeCategoryOf(*c.point, th);
    present.any[i] = true;
    if (metric == "status" || !std::isfinite(CellValue(*c.point, metric)))
      present.unvalued[i] = true;
  }
  return present;
}

// The plot clauses of the cells: coloured by the metric's palette, except cells without a
// value (no score, or the status map), filled with their category's colour; then each marked
// category's marker at the centre of its cells, valued or not. The legend names each category
// present once: by its marker when it has one, else by its fill.
std::string CellClauses(const MapGrid& grid, const std::string& metric, const CriteriaOptions& th,
                        const std::string& data) {
  const PresentCategories present = Present(grid, metric, th);
  std::vector<std::string> clauses;
  if (metric != "status") {
    clauses.push_back(
        " index 0 using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 border lc rgb "
        "'#ffffff' fc palette notitle");
  }
  auto label = [&](std::size_t i) {
    const std::string& name = OutcomeCategories()[i].label;
    return GnuplotQuoted(metric == "status" || !present.unvalued[i] ? name : name + " (no score)");
  };
  for (std::size_t i = 0; i < present.any.size(); ++i) {
    if (!present.unvalued[i]) continue;
    const OutcomeCategory& category = OutcomeCategories()[i];
    clauses.push_back(fmt::format(
        " index 0 using 1:($8 == {} && $9 == 0 ? $2 : 1/0):3:4:5:6 with boxxyerror fs solid 1.0 "
        "border lc rgb '#ffffff' fc rgb '{}' {}",
        i, category.colour,
        category.marker == CellMarker::kNone ? "title " + label(i) : std::string("notitle")));
  }
  for (std::size_t i = 0; i < present.any.size(); ++i) {
    const OutcomeCategory& category = OutcomeCategories()[i];
    if (!present.any[i] || category.marker == CellMarker::kNone) continue;
    clauses.push_back(
        fmt::format(" index 0 using (sqrt($3 * $4)):($8 == {} ? sqrt($5 * $6) : 1/0) with points "
                    "pt {} ps 3 lw 2 lc rgb '#000000' title {}",
                    i, PointType(category.marker), label(i)));
  }
  std::string joined;
  for (const std::string& c : clauses) {
    joined += joined.empty() ? data + c : ", \\\n     ''" + c;
  }
  return joined;
}

// The curves drawn over the cells: the boundary of the map's criteria with the points it
// envelopes and the paper's rules, or, on the dt map, the stability bound when it lies within
// the range shown (`dt_ratio_max`, the top of the y range). Without criteria (a score without a
// threshold) the legend says that no boundary is drawn.
std::string Overlays(const std::optional<ValidityCriteria>& criteria, const std::string& metric,
                     MapAxis y, double dt_ratio_max) {
  if (y == MapAxis::kDt) {
    return dt_ratio_max >= 1.0 ? ", \\\n     1 with lines lw 3 lc rgb '#000000' title 'sharp "
                                 "stability bound 2/ω_{max}'"
                               : "";
  }
  std::string overlays;
  if (!criteria) {
    const ScoreDefinition& score = *FindScore(metric);
    std::string flag = score.ThresholdKey();
    std::ranges::replace(flag, '_', '-');
    overlays = ", \\\n     keyentry title " +
               GnuplotQuoted(fmt::format("{} has no threshold, so no boundary is drawn (give one "
                                         "with --{} or in the study file's thresholds)",
                                         score.label, flag));
  } else {
    const std::string judged = ThresholdsText(criteria->options, false);
    overlays = fmt::format(
        ", \\\n     '' index 1 using 1:2 with points pt 9 ps 1.6 lc rgb '#000000' title 'smallest "
        "R_{{ftrunc}} passing {} at each R_k'",
        judged);
    if (criteria->fit) {
      overlays += fmt::format(
          ", \\\n     (x >= {k} ? {c} * x**{p} : 1/0) with lines lw 3 dt 1 lc rgb '#000000' "
          "title 'derived boundary ({j}): R_{{ftrunc}} = {c:.3g} R_k^{{{p:.3f}}}, the fit above "
          "the knee R_k = {k:.4g} raised to cover every point'",
          fmt::arg("j", judged), fmt::arg("k", criteria->fit->knee_r_k),
          fmt::arg("c", criteria->fit->c_envelope), fmt::arg("p", criteria->fit->p));
    }
  }
  return overlays +
         ", \\\n     sqrt(x) with lines lw 2 dt 2 lc rgb '#5e3c99' title 'paper eq. 10: R_{ftrunc} "
         "= "
         "sqrt(R_k)', \\\n     (x > 100 ? 300 : 1/0) with lines lw 2 dt 4 lc rgb '#0571b0' title "
         "'paper "
         "eq. 11: R_{ftrunc} = 300 for R_k > 10^2'";
}

// What the script needs beyond the style: names, axes and ranges.
struct MapFrame {
  std::string title, ylabel, tics, cells, overlays;
  std::filesystem::path image;
  double xmin, xmax, ymin, ymax;
};

std::string MapScript(const MapFrame& f, const MetricStyle& style) {
  return fmt::format(
      R"(set terminal {terminal}
set output {out}
set title {title} font ',13' noenhanced
set logscale x
set logscale y
{tics}set xlabel 'R_k = k_s / K_{{bend}} (the studied values ticked)'
set ylabel {ylabel}
set cblabel {cb}
{palette}set xrange [{xmin}:{xmax}]
set yrange [{ymin}:{ymax}]
set key outside bottom center horizontal box opaque font ',10' samplen 3 maxcols 3
set grid front lc rgb '#999999'
set samples 400
plot {cells}{overlays}
)",
      fmt::arg("terminal", TerminalFor(f.image, 1100, 850)),
      fmt::arg("out", GnuplotOutputName(f.image)), fmt::arg("title", GnuplotQuoted(f.title)),
      fmt::arg("tics", f.tics), fmt::arg("ylabel", GnuplotQuoted(f.ylabel)),
      fmt::arg("cb", GnuplotQuoted(style.cb)), fmt::arg("palette", style.palette),
      fmt::arg("xmin", f.xmin), fmt::arg("xmax", f.xmax), fmt::arg("ymin", f.ymin),
      fmt::arg("ymax", f.ymax), fmt::arg("cells", f.cells), fmt::arg("overlays", f.overlays));
}

}  // namespace

void DrawValidityMap(const std::string& study, const std::vector<ScoredPoint>& points,
                     const ValidityCriteria& criteria, const MapOptions& options,
                     const std::filesystem::path& file) {
  const MapGrid grid = BuildMapGrid(points, options.y, options.r_ftrunc.value_or(0.0));
  TerminalFor(file, 1100, 850);  // Throws for a bad extension before any file is written.
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const auto data_file = std::filesystem::path(file).replace_extension(".dat");
  const std::optional<ValidityCriteria> drawn = MetricCriteria(points, criteria, options.metric);
  // Without a threshold no cell fails: the cells' categories are their runs' statuses alone.
  ValidityCriteria unjudged;
  unjudged.options.thresholds = {};
  const ValidityCriteria judged = drawn.value_or(unjudged);
  WriteMapData(grid, judged, options.metric, data_file);
  const MetricStyle style = StyleOf(grid, options.metric, judged.options);
  const bool by_dt = options.y == MapAxis::kDt;
  const std::string shown =
      by_dt ? fmt::format("at R_ftrunc = {:g}", grid.fixed_r_ftrunc) : "at " + DtShown(grid);
  const double ymax = std::ranges::max(grid.cells, {}, &MapCell::y_high).y_high;
  const MapFrame frame{
      study + ": " + style.title + ", " + shown,
      by_dt ? "dt / dt_{sharp}" : "R_{ftrunc} = f_{trunc} / f_1",
      GnuplotTics("x", grid.r_k_values) + GnuplotTics("y", grid.y_values),
      CellClauses(grid, options.metric, judged.options, GnuplotFileName(data_file)),
      Overlays(drawn, options.metric, options.y, ymax),
      file,
      grid.cells.front().x_low,
      grid.cells.back().x_high,
      std::ranges::min(grid.cells, {}, &MapCell::y_low).y_low,
      ymax};
  RunGnuplot(MapScript(frame, style), std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

#include "views/validity_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/input_error.h"
#include "formats/output_file.h"
#include "views/gnuplot.h"

namespace shockmap {

std::string ToString(MapMetric m) {
  switch (m) {
    case MapMetric::kErr:
      return "err";
    case MapMetric::kSrf:
      return "srf";
    case MapMetric::kCost:
      return "cost";
    case MapMetric::kStatus:
      return "status";
  }
  return "unknown";
}

std::optional<MapMetric> MapMetricFromString(std::string_view s) {
  for (auto m : {MapMetric::kErr, MapMetric::kSrf, MapMetric::kCost, MapMetric::kStatus}) {
    if (ToString(m) == s) return m;
  }
  return std::nullopt;
}

std::string ToString(MapAxis a) { return a == MapAxis::kRFtrunc ? "rftrunc" : "dt"; }

std::optional<MapAxis> MapAxisFromString(std::string_view s) {
  for (auto a : {MapAxis::kRFtrunc, MapAxis::kDt}) {
    if (ToString(a) == s) return a;
  }
  return std::nullopt;
}

namespace {

// Status classes drawn by the status map, in colour order.
enum StatusClass {
  kPasses = 0,
  kFailsThresholds = 1,
  kDiverged = 2,
  kFailed = 3,
  kUnscored = 4,
  kUnstable = 5  // Reached the end undamped with its energy grown past the limit.
};

StatusClass ClassOf(const ScoredPoint& p, const CriteriaOptions& o) {
  if (p.status == RunStatus::kDiverged) return kDiverged;
  if (p.status == RunStatus::kUnstable) return kUnstable;
  if (p.status == RunStatus::kFailed) return kFailed;
  if (p.status == RunStatus::kReferenceUnconverged) return kUnscored;
  return o.Passes(p) ? kPasses : kFailsThresholds;
}

// Geometric half-cell around each grid value: the box of value v spans [v / a, v * b].
std::map<double, std::pair<double, double>> LogCells(std::vector<double> values) {
  std::ranges::sort(values);
  values.erase(std::unique(values.begin(), values.end()), values.end());
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

// The points drawn, by (R_k, y): the finest time step on the R_ftrunc map; on the dt map only
// the points at truncation `fixed_rft`.
using Cells = std::map<std::pair<double, double>, const ScoredPoint*>;

Cells PickCells(const std::vector<ScoredPoint>& points, const MapOptions& options,
                double fixed_rft) {
  Cells cell;
  for (const auto& p : points) {
    double y = p.r_ftrunc;
    if (options.y == MapAxis::kDt) {
      if (std::abs(p.r_ftrunc - fixed_rft) > 1e-9 * fixed_rft) continue;
      y = RatioKey(p.DtRatio());
    }
    auto& slot = cell[{p.r_k, y}];
    if (slot == nullptr || p.DtRatio() < slot->DtRatio()) slot = &p;
  }
  if (cell.empty()) throw InputError("nothing to draw: no stored point matches the map's axes");
  return cell;
}

double CellValue(const ScoredPoint& p, MapMetric metric, const CriteriaOptions& th) {
  switch (metric) {
    case MapMetric::kErr:
      return p.err.value_or(NAN);
    case MapMetric::kSrf:
      return p.srf.value_or(NAN);
    case MapMetric::kCost:
      return p.cpu_s;
    case MapMetric::kStatus:
      return ClassOf(p, th);
  }
  return NAN;
}

using CellBounds = std::map<double, std::pair<double, double>>;

// One line per cell: r_k y x_low x_high y_low y_high value status_class.
void WriteMapData(const Cells& cells, const CellBounds& xcells, const CellBounds& ycells,
                  MapMetric metric, const CriteriaOptions& th,
                  const std::filesystem::path& data_file) {
  AtomicFile file(data_file);
  std::ostream& data = file.Stream();
  data << "# r_k y x_low x_high y_low y_high value status_class\n";
  for (const auto& [key, p] : cells) {
    const double value = CellValue(*p, metric, th);
    const auto [xl, xh] = xcells.at(key.first);
    const auto [yl, yh] = ycells.at(key.second);
    data << fmt::format("{:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {} {}\n", key.first,
                        key.second, xl, xh, yl, yh,
                        std::isfinite(value) ? fmt::format("{:.6g}", value) : "NaN",
                        static_cast<int>(ClassOf(*p, th)));
  }
  file.Commit();
}

// How a metric is coloured: the palette commands, the colour bar's label, the title.
struct MetricStyle {
  std::string palette, cb, title;
};

MetricStyle StyleOf(MapMetric metric, const CriteriaOptions& th) {
  switch (metric) {
    case MapMetric::kErr:
      return {fmt::format(
                  "set palette defined (0 '#1a9850', {t} '#a6d96a', {t} '#fdae61', 0.6 '#d73027')\n"
                  "set cbrange [0:0.6]\nset cbtics add ('{t:g}' {t})\n",
                  fmt::arg("t", th.err_max)),
              "Err", fmt::format("Err (paper eq. 8); threshold {:g}", th.err_max)};
    case MapMetric::kSrf:
      return {fmt::format(
                  "set palette defined (0.5 '#d73027', {t} '#fdae61', {t} '#a6d96a', 1 '#1a9850')\n"
                  "set cbrange [0.5:1]\nset cbtics add ('{t:g}' {t})\n",
                  fmt::arg("t", th.srf_min)),
              "SRf", fmt::format("SRf (paper eq. 9); threshold {:g}", th.srf_min)};
    case MapMetric::kCost:
      return {"set palette defined (0 '#f7fbff', 0.5 '#6baed6', 1 '#08306b')\nset logscale cb\n",
              "CPU time (s)", "CPU time of the numerical run"};
    case MapMetric::kStatus:
      return {
          "set palette maxcolors 6\n"
          "set palette defined (0 '#1a9850', 1 '#fdae61', 2 '#d73027', 3 '#000000', 4 "
          "'#bdbdbd', 5 '#762a83')\n"
          "set cbrange [-0.5:5.5]\nset rmargin 26\n"
          "set cbtics ('passes' 0, 'fails thresholds' 1, 'diverged' 2, 'failed' 3, "
          "'reference unconverged' 4, 'unstable (energy grew)' 5)\n",
          "", "outcome"};
  }
  return {};
}

// The curves drawn over the cells: the derived boundary and the paper's rules, or the
// stability bound on the dt map.
std::string Overlays(const ValidityCriteria& criteria, MapAxis y) {
  if (y == MapAxis::kDt) {
    return ", 1 with lines lw 3 lc rgb '#000000' title 'sharp stability bound 2/{/Symbol "
           "w}_{max}'";
  }
  std::string overlays;
  if (criteria.fit) {
    overlays += fmt::format(
        ", (x >= {k} ? {c} * x**{p} : 1/0) with lines lw 3 dt 1 lc rgb '#000000' "
        "title 'derived boundary R_{{ftrunc}} = {c:.3g} R_k^{{{p:.3f}}}'",
        fmt::arg("k", criteria.fit->knee_r_k), fmt::arg("c", criteria.fit->c_envelope),
        fmt::arg("p", criteria.fit->p));
  }
  return overlays +
         ", sqrt(x) with lines lw 2 dt 2 lc rgb '#5e3c99' title 'paper eq. 10: R_{ftrunc} = "
         "sqrt(R_k)', (x > 100 ? 300 : 1/0) with lines lw 2 dt 4 lc rgb '#0571b0' title 'paper "
         "eq. 11: R_{ftrunc} = 300 for R_k > 10^2'";
}

// What the script needs beyond the style: names, axes and ranges.
struct MapFrame {
  std::string study, ylabel, overlays;
  std::filesystem::path image, data;
  double xmin, xmax, ymin, ymax;
};

std::string MapScript(const MapFrame& f, const MetricStyle& style) {
  return fmt::format(
      R"(set terminal {terminal}
set output {out}
set title {title} font ',13' noenhanced
set logscale x
set logscale y
set format x '10^{{%L}}'
set xlabel 'R_k = k_s / K_{{bend}}'
set ylabel {ylabel}
set cblabel {cb}
{palette}set xrange [{xmin}:{xmax}]
set yrange [{ymin}:{ymax}]
set key outside bottom center horizontal box opaque font ',10' samplen 3
set grid front lc rgb '#999999'
set samples 400
plot {data} using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 border lc rgb '#ffffff' fc palette notitle, \
     '' using 1:($8 == 4 ? $2 : 1/0):3:4:5:6 with boxxyerror fs solid 1.0 border lc rgb '#ffffff' fc rgb '#bdbdbd' title 'reference unconverged (not scored)', \
     '' using 1:($8 == 2 ? $2 : 1/0) with points pt 2 ps 2 lw 2 lc rgb '#000000' title 'diverged', \
     '' using 1:($8 == 3 ? $2 : 1/0) with points pt 6 ps 2 lw 2 lc rgb '#000000' title 'failed', \
     '' using 1:($8 == 5 ? $2 : 1/0) with points pt 4 ps 2 lw 2 lc rgb '#000000' title 'unstable (energy grew > {unstable:g}x)'{overlays}
)",
      fmt::arg("terminal", TerminalFor(f.image, 1100, 800)),
      fmt::arg("out", GnuplotFileName(f.image)),
      fmt::arg("title", GnuplotQuoted(f.study + ": " + style.title)),
      fmt::arg("ylabel", GnuplotQuoted(f.ylabel)), fmt::arg("cb", GnuplotQuoted(style.cb)),
      fmt::arg("palette", style.palette), fmt::arg("xmin", f.xmin), fmt::arg("xmax", f.xmax),
      fmt::arg("ymin", f.ymin), fmt::arg("ymax", f.ymax), fmt::arg("data", GnuplotFileName(f.data)),
      fmt::arg("overlays", f.overlays), fmt::arg("unstable", kUnstableEnergyRatio));
}

}  // namespace

void DrawValidityMap(const std::string& study, const std::vector<ScoredPoint>& points,
                     const ValidityCriteria& criteria, const MapOptions& options,
                     const std::filesystem::path& file) {
  double r_ftrunc_max = 0.0;
  for (const auto& p : points) r_ftrunc_max = std::max(r_ftrunc_max, p.r_ftrunc);
  const double fixed_rft = options.r_ftrunc.value_or(r_ftrunc_max);
  const Cells cells = PickCells(points, options, fixed_rft);
  std::vector<double> xs, ys;
  for (const auto& [key, p] : cells) xs.push_back(key.first), ys.push_back(key.second);
  const CellBounds xcells = LogCells(xs);
  const CellBounds ycells = LogCells(ys);

  TerminalFor(file, 1100, 800);  // Throws for a bad extension before any file is written.
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const auto data_file = std::filesystem::path(file).replace_extension(".dat");
  WriteMapData(cells, xcells, ycells, options.metric, criteria.options, data_file);
  const MapFrame frame{study,
                       options.y == MapAxis::kRFtrunc
                           ? "R_{ftrunc} = f_{trunc} / f_1"
                           : fmt::format("dt / dt_{{sharp}} (R_{{ftrunc}} = {:g})", fixed_rft),
                       Overlays(criteria, options.y),
                       file,
                       data_file,
                       xcells.begin()->second.first,
                       xcells.rbegin()->second.second,
                       ycells.begin()->second.first,
                       ycells.rbegin()->second.second};
  RunGnuplot(MapScript(frame, StyleOf(options.metric, criteria.options)),
             std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

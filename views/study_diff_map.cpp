#include "views/study_diff_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/scheme.h"
#include "formats/output_file.h"
#include "views/gnuplot.h"
#include "views/map_grid.h"

namespace shockmap {
namespace {

struct DiffCategory {
  const char* label;
  const char* colour;
};

// By index: passes in both, in neither, in A only, in B only; studied in one only; not judged
// in one at least (its reference did not converge: no score).
constexpr std::array<DiffCategory, 6> kCategories{{{"passes in both", "#a6d96a"},
                                                   {"fails in both", "#bdbdbd"},
                                                   {"passes in A only", "#f4a582"},
                                                   {"passes in B only", "#92c5de"},
                                                   {"studied in one only", "#fff7bc"},
                                                   {"reference unconverged", "#f0f0f0"}}};

std::vector<ScoredPoint> ExplicitPoints(const DiffedStudy& s) {
  std::vector<ScoredPoint> points;
  for (const DiffPoint& p : s.points) {
    if (p.scheme == ToString(Scheme::kExplicitModal)) points.push_back(p.scored);
  }
  return points;
}

bool SameCell(const MapCell& x, const MapCell& y) {
  return std::abs(x.r_k - y.r_k) <= 1e-9 * x.r_k && std::abs(x.y - y.y) <= 1e-9 * x.y;
}

int CategoryOf(const MapCell* in_a, const MapCell* in_b, const DiffedStudy& a,
               const DiffedStudy& b) {
  if (in_a == nullptr || in_b == nullptr) return 4;
  if (in_a->point->status == RunStatus::kReferenceUnconverged ||
      in_b->point->status == RunStatus::kReferenceUnconverged) {
    return 5;
  }
  const bool pass_a = a.criteria.options.Passes(*in_a->point);
  const bool pass_b = b.criteria.options.Passes(*in_b->point);
  if (pass_a == pass_b) return pass_a ? 0 : 1;
  return pass_a ? 2 : 3;
}

// Index 0: one line per cell of either study, "r_k r_ftrunc x_low x_high y_low y_high
// category"; indices 1 and 2: the boundary of A and of B, "r_k smallest_passing_r_ftrunc".
// Returns which categories are present.
std::array<bool, kCategories.size()> WriteDiffData(const DiffedStudy& a, const MapGrid& grid_a,
                                                   const DiffedStudy& b, const MapGrid& grid_b,
                                                   const std::filesystem::path& data_file) {
  std::array<bool, kCategories.size()> present{};
  AtomicFile file(data_file);
  std::ostream& data = file.Stream();
  data << "# r_k r_ftrunc x_low x_high y_low y_high category\n";
  auto line = [&](const MapCell& c, int category) {
    present[static_cast<std::size_t>(category)] = true;
    data << fmt::format("{} {} {} {} {} {} {}\n", c.r_k, c.y, c.x_low, c.x_high, c.y_low, c.y_high,
                        category);
  };
  for (const MapCell& c : grid_a.cells) {
    const auto in_b =
        std::ranges::find_if(grid_b.cells, [&](const MapCell& o) { return SameCell(c, o); });
    line(c, CategoryOf(&c, in_b != grid_b.cells.end() ? &*in_b : nullptr, a, b));
  }
  for (const MapCell& c : grid_b.cells) {
    if (std::ranges::none_of(grid_a.cells, [&](const MapCell& o) { return SameCell(c, o); })) {
      line(c, 4);
    }
  }
  for (const DiffedStudy* s : {&a, &b}) {
    data << "\n\n# " << s->name << ": r_k smallest_passing_r_ftrunc\n";
    for (const RkBoundary& boundary : s->criteria.boundary) {
      if (boundary.r_ftrunc_min)
        data << fmt::format("{} {}\n", boundary.r_k, *boundary.r_ftrunc_min);
    }
  }
  file.Commit();
  return present;
}

std::vector<double> Union(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> all = x;
  for (double v : y) {
    if (std::ranges::none_of(all, [&](double w) { return std::abs(v - w) <= 1e-9 * v; })) {
      all.push_back(v);
    }
  }
  return all;
}

std::string PlotClauses(const std::array<bool, kCategories.size()>& present, const DiffedStudy& a,
                        const DiffedStudy& b, const std::string& data) {
  std::string clauses;
  for (std::size_t i = 0; i < kCategories.size(); ++i) {
    if (!present[i]) continue;
    clauses += fmt::format(
        "{}{} index 0 using 1:($7 == {} ? $2 : 1/0):3:4:5:6 with boxxyerror fs solid 1.0 "
        "border lc rgb '#ffffff' fc rgb '{}' title {} noenhanced",
        clauses.empty() ? "" : ", \\\n     ", clauses.empty() ? data : "''", i,
        kCategories[i].colour, GnuplotQuoted(kCategories[i].label));
  }
  clauses += fmt::format(
      ", \\\n     '' index 1 using 1:2 with linespoints lw 3 pt 7 ps 1.4 lc rgb '#b2182b' "
      "title {} noenhanced",
      GnuplotQuoted("boundary of A, " + a.name));
  clauses += fmt::format(
      ", \\\n     '' index 2 using 1:2 with linespoints lw 3 dt 2 pt 9 ps 1.8 lc rgb '#2166ac' "
      "title {} noenhanced",
      GnuplotQuoted("boundary of B, " + b.name));
  return clauses +
         ", \\\n     sqrt(x) with lines lw 2 dt 3 lc rgb '#5e3c99' title 'paper eq. 10: "
         "R_{ftrunc} = sqrt(R_k)'";
}

}  // namespace

void DrawDiffMap(const DiffedStudy& a, const DiffedStudy& b, const std::filesystem::path& file) {
  const std::string terminal = TerminalFor(file, 1100, 850);  // Throws for a bad extension.
  const std::vector<ScoredPoint> points_a = ExplicitPoints(a), points_b = ExplicitPoints(b);
  const MapGrid grid_a = BuildMapGrid(points_a, MapAxis::kRFtrunc);
  const MapGrid grid_b = BuildMapGrid(points_b, MapAxis::kRFtrunc);
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const auto data_file = std::filesystem::path(file).replace_extension(".dat");
  const auto present = WriteDiffData(a, grid_a, b, grid_b, data_file);
  const auto x_low = std::min(grid_a.cells.front().x_low, grid_b.cells.front().x_low);
  const auto x_high = std::max(grid_a.cells.back().x_high, grid_b.cells.back().x_high);
  double y_low = INFINITY, y_high = 0.0;
  for (const MapGrid* g : {&grid_a, &grid_b}) {
    for (const MapCell& c : g->cells)
      y_low = std::min(y_low, c.y_low), y_high = std::max(y_high, c.y_high);
  }
  const std::string title = fmt::format("A = {} ({}) against B = {} ({})", a.name, DtShown(grid_a),
                                        b.name, DtShown(grid_b));
  const std::string script = fmt::format(
      R"(set terminal {terminal}
set output {out}
set title {title} font ',13' noenhanced
set logscale x
set logscale y
{xtics}{ytics}set xlabel 'R_k = k_s / K_{{bend}} (the studied values ticked)'
set ylabel 'R_{{ftrunc}} = f_{{trunc}} / f_1'
set xrange [{xmin}:{xmax}]
set yrange [{ymin}:{ymax}]
set key outside bottom center horizontal box opaque font ',10' samplen 3 maxcols 3
set grid front lc rgb '#999999'
set samples 400
plot {clauses}
)",
      fmt::arg("terminal", terminal), fmt::arg("out", GnuplotOutputName(file)),
      fmt::arg("title", GnuplotQuoted(title)),
      fmt::arg("xtics", GnuplotTics("x", Union(grid_a.r_k_values, grid_b.r_k_values))),
      fmt::arg("ytics", GnuplotTics("y", Union(grid_a.y_values, grid_b.y_values))),
      fmt::arg("xmin", x_low), fmt::arg("xmax", x_high), fmt::arg("ymin", y_low),
      fmt::arg("ymax", y_high),
      fmt::arg("clauses", PlotClauses(present, a, b, GnuplotFileName(data_file))));
  RunGnuplot(script, std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

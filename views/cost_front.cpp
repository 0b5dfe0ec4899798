#include "views/cost_front.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/input_error.h"
#include "formats/counted.h"
#include "formats/output_file.h"
#include "views/gnuplot.h"

namespace shockmap {

std::string CostHeadline(const CostTable& t) {
  std::string s = fmt::format("R_k = {:.4g}", t.r_k);
  if (t.asked_r_k && std::abs(*t.asked_r_k - t.r_k) > 1e-9 * t.r_k) {
    s += fmt::format(" (the studied R_k nearest to the {:g} asked)", *t.asked_r_k);
  }
  const auto passing = std::ranges::count_if(t.rows, [](const CostRow& r) { return r.passes; });
  const auto fragile = std::ranges::count_if(t.rows, [](const CostRow& r) { return r.fragile; });
  s += fmt::format(": {} scored, {} within the thresholds",
                   Counted(static_cast<long long>(t.rows.size()), "point"), passing);
  s += fragile == 0 ? " (the front is built from those)"
                    : fmt::format(
                          ", {} of them only by error cancellation (passes \"fragile\": a "
                          "finer dt at the same R_ftrunc fails; left off the front)",
                          fragile);
  if (t.implicit_over_explicit) {
    s += fmt::format("; implicit / explicit CPU time at equal accuracy: {:.3g} (median of {})",
                     *t.implicit_over_explicit, t.ratio_pairs);
  }
  return s;
}

namespace {

std::string Passes(const CostRow& r) { return r.fragile ? "fragile" : r.passes ? "yes" : "no"; }

}  // namespace

Table CostRowsTable(const CostTable& t) {
  Table table;
  table.columns = {"scheme", "r_ftrunc", "dt_over_dt_sharp", "cpu_s", "steps_x_modes",
                   "err",    "srf",      "passes",           "pareto"};
  for (const auto& r : t.rows) {
    const auto srf = r.point.scores["srf"];
    table.rows.push_back({r.scheme, r.point.r_ftrunc, r.point.DtRatio(), r.point.cpu_s,
                          static_cast<double>(r.point.steps) * r.point.n_modes,
                          *r.point.scores["err"], srf ? TableCell(*srf) : TableCell(), Passes(r),
                          std::string(r.pareto ? "*" : "")});
  }
  return table;
}

std::string CostSummary(const std::vector<CostTable>& tables) {
  std::string s;
  for (const auto& t : tables) {
    s += CostHeadline(t);
    s += fmt::format("\n  {:<15} {:>9} {:>11} {:>11} {:>13} {:>8} {:>7} {:>7} {}\n", "scheme",
                     "R_ftrunc", "dt/dt_sharp", "CPU (s)", "steps x modes", "Err", "SRf", "passes",
                     "Pareto");
    for (const auto& r : t.rows) {
      s += fmt::format("  {:<15} {:>9.4g} {:>11.3g} {:>11.3e} {:>13.4g} {:>8.4f} {:>7} {:>7} {}\n",
                       r.scheme, r.point.r_ftrunc, r.point.DtRatio(), r.point.cpu_s,
                       static_cast<double>(r.point.steps) * r.point.n_modes, *r.point.scores["err"],
                       r.point.scores["srf"] ? fmt::format("{:.4f}", *r.point.scores["srf"]) : "-",
                       Passes(r), r.pareto ? "*" : "");
    }
  }
  return s;
}

namespace {

// Point types by dt / dt_sharp, in the order of the ratios: filled for the explicit scheme
// (coloured by R_ftrunc), the same shape open for the implicit one.
constexpr int kFilledTypes[] = {7, 5, 9, 13, 11, 15};
constexpr int kOpenTypes[] = {6, 4, 8, 12, 10, 14};

// The dt / dt_sharp ratios of the rows, rounded as the table prints them, ascending.
std::vector<std::string> DtClasses(const CostTable& table) {
  std::vector<std::string> classes;
  for (const auto& r : table.rows) classes.push_back(fmt::format("{:.3g}", r.point.DtRatio()));
  std::ranges::sort(classes, {}, [](const std::string& c) { return std::stod(c); });
  classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
  return classes;
}

// Index 0: every row (cpu_s err srf implicit pareto r_ftrunc dt_ratio dt_class fragile, the
// class an index into `classes`); index 1: the Pareto front alone, fastest first, so that its line
// joins every point of the front.
void WriteCostData(const CostTable& table, const std::vector<std::string>& classes,
                   const std::filesystem::path& data_file) {
  AtomicFile data_out(data_file);
  std::ostream& data = data_out.Stream();
  data << "# cpu_s err srf implicit pareto r_ftrunc dt_ratio dt_class fragile\n";
  for (const auto& r : table.rows) {
    const std::string ratio = fmt::format("{:.3g}", r.point.DtRatio());
    data << fmt::format("{:.6g} {:.6g} {:.6g} {} {} {:g} {} {} {}\n", r.point.cpu_s,
                        *r.point.scores["err"], r.point.scores["srf"].value_or(NAN),
                        r.scheme == "implicit-full" ? 1 : 0, r.pareto ? 1 : 0, r.point.r_ftrunc,
                        ratio, std::ranges::find(classes, ratio) - classes.begin(),
                        r.fragile ? 1 : 0);
  }
  data << "\n\n# the Pareto front: cpu_s err\n";
  for (const auto& r : table.rows) {
    if (r.pareto) data << fmt::format("{:.6g} {:.6g}\n", r.point.cpu_s, *r.point.scores["err"]);
  }
  data_out.Commit();
}

// One clause per scheme and dt / dt_sharp present: the point type tells the time step.
std::string PointClauses(const CostTable& table, const std::vector<std::string>& classes,
                         const std::string& data) {
  std::string clauses;
  for (const bool implicit : {false, true}) {
    for (std::size_t k = 0; k < classes.size(); ++k) {
      const bool present = std::ranges::any_of(table.rows, [&](const CostRow& r) {
        return (r.scheme == "implicit-full") == implicit &&
               fmt::format("{:.3g}", r.point.DtRatio()) == classes[k];
      });
      if (!present) continue;
      const int type = (implicit ? kOpenTypes : kFilledTypes)[k % std::size(kFilledTypes)];
      clauses += fmt::format(
          "{} index 0 using 1:($4 == {} && $8 == {} ? $2 : 1/0){} with points pt {} ps {} {} title "
          "{}, "
          "\\\n     ",
          clauses.empty() ? data : "''", implicit ? 1 : 0, k, implicit ? "" : ":6", type,
          implicit ? 2 : 1.5, implicit ? "lw 2 lc rgb '#000000'" : "lc palette",
          GnuplotQuoted(fmt::format("{}, dt = {} dt_{{sharp}}",
                                    implicit ? "implicit full model" : "explicit modal",
                                    classes[k])));
    }
  }
  return clauses;
}

}  // namespace

void DrawCost(const std::string& study, const CostTable& table, const std::filesystem::path& file) {
  if (table.rows.empty()) throw InputError("nothing to draw: no scored point at this R_k");
  TerminalFor(file, 1000, 760);  // Throws for a bad extension before any file is written.
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const auto data_file = std::filesystem::path(file).replace_extension(".dat");
  const std::vector<std::string> classes = DtClasses(table);
  WriteCostData(table, classes, data_file);
  const bool front = std::ranges::any_of(table.rows, &CostRow::pareto);
  const std::string script = fmt::format(
      R"gp(set terminal {terminal}
set output {out}
set title {title} noenhanced
set logscale x
set logscale y
set format x '10^{{%L}}'
set format y '10^{{%L}}'
set xlabel 'CPU time of the numerical run (s, median of repeats for short runs)'
set ylabel 'Err (paper eq. 8)'
set grid
set key below maxrows 4 font ',10'
set palette defined (1 '#fee08b', 2 '#66bd63', 3 '#1a9850', 4 '#006837')
set logscale cb
set format cb '%g'
set cblabel 'R_{{ftrunc}} = f_{{trunc}} / f_1 (colour of the explicit points)'
{threshold_line}plot {points}{front}{fragile}{threshold}
)gp",
      fmt::arg("terminal", TerminalFor(file, 1000, 760)), fmt::arg("out", GnuplotOutputName(file)),
      fmt::arg("title", GnuplotQuoted(fmt::format("{}: what accuracy costs at R_k = {:.4g}", study,
                                                  table.r_k))),
      fmt::arg("points", PointClauses(table, classes, GnuplotFileName(data_file))),
      fmt::arg("front", front ? "'' index 1 using 1:2 with linespoints lw 2 pt 6 ps 2.2 lc rgb "
                                "'#d73027' title 'Pareto front of the passing points'"
                              : "NaN notitle"),
      fmt::arg(
          "fragile",
          std::ranges::any_of(table.rows, &CostRow::fragile)
              ? ", \\\n     '' index 0 using 1:($9 == 1 ? $2 : 1/0) with points pt 4 ps 2.4 lw 2 "
                "lc rgb '#7b3294' title 'passes by error cancellation (a finer dt fails): off "
                "the front'"
              : ""),
      // Across the whole frame; its legend entry is the keyentry below.
      fmt::arg("threshold_line",
               table.err_max
                   ? fmt::format("set arrow from graph 0, first {0} to graph 1, first {0} "
                                 "nohead lw 2 dt 2 lc rgb '#000000' front\n",
                                 *table.err_max)
                   : ""),
      fmt::arg("threshold",
               table.err_max
                   ? fmt::format(", \\\n     keyentry with lines lw 2 dt 2 lc rgb '#000000' "
                                 "title 'Err threshold {:g}'",
                                 *table.err_max)
                   : ""));
  RunGnuplot(script, std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

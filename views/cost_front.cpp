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

namespace {

// True when some point of `points` at p's R_k and R_ftrunc with a finer time step fails.
bool FinerStepFails(const ScoredPoint& p, const std::vector<ScoredPoint>& points,
                    const CriteriaOptions& thresholds) {
  return std::ranges::any_of(points, [&](const ScoredPoint& q) {
    return q.r_k == p.r_k && q.r_ftrunc == p.r_ftrunc && q.DtRatio() < p.DtRatio() &&
           !thresholds.Passes(q);
  });
}

}  // namespace

std::vector<CostTable> BuildCostTables(const std::vector<ScoredPoint>& explicit_points,
                                       const std::vector<ScoredPoint>& implicit_points,
                                       std::optional<double> r_k,
                                       const CriteriaOptions& thresholds) {
  std::map<double, CostTable> by_rk;
  auto add = [&](const std::vector<ScoredPoint>& points, const char* scheme) {
    for (const auto& p : points) {
      if (p.status != RunStatus::kOk || !p.scores["err"]) continue;
      CostTable& t = by_rk[p.r_k];
      t.r_k = p.r_k;
      const bool passes = thresholds.Passes(p);
      t.rows.push_back({p, scheme, passes, passes && FinerStepFails(p, points, thresholds), false});
    }
  };
  add(explicit_points, "explicit-modal");
  add(implicit_points, "implicit-full");
  if (r_k && !by_rk.empty()) {
    auto nearest = by_rk.begin();
    for (auto it = by_rk.begin(); it != by_rk.end(); ++it) {
      if (std::abs(std::log(it->first / *r_k)) < std::abs(std::log(nearest->first / *r_k))) {
        nearest = it;
      }
    }
    CostTable only = std::move(nearest->second);
    only.asked_r_k = *r_k;
    by_rk.clear();
    by_rk[only.r_k] = std::move(only);
  }
  std::vector<CostTable> tables;
  for (auto& [key, t] : by_rk) {
    std::ranges::sort(t.rows, {}, [](const CostRow& r) { return r.point.cpu_s; });
    double best_err = INFINITY;
    for (auto& row : t.rows) {
      if (row.passes && !row.fragile && *row.point.scores["err"] < best_err) {
        row.pareto = true;
        best_err = *row.point.scores["err"];
      }
    }
    std::vector<double> ratios;
    for (const auto& imp : t.rows) {
      if (imp.scheme != "implicit-full") continue;
      for (const auto& exp : t.rows) {  // Fastest first: the first match is the cheapest.
        if (exp.scheme == "explicit-modal" &&
            *exp.point.scores["err"] <= *imp.point.scores["err"]) {
          ratios.push_back(imp.point.cpu_s / exp.point.cpu_s);
          break;
        }
      }
    }
    if (!ratios.empty()) {
      std::ranges::sort(ratios);
      t.implicit_over_explicit = ratios[ratios.size() / 2];
      t.ratio_pairs = static_cast<int>(ratios.size());
    }
    tables.push_back(std::move(t));
  }
  return tables;
}

std::string CostSummary(const std::vector<CostTable>& tables) {
  std::string s;
  for (const auto& t : tables) {
    s += fmt::format("R_k = {:.4g}", t.r_k);
    if (t.asked_r_k && std::abs(*t.asked_r_k - t.r_k) > 1e-9 * t.r_k) {
      s += fmt::format(" (the studied R_k nearest to --rk {:g})", *t.asked_r_k);
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
    s += fmt::format("\n  {:<15} {:>9} {:>11} {:>11} {:>13} {:>8} {:>7} {:>7} {}\n", "scheme",
                     "R_ftrunc", "dt/dt_sharp", "CPU (s)", "steps x modes", "Err", "SRf", "passes",
                     "Pareto");
    for (const auto& r : t.rows) {
      s += fmt::format("  {:<15} {:>9.4g} {:>11.3g} {:>11.3e} {:>13.4g} {:>8.4f} {:>7} {:>7} {}\n",
                       r.scheme, r.point.r_ftrunc, r.point.DtRatio(), r.point.cpu_s,
                       static_cast<double>(r.point.steps) * r.point.n_modes, *r.point.scores["err"],
                       r.point.scores["srf"] ? fmt::format("{:.4f}", *r.point.scores["srf"]) : "-",
                       r.fragile  ? "fragile"
                       : r.passes ? "yes"
                                  : "no",
                       r.pareto ? "*" : "");
    }
  }
  return s;
}

void DrawCost(const std::string& study, const CostTable& table, const std::filesystem::path& file) {
  if (table.rows.empty()) throw InputError("nothing to draw: no scored point at this R_k");
  TerminalFor(file, 1000, 700);  // Throws for a bad extension before any file is written.
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const auto data_file = std::filesystem::path(file).replace_extension(".dat");
  {
    AtomicFile data_out(data_file);
    std::ostream& data = data_out.Stream();
    data << "# cpu_s err srf implicit pareto r_ftrunc dt_ratio fragile\n";
    for (const auto& r : table.rows) {
      data << fmt::format("{:.6g} {:.6g} {:.6g} {} {} {:g} {:.3g} {}\n", r.point.cpu_s,
                          *r.point.scores["err"], r.point.scores["srf"].value_or(NAN),
                          r.scheme == "implicit-full" ? 1 : 0, r.pareto ? 1 : 0, r.point.r_ftrunc,
                          r.point.DtRatio(), r.fragile ? 1 : 0);
    }
    data_out.Commit();
  }
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
set key top right
set palette defined (1 '#fee08b', 2 '#66bd63', 3 '#1a9850', 4 '#006837')
set cblabel 'log_{{10}} R_{{ftrunc}}'
plot {data} using 1:($4 == 0 ? $2 : 1/0):(log10($6)) with points pt 7 ps 1.5 lc palette title 'explicit modal', \
     '' using 1:($4 == 1 ? $2 : 1/0) with points pt 9 ps 2 lc rgb '#000000' title 'implicit full model', \
     '' using 1:($5 == 1 ? $2 : 1/0) with linespoints lw 2 pt 6 ps 2.2 lc rgb '#d73027' title 'Pareto front'{fragile}
)gp",
      fmt::arg("terminal", TerminalFor(file, 1000, 700)), fmt::arg("out", GnuplotOutputName(file)),
      fmt::arg("title", GnuplotQuoted(fmt::format("{}: what accuracy costs at R_k = {:.4g}", study,
                                                  table.r_k))),
      fmt::arg("data", GnuplotFileName(data_file)),
      fmt::arg("fragile",
               std::ranges::any_of(table.rows, [](const CostRow& r) { return r.fragile; })
                   ? ", \\\n     '' using 1:($8 == 1 ? $2 : 1/0) with points pt 4 ps 2.4 lw 2 lc "
                     "rgb '#7b3294' title 'passes by error cancellation (a finer dt fails): off "
                     "the front'"
                   : ""));
  RunGnuplot(script, std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

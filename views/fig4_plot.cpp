#include "views/fig4_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/input_error.h"
#include "formats/output_file.h"
#include "views/gnuplot.h"

namespace shockmap {
namespace {

struct RkCurve {
  std::string title;
  std::map<double, const ScoredPoint*> by_rk;  // Finest time step per R_k.
};

void AddCurves(const std::vector<ScoredPoint>& points, const std::string& scheme,
               std::map<std::pair<std::string, double>, RkCurve>& curves) {
  for (const auto& p : points) {
    RkCurve& c = curves[{scheme, p.r_ftrunc}];
    c.title = fmt::format("{} R_{{ftrunc}} = {:.6g}", scheme, p.r_ftrunc);
    auto& slot = c.by_rk[p.r_k];
    if (slot == nullptr || p.DtRatio() < slot->DtRatio()) slot = &p;
  }
}

std::string Value(const std::optional<double>& v) { return v ? fmt::format("{}", *v) : "NaN"; }

// The R_k at which some curve's point has no score, or lacks one, because its reference did not
// converge or does not decide it: drawn as dashed verticals, so that the curves' gaps there are
// not read as data.
std::set<double> UnconvergedRk(const std::map<std::pair<std::string, double>, RkCurve>& curves) {
  std::set<double> r_k;
  for (const auto& [key, curve] : curves) {
    for (const auto& [rk, p] : curve.by_rk) {
      if (p->status == RunStatus::kReferenceUnconverged || !p->reference_undecided.empty())
        r_k.insert(rk);
    }
  }
  return r_k;
}

std::string UnconvergedMarks(const std::set<double>& r_k) {
  std::string marks;
  for (double rk : r_k) {
    marks += fmt::format(
        "set arrow from first {0}, graph 0 to first {0}, graph 1 nohead dt 3 lw 2 lc rgb "
        "'#969696' back\n",
        rk);
  }
  return marks;
}

// A legend entry for the verticals, "" without any.
std::string UnconvergedKey(const std::set<double>& r_k) {
  return r_k.empty() ? ""
                     : ", NaN with lines dt 3 lw 2 lc rgb '#969696' title 'R_k left out: "
                       "reference unconverged (not scored, or a score undecided)'";
}

// The smallest and largest R_k of the curves.
std::pair<double, double> RkRange(const std::map<std::pair<std::string, double>, RkCurve>& curves) {
  std::pair<double, double> range{INFINITY, 0.0};
  for (const auto& [key, curve] : curves) {
    range.first = std::min(range.first, curve.by_rk.begin()->first);
    range.second = std::max(range.second, curve.by_rk.rbegin()->first);
  }
  return range;
}

// The SRf axis: the curves' values and the threshold, with a twentieth of their span (at
// least 0.01) around them; [0, 1.05] when nothing is scored.
std::string SrfRange(const std::map<std::pair<std::string, double>, RkCurve>& curves,
                     double threshold) {
  double low = threshold, high = threshold;
  bool scored = false;
  for (const auto& [key, curve] : curves) {
    for (const auto& [rk, p] : curve.by_rk) {
      if (const auto srf = p->scores["srf"]) {
        low = std::min(low, *srf), high = std::max(high, *srf), scored = true;
      }
    }
  }
  if (!scored) return "[0:1.05]";
  const double margin = std::max(0.01, 0.05 * (high - low));
  return fmt::format("[{:.4g}:{:.4g}]", low - margin, high + margin);
}

// Writes one data block per curve (columns r_k err srf status) and returns the plot clauses
// of the Err and the SRf panels.
std::pair<std::string, std::string> WriteCurves(
    const std::map<std::pair<std::string, double>, RkCurve>& curves,
    const std::filesystem::path& data_file) {
  AtomicFile data_out(data_file);
  std::ostream& data = data_out.Stream();
  std::string err_plot, srf_plot;
  int index = 0;
  for (const auto& [key, curve] : curves) {
    data << "# " << curve.title << "\n# r_k err srf status\n";
    for (const auto& [r_k, p] : curve.by_rk) {
      data << fmt::format("{} {} {} {}\n", r_k, Value(p->scores["err"]), Value(p->scores["srf"]),
                          ToString(p->status));
    }
    data << "\n\n";
    const bool is_implicit = key.first == "implicit";
    auto clause = [&, &title = curve.title](int column) {
      return fmt::format("{} index {} using 1:{} with linespoints lw 2 pt {} ps 1.3 {} title {}",
                         GnuplotFileName(data_file), index, column, is_implicit ? 8 : 7,
                         is_implicit ? "dt 2 lc rgb '#000000'" : "", GnuplotQuoted(title));
    };
    err_plot += (err_plot.empty() ? "" : ", ") + clause(2);
    srf_plot += (srf_plot.empty() ? "" : ", ") + clause(3);
    ++index;
  }
  data_out.Commit();
  return {err_plot, srf_plot};
}

}  // namespace

void DrawFig4(const std::string& study, const std::vector<ScoredPoint>& explicit_points,
              const std::vector<ScoredPoint>& implicit_points, const CriteriaOptions& thresholds,
              const std::filesystem::path& file) {
  std::map<std::pair<std::string, double>, RkCurve> curves;
  AddCurves(explicit_points, "explicit", curves);
  AddCurves(implicit_points, "implicit", curves);
  if (curves.empty()) throw InputError("nothing to draw: the study has no stored point");
  TerminalFor(file, 1400, 700);  // Throws for a bad extension before any file is written.
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const auto [err_plot, srf_plot] =
      WriteCurves(curves, std::filesystem::path(file).replace_extension(".dat"));
  const std::pair<double, double> range = RkRange(curves);
  const std::string script = fmt::format(
      R"gp(set terminal {terminal}
set output {out}
set multiplot layout 1,2 title {title} noenhanced
set logscale x
set format x '10^{{%L}}'
set xlabel 'R_k = k_s / K_{{bend}}'
set xrange [{x0}:{x1}]
set grid
set key below font ',10' maxrows 4
{unconverged}set ylabel 'Err (paper eq. 8)'
set yrange [0:*]
plot {err_plot}, {err_max} with lines lw 1 dt 3 lc rgb '#d73027' title 'threshold {err_max:g}'{unconverged_key}
set ylabel 'SRf (paper eq. 9)'
set yrange {srf_range}
plot {srf_plot}, {srf_min} with lines lw 1 dt 3 lc rgb '#d73027' title 'threshold {srf_min:g}'{unconverged_key}
unset multiplot
)gp",
      fmt::arg("terminal", TerminalFor(file, 1400, 700)), fmt::arg("out", GnuplotOutputName(file)),
      fmt::arg("x0", range.first / 2), fmt::arg("x1", range.second * 2),
      fmt::arg("title", GnuplotQuoted(study + ": the paper's Fig. 4 (finest time step per point)")),
      fmt::arg("err_plot", err_plot), fmt::arg("srf_plot", srf_plot),
      fmt::arg("err_max", thresholds.thresholds.at("err")),
      fmt::arg("srf_min", thresholds.thresholds.at("srf")),
      fmt::arg("srf_range", SrfRange(curves, thresholds.thresholds.at("srf"))),
      fmt::arg("unconverged", UnconvergedMarks(UnconvergedRk(curves))),
      fmt::arg("unconverged_key", UnconvergedKey(UnconvergedRk(curves))));
  RunGnuplot(script, std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

#include "views/comparison_plot.h"

#include <fmt/format.h>

#include "views/gnuplot.h"

namespace shockmap {

std::filesystem::path PlotComparison(const ComparisonResult& result,
                                     const CantileverImpact& problem,
                                     const ComparisonOptions& options,
                                     const std::filesystem::path& dir) {
  const auto png = dir / "fig3.png";
  const std::optional<double> err = result.scores["err"], srf = result.scores["srf"];
  const std::string scores = err ? fmt::format("Err = {:.1f} %, SRf = {}", 100.0 * *err,
                                               srf ? fmt::format("{:.3f}", *srf) : "n/a")
                                 : ToString(result.status);
  const std::string script = fmt::format(
      R"(set terminal pngcairo size 1200,900 font "DejaVu Sans,11"
set output {png}
set datafile separator ','
set multiplot layout 2,1 title {title}
set lmargin 10
set rmargin 3
set grid
set key top right
set xrange [0:{window}]
set ylabel 'tip displacement (mm)'
plot 'reference.csv' using 1:($2*1000) skip 1 with lines lw 2 lc rgb '#1f77b4' title 'reference (R_{{fref}} = {rfref:g})', \
     'numerical.csv' using 1:($2*1000) skip 1 with lines lw 1.5 dt 2 lc rgb '#d62728' title 'numerical'
set xlabel 'time (s)'
set ylabel 'contact force (kN)'
plot 'reference.csv' using 1:($3/1000) skip 1 with lines lw 2 lc rgb '#1f77b4' title 'reference', \
     'numerical.csv' using 1:($4/1000) skip 1 with lines lw 1.5 dt 2 lc rgb '#d62728' title 'numerical'
unset multiplot
)",
      fmt::arg("png", GnuplotOutputName(png)),
      fmt::arg("title", GnuplotQuoted(fmt::format(
                            "Tip of the beam, R_k = {:g}, R_{{ftrunc}} = {:g} ({} modes, {}, dt = "
                            "{:.3g} s) - {}",
                            problem.r_k, options.r_ftrunc, result.n_modes, ToString(options.scheme),
                            result.numerical.dt_used_s, scores))),
      fmt::arg("window", options.window_s), fmt::arg("rfref", options.reference.r_fref));
  RunGnuplot(script, dir / "fig3.gp", png);
  return png;
}

}  // namespace shockmap

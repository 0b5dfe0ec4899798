#include "views/advice_summary.h"

#include <fmt/format.h>

#include "formats/counted.h"

namespace shockmap {
namespace {

std::string OptionalText(const std::optional<double>& v) {
  return v ? fmt::format("{:.3g}", *v) : "-";
}

}  // namespace

std::string AdviceSummary(const Advice& a) {
  std::string s = fmt::format(
      "advice for R_k = {:g}\n"
      "  R_ftrunc     {:.4g} ({})\n"
      "  dt           {:.4g} s = {:.3g} x the sharp bound {:.4g} s\n"
      "  basis        {}\n"
      "  cost         {} over the {:g} s window, about {:.3g} s at {:.3g} ns per mode per "
      "step (CPU time, median of the stored runs)\n",
      a.r_k, a.r_ftrunc, Counted(a.n_modes, "mode"), a.dt_s, a.dt_ratio, a.dt_sharp_s, a.basis,
      Counted(a.steps, "step"), a.window_s, a.expected_cpu_s, 1e9 * a.seconds_per_mode_step);
  if (!a.nearest.empty()) {
    s += fmt::format("  nearest stored points\n  {:>10}  {:>9}  {:>11}  {:<22}", "R_k", "R_ftrunc",
                     "dt/dt_sharp", "status");
    for (const ScoreDefinition& score : Scores()) s += fmt::format("  {:>6}", score.label);
    s += "\n";
    for (const auto& p : a.nearest) {
      s += fmt::format("  {:>10.4g}  {:>9.4g}  {:>11.3g}  {:<22}", p.r_k, p.r_ftrunc, p.DtRatio(),
                       ToString(p.status));
      for (const ScoreDefinition& score : Scores()) {
        s += fmt::format("  {:>6}", OptionalText(p.scores[score.name]));
      }
      s += "\n";
    }
  }
  for (const auto& w : a.warnings) s += "  warning      " + w + "\n";
  return s;
}

nlohmann::json AdviceToJson(const Advice& a) {
  nlohmann::json nearest = nlohmann::json::array();
  for (const auto& p : a.nearest) {
    nlohmann::json point = {{"point_id", p.point_id},
                            {"r_k", p.r_k},
                            {"r_ftrunc", p.r_ftrunc},
                            {"dt_ratio", p.DtRatio()},
                            {"status", ToString(p.status)}};
    for (const ScoreDefinition& score : Scores()) {
      const std::optional<double> v = p.scores[score.name];
      point[std::string(score.name)] = v ? nlohmann::json(*v) : nlohmann::json();
    }
    nearest.push_back(std::move(point));
  }
  return {{"r_k", a.r_k},
          {"r_ftrunc", a.r_ftrunc},
          {"n_modes", a.n_modes},
          {"dt_s", a.dt_s},
          {"dt_ratio", a.dt_ratio},
          {"dt_sharp_s", a.dt_sharp_s},
          {"steps", a.steps},
          {"window_s", a.window_s},
          {"seconds_per_mode_step", a.seconds_per_mode_step},
          {"expected_cpu_s", a.expected_cpu_s},
          {"studied_r_k", a.studied_r_k},
          {"basis", a.basis},
          {"nearest", nearest},
          {"warnings", a.warnings}};
}

}  // namespace shockmap

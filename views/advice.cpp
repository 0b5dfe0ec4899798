#include "views/advice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/cantilever_impact.h"
#include "core/input_error.h"

namespace shockmap {

Advice Advise(const StudySpec& spec, const ValidityCriteria& criteria,
              const std::vector<ScoredPoint>& points, double r_k) {
  if (!criteria.fit || !criteria.dt_ratio_max) {
    throw InputError(
        "the study's criteria have no fitted truncation boundary or time-step "
        "bound to advise from; study a wider range of R_k and R_ftrunc");
  }
  Advice a;
  a.r_k = r_k;
  a.r_ftrunc = *criteria.RequiredRFtrunc(r_k);
  a.dt_ratio = *criteria.dt_ratio_max;
  CantileverImpact problem = spec.problem;
  problem.r_k = r_k;
  const ImpactModel model = BuildImpactModel(problem, Scheme::kExplicitModal, a.r_ftrunc);
  a.n_modes = model.n_modes;
  a.dt_sharp_s = model.bounds.dt_sharp_s;
  a.dt_s = a.dt_ratio * a.dt_sharp_s;
  a.window_s = spec.scoring.window_s;
  a.steps = static_cast<std::int64_t>(std::ceil(a.window_s / a.dt_s));
  std::vector<double> per_mode_step;
  for (const auto& p : points) {
    if (p.status == RunStatus::kOk && p.steps > 0 && p.n_modes > 0) {
      per_mode_step.push_back(p.wall_s / (static_cast<double>(p.steps) * p.n_modes));
    }
  }
  if (!per_mode_step.empty()) {
    std::ranges::nth_element(per_mode_step, per_mode_step.begin() + per_mode_step.size() / 2);
    a.seconds_per_mode_step = per_mode_step[per_mode_step.size() / 2];
  }
  a.expected_wall_s = a.seconds_per_mode_step * static_cast<double>(a.steps) * a.n_modes;
  const auto [lo, hi] =
      std::ranges::minmax_element(criteria.boundary, {}, [](const RkBoundary& b) { return b.r_k; });
  if (lo != criteria.boundary.end() && (r_k < lo->r_k || r_k > hi->r_k)) {
    a.warning = fmt::format(
        "R_k = {:g} lies outside the studied range [{:g}, {:g}]: the criterion is extrapolated",
        r_k, lo->r_k, hi->r_k);
  }
  return a;
}

std::string AdviceSummary(const Advice& a) {
  std::string s = fmt::format(
      "advice for R_k = {:g}\n"
      "  R_ftrunc     {:.4g} ({} modes)\n"
      "  dt           {:.4g} s = {:.3g} x the sharp bound {:.4g} s\n"
      "  cost         {} steps over the {:g} s window, about {:.3g} s at {:.3g} ns per mode per "
      "step (median of the stored runs)\n",
      a.r_k, a.r_ftrunc, a.n_modes, a.dt_s, a.dt_ratio, a.dt_sharp_s, a.steps, a.window_s,
      a.expected_wall_s, 1e9 * a.seconds_per_mode_step);
  if (a.warning) s += "  warning      " + *a.warning + "\n";
  return s;
}

}  // namespace shockmap

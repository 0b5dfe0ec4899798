#include "analysis/cost_front.h"

#include <algorithm>
#include <cmath>
#include <map>

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
      if (const auto err_max = thresholds.thresholds.find("err");
          err_max != thresholds.thresholds.end()) {
        t.err_max = err_max->second;
      }
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

}  // namespace shockmap

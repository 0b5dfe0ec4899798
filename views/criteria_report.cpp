#include "views/criteria_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "formats/counted.h"

namespace shockmap {
namespace {

std::string Num(std::optional<double> v) { return v ? fmt::format("{:.4g}", *v) : "-"; }

// Paper eq. 11's step against the sharp bound, counted per (R_k, R_ftrunc) cell: the step
// 1/(4 f_trunc) and the bound depend on the cell only, not on the dt factor studied there.
std::string PaperStepLine(const std::vector<ScoredPoint>& points) {
  std::set<std::pair<double, double>> cells, beyond;
  for (const auto& p : points) {
    cells.insert({p.r_k, p.r_ftrunc});
    if (p.dt_paper_s > p.dt_sharp_s) beyond.insert({p.r_k, p.r_ftrunc});
  }
  std::string first;
  if (!beyond.empty()) {
    const auto lowest = std::ranges::min(beyond);  // Smallest R_k, then its smallest R_ftrunc.
    first = fmt::format(" (from R_k = {:.3g} at R_ftrunc = {:g})", lowest.first, lowest.second);
  }
  return fmt::format(
      "  paper eq. 11  1/(4 dt f1) > R_ftrunc: dt = 1/(4 f_trunc) exceeds the sharp bound "
      "2/omega_max in {} of {} (R_k, R_ftrunc) cells{}.\n",
      beyond.size(), cells.size(), first);
}

// Paper eq. 11's truncation rule against the boundary above R_k = 1e2. The rule is confirmed
// only where a studied truncation passes at every such R_k: an R_k where none passes is named,
// never counted as agreeing.
std::string PaperTruncationLine(const ValidityCriteria& c) {
  const std::string rule = "  paper eq. 11  R_ftrunc > 300 for R_k > 1e2: ";
  double needed = 0.0;
  std::vector<std::string> none_passes;
  for (const auto& b : c.boundary) {
    if (b.r_k <= 100) continue;
    if (b.r_ftrunc_min) {
      needed = std::max(needed, *b.r_ftrunc_min);
    } else {
      none_passes.push_back(fmt::format("{:.3g}", b.r_k));
    }
  }
  if (!none_passes.empty()) {
    return rule + fmt::format(
                      "no studied truncation passes at R_k = {}, so the data cannot confirm "
                      "it.\n",
                      fmt::join(none_passes, ", "));
  }
  if (needed == 0.0) return rule + "no R_k above 1e2 was studied.\n";
  return rule + fmt::format("the data needs at most R_ftrunc = {:g} there ({}).\n", needed,
                            needed <= 300 ? "agrees" : "300 is not enough");
}

// Where stability was kept and where it was lost: the two ratios never overlap
// (validation/validity_criteria.h), and the points at the first lost ratio are counted.
std::string StabilityLine(const ValidityCriteria& c, const std::vector<ScoredPoint>& points) {
  std::string s =
      c.dt_ratio_max
          ? fmt::format("  time step   every point at dt <= {} dt_sharp above the boundary passes",
                        Num(c.dt_ratio_max))
          : std::string("  time step   no studied time step passes at every R_k with a boundary");
  s += c.largest_stable_dt_ratio ? fmt::format("; every run stayed stable up to {} dt_sharp",
                                               Num(c.largest_stable_dt_ratio))
                                 : std::string("; no studied time step kept every R_k stable");
  if (!c.smallest_diverged_dt_ratio) return s + "; none lost stability (predicted bound: 1)\n";
  const double first = *c.smallest_diverged_dt_ratio;
  int at = 0, diverged = 0, unstable = 0;
  for (const auto& p : points) {
    if (std::abs(p.DtRatio() - first) > 1e-9 * first) continue;
    ++at;
    diverged += p.status == RunStatus::kDiverged;
    unstable += p.status == RunStatus::kUnstable;
  }
  return s + fmt::format(
                 "; at {} dt_sharp {} of {} points diverged and {} ended unstable (predicted "
                 "bound: 1)\n",
                 Num(c.smallest_diverged_dt_ratio), diverged, at, unstable);
}

// The lines after the table, each indented by two spaces: the fit, the paper's rules, the time
// step.
std::string RuleLines(const ValidityCriteria& c, const std::vector<ScoredPoint>& points) {
  std::string s;
  if (c.fit) {
    const PowerLawFit& f = *c.fit;
    const bool inside = f.p_low <= 0.5 && 0.5 <= f.p_high;
    s += fmt::format(
        "  truncation  R_ftrunc > C R_k^p above R_k = {:.4g} ({} R_k): p = {:.3f} +- {:.3f}, "
        "{:.0f} % interval [{:.3f}, {:.3f}]; C = {:.3g} (least squares), {:.3g} (covering every "
        "boundary point)\n",
        f.knee_r_k, f.n, f.p, f.p_stderr, 100 * c.options.confidence, f.p_low, f.p_high, f.c,
        f.c_envelope);
    s += fmt::format("  paper eq. 10  R_ftrunc > sqrt(R_k), p = 0.5: {} the interval.",
                     inside ? "inside" : "outside");
    double worst_ratio = 0.0, at = 0.0;
    for (const auto& b : c.boundary) {
      if (b.r_ftrunc_min && b.r_k >= f.knee_r_k) {
        const double ratio = *b.r_ftrunc_min / std::sqrt(b.r_k);
        if (ratio > worst_ratio) worst_ratio = ratio, at = b.r_k;
      }
    }
    s += fmt::format(" The data needs up to {:.2g} x sqrt(R_k) (at R_k = {:.3g})", worst_ratio, at);
    s += worst_ratio > 1 ? ": sqrt(R_k) alone is not enough there.\n"
                         : ": sqrt(R_k) is sufficient everywhere studied.\n";
  } else {
    s += "  truncation  no fit: fewer than two R_k have a boundary above the smallest truncation\n";
  }
  s += PaperTruncationLine(c);
  s += PaperStepLine(points);
  s += StabilityLine(c, points);
  if (const auto unscored = UnscoredWarning(c)) s += "  not scored  " + *unscored + "\n";
  if (const auto undecided = UndecidedWarning(c.undecided))
    s += "  undecided   " + *undecided + "\n";
  return s;
}

}  // namespace

std::string CriteriaSummary(const std::string& study, const ValidityCriteria& c,
                            const std::vector<ScoredPoint>& points) {
  std::string s = fmt::format("criteria of study {} (explicit-modal; {}; {} stored)\n", study,
                              ThresholdsText(c.options, false),
                              Counted(static_cast<long long>(points.size()), "point"));
  s += fmt::format("  {:>10}  {:>12}  {:>9}  {:>15}  {:>8}\n", "R_k", "R_ftrunc_min", "sqrt(R_k)",
                   "dt/dt_sharp max", "passing");
  for (const auto& b : c.boundary) {
    s += fmt::format("  {:>10.4g}  {:>12}  {:>9.4g}  {:>15}  {:>4}/{:<3}\n", b.r_k,
                     Num(b.r_ftrunc_min), std::sqrt(b.r_k), Num(b.dt_ratio_max), b.n_passing,
                     b.n_points);
  }
  return s + RuleLines(c, points);
}

std::vector<std::string> CriteriaRuleLines(const ValidityCriteria& c,
                                           const std::vector<ScoredPoint>& points) {
  std::vector<std::string> lines;
  const std::string text = RuleLines(c, points);
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end - at);
    lines.push_back(line.substr(line.find_first_not_of(' ')));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return lines;
}

}  // namespace shockmap

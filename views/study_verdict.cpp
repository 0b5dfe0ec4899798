#include "views/study_verdict.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "formats/counted.h"
#include "views/html_text.h"

namespace shockmap {
namespace {

TableCell Cell(const std::optional<double>& v) { return v ? TableCell(*v) : TableCell(); }

// "1 to 1e+05", or "10" when both ends show alike.
std::string Range(double low, double high) {
  const std::string from = fmt::format("{:.4g}", low), to = fmt::format("{:.4g}", high);
  return from == to ? from : from + " to " + to;
}

// The studied ranges of R_k, R_ftrunc and dt / dt_sharp.
std::string Studied(const std::vector<ScoredPoint>& points) {
  auto range = [&](auto value) {
    const auto [lo, hi] = std::ranges::minmax_element(points, {}, value);
    return Range(value(*lo), value(*hi));
  };
  return fmt::format("R_k {}, R_ftrunc {}, dt {} dt_sharp",
                     range([](const ScoredPoint& p) { return p.r_k; }),
                     range([](const ScoredPoint& p) { return p.r_ftrunc; }),
                     range([](const ScoredPoint& p) { return p.DtRatio(); }));
}

// The truncation rule over the studied R_k only: the fit from its knee to the largest studied
// R_k, the smallest studied truncation at the studied R_k below the knee (when there are any),
// and nothing of an R_k outside the studied range.
std::string Rule(const ValidityCriteria& c) {
  std::vector<double> bounded, unbounded, below_knee;
  for (const RkBoundary& b : c.boundary) {
    (b.r_ftrunc_min ? bounded : unbounded).push_back(b.r_k);
    if (c.fit && b.r_k < c.fit->knee_r_k) below_knee.push_back(b.r_k);
  }
  std::string s;
  if (c.fit) {
    const PowerLawFit& f = *c.fit;
    s = fmt::format("R_ftrunc >= {:.3g} R_k^{:.3f} at R_k = {}", f.c_envelope, f.p,
                    Range(f.knee_r_k, bounded.back()));
    if (!below_knee.empty()) {
      s += fmt::format(" and R_ftrunc >= {:g} at R_k = {}", c.r_ftrunc_smallest_studied,
                       Range(below_knee.front(), below_knee.back()));
    }
    s += fmt::format(
        " (the fit over {} raised to cover the smallest passing truncation of every R_k; the "
        "exponent's {:.0f} % interval [{:.3f}, {:.3f}] {} the paper's 0.5 of R_ftrunc > "
        "sqrt(R_k))",
        Counted(f.n, "R_k", "R_k"), 100 * c.options.confidence, f.p_low, f.p_high,
        f.p_low <= 0.5 && 0.5 <= f.p_high ? "holds" : "excludes");
  } else {
    s = "no truncation rule could be fitted (fewer than two R_k pass above the smallest "
        "truncation): the smallest passing truncation of each R_k is in the table below";
  }
  if (c.dt_ratio_max) {
    s += fmt::format(", with dt <= {:.3g} dt_sharp", *c.dt_ratio_max);
  } else {
    s += ", but no time step passes at every R_k";
  }
  if (!bounded.empty()) {
    s += fmt::format(". It holds over the studied R_k = {} ({}) and says nothing outside them",
                     Range(bounded.front(), bounded.back()), Counted(bounded.size(), "value"));
  }
  if (!unbounded.empty()) {
    std::string list;
    for (double r : unbounded) list += fmt::format("{}{:.4g}", list.empty() ? "" : ", ", r);
    s += fmt::format("; no studied truncation passes at R_k = {}", list);
  }
  return s + ".";
}

// The time-step margin below the sharp stability bound.
std::string Margin(const ValidityCriteria& c) {
  std::string s;
  if (c.dt_ratio_max) {
    s = fmt::format(
        "Time-step margin: runs pass up to dt = {:.3g} dt_sharp, {:.3g} times below "
        "the sharp stability bound dt_sharp = 2/ω_max",
        *c.dt_ratio_max, 1.0 / *c.dt_ratio_max);
  } else {
    s = "Time-step margin: none (no studied dt passes at every R_k)";
  }
  if (c.largest_stable_dt_ratio) {
    s += fmt::format("; every run stayed stable up to {:.3g} dt_sharp", *c.largest_stable_dt_ratio);
  }
  if (c.smallest_diverged_dt_ratio) {
    s += fmt::format(" and stability was lost from {:.3g} dt_sharp", *c.smallest_diverged_dt_ratio);
  }
  return s + ".";
}

// Why runs of a status count for nothing, in a few words.
std::string StatusReason(RunStatus s) {
  switch (s) {
    case RunStatus::kDiverged:
      return "the state went non-finite or the energy passed its growth limit";
    case RunStatus::kUnstable:
      return fmt::format("reached the end with their energy grown more than {:g}-fold",
                         kUnstableEnergyRatio);
    case RunStatus::kFailed:
      return "a solve failed";
    case RunStatus::kReferenceUnconverged:
      return "the reference's two truncations disagree, so nothing is scored";
    case RunStatus::kOk:
      break;
  }
  return "";
}

// "Err alone", "Err and SRf together": the thresholded scores a point that ran to the end fails,
// in registry order, so that each failing point is counted under one name.
std::string FailedScores(const CriteriaOptions& options, const ScoredPoint& p) {
  std::vector<std::string> failed;
  for (const ScoreDefinition& score : Scores()) {
    const auto threshold = options.thresholds.find(score.name);
    if (threshold == options.thresholds.end()) continue;
    const std::optional<double> v = p.scores[score.name];
    if (v ? !score.Meets(*v, threshold->second) : score.required) {
      failed.emplace_back(score.label);
    }
  }
  if (failed.size() == 1) return failed.front() + " alone";
  std::string joined;
  for (std::size_t i = 0; i < failed.size(); ++i) {
    joined += (i == 0 ? "" : i + 1 == failed.size() ? " and " : ", ") + failed[i];
  }
  return joined + " together";
}

// The points that ran to the end, passing and failing (by which thresholds, each point once), then
// each other status with its reason, where in dt it happened, and a stored message.
std::string Failures(const ValidityCriteria& c, const std::vector<ScoredPoint>& points,
                     const Table& results) {
  std::map<std::int64_t, std::string> messages;
  const auto id_column = std::ranges::find(results.columns, "point_id") - results.columns.begin();
  const auto message_column =
      std::ranges::find(results.columns, "message") - results.columns.begin();
  for (const auto& row : results.rows) {
    if (static_cast<std::size_t>(message_column) < row.size()) {
      messages[std::get<std::int64_t>(row[id_column])] = CellText(row[message_column]);
    }
  }
  int ok = 0, passing = 0, undecided = 0;
  std::map<std::string, int> failing_by;  // By the scores failed together: each point once.
  struct Others {
    int n = 0;
    double dt_low = INFINITY, dt_high = 0.0;
    std::string message;
  };
  std::map<RunStatus, Others> others;
  for (const ScoredPoint& p : points) {
    if (p.status == RunStatus::kOk) {
      ++ok;
      if (c.options.Passes(p)) {
        ++passing;
        continue;
      }
      if (c.options.Undecided(p)) {
        ++undecided;
        continue;
      }
      ++failing_by[FailedScores(c.options, p)];
      continue;
    }
    Others& o = others[p.status];
    ++o.n;
    if (p.dt_sharp_s > 0) {
      o.dt_low = std::min(o.dt_low, p.DtRatio());
      o.dt_high = std::max(o.dt_high, p.DtRatio());
    }
    if (o.message.empty()) o.message = messages[p.point_id];
  }
  std::string s = fmt::format("Of {}, {} ran to the end: {} pass and {} fail the thresholds",
                              Counted(points.size(), "point"), ok, passing, ok - passing);
  std::string by;
  for (const auto& [scores, n] : failing_by) {
    by += fmt::format("{}{} by {}", by.empty() ? "" : ", ", n, scores);
  }
  if (undecided > 0) {
    by += fmt::format(
        "{}{} undecided: a score's spread over perturbed runs straddles its threshold, or their "
        "reference does not decide a thresholded score",
        by.empty() ? "" : ", ", undecided);
  }
  if (!by.empty()) s += " (" + by + ")";
  for (const auto& [status, o] : others) {
    s += fmt::format("; {} {} ({}", o.n, ToString(status), StatusReason(status));
    if (o.dt_high > 0) s += fmt::format(", at dt = {} dt_sharp", Range(o.dt_low, o.dt_high));
    if (!o.message.empty() && status != RunStatus::kDiverged) {
      s += fmt::format("; for one: \"{}\"", o.message);
    }
    s += ")";
  }
  return s + ".";
}

}  // namespace

std::string StudyVerdict(const std::string& study, const ValidityCriteria& c,
                         const std::vector<ScoredPoint>& points, const Table& results) {
  if (points.empty()) return fmt::format("Study {} has no scored point.", study);
  return fmt::format(
      "Study {} (explicit-modal scheme on the paper's beam, {} over {}), judged by {}. Validity "
      "rule: {} {} {}",
      study, Counted(points.size(), "point"), Studied(points), ThresholdsText(c.options, false),
      Rule(c), Margin(c), Failures(c, points, results));
}

Table CriteriaTable(const ValidityCriteria& c) {
  Table t;
  t.columns = {"R_k",
               "smallest passing R_ftrunc",
               "sqrt(R_k)",
               "R_ftrunc / sqrt(R_k)",
               "largest passing dt/dt_sharp",
               "stable up to dt/dt_sharp",
               "stability lost from dt/dt_sharp",
               "passing points",
               "points"};
  for (const RkBoundary& b : c.boundary) {
    const double root = std::sqrt(b.r_k);
    t.rows.push_back({b.r_k, Cell(b.r_ftrunc_min), root,
                      b.r_ftrunc_min ? TableCell(*b.r_ftrunc_min / root) : TableCell(),
                      Cell(b.dt_ratio_max), Cell(b.largest_stable_dt_ratio),
                      Cell(b.smallest_diverged_dt_ratio), static_cast<std::int64_t>(b.n_passing),
                      static_cast<std::int64_t>(b.n_points)});
  }
  return t;
}

}  // namespace shockmap

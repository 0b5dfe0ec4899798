#include "views/criteria_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "compare/comparison_options.h"
#include "formats/counted.h"
#include "formats/json_reader.h"
#include "formats/study_spec.h"
#include "validation/boundary_comparison.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

template <typename T>
Json OrNull(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

// What a criteria file may hold: a range per number, each end open or closed.
struct Allowed {
  double lo, hi;
  bool lo_open = true;
  const char* why = "";  // What lies outside, for the message.
};

// dt / dt_sharp where points pass: criteria are of the explicit scheme (as written below),
// which is unstable past its sharp bound, a ratio of 1.
constexpr Allowed kPassingDtRatio{0.0, 1.0, true,
                                  "above 1 the explicit scheme is past its stability bound"};
constexpr Allowed kDtRatio{0.0, 1e3};
// As a study's axes allow (formats/study_spec.cpp).
constexpr Allowed kRk{0.0, kMaxRk};
constexpr Allowed kRftrunc{1.0, 1e5, false};
// 0: nothing studied below the boundary.
constexpr Allowed kRftruncBelow{0.0, 1e5, false};
constexpr Allowed kExponent{-10.0, 10.0, false};
constexpr Allowed kCoefficient{0.0, 1e12};
constexpr Allowed kSpread{0.0, 1e3, false};  // A standard error or residual.
constexpr Allowed kFactor{1.0, 1e3, false};  // A ratio either way.

double Checked(JsonObjectReader& r, const std::string& key, double v, const Allowed& a) {
  if (!((a.lo_open ? v > a.lo : v >= a.lo) && v <= a.hi)) {
    r.Fail(key, fmt::format("value {} must lie in {}{:g}, {:g}]{}{}", Shown(Json(v)),
                            a.lo_open ? "(" : "[", a.lo, a.hi, *a.why ? ": " : "", a.why));
  }
  return v;
}

// Refuses, naming the file and the key, options outside CriteriaOptions::IsValid's ranges, which
// every use of them (DeriveCriteria, Passes, the views) assumes. `options` were read from
// "thresholds" (each score's key: err_max, srf_min, ...) and "fit" (confidence).
void CheckOptions(const CriteriaOptions& options, const std::string& file) {
  std::string error;  // "<name> = <value>: must be in [<lo>, <hi>]"
  if (options.IsValid(&error)) return;
  const std::string name = error.substr(0, error.find(' '));
  FailAt(file, (name == "confidence" ? "fit." : "thresholds.") + name, error);
}

double RequiredIn(JsonObjectReader& r, const std::string& key, const Allowed& a) {
  return Checked(r, key, r.RequiredNumber(key), a);
}

double ReadNumber(JsonObjectReader& r, const std::string& key, double fallback, const Allowed& a) {
  return Checked(r, key, r.Number(key, fallback), a);
}

// A fit through two R_k has no spread: its standard errors, interval and residual are NaN,
// which a baseline file holds as null.
double SpreadIn(JsonObjectReader& r, const std::string& key, double fallback, const Allowed& a) {
  const Json* v = r.Get(key);
  if (v != nullptr && (v->is_null() || (v->is_number_float() && std::isnan(v->get<double>())))) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return ReadNumber(r, key, fallback, a);
}

std::optional<double> OptionalNumber(JsonObjectReader& r, const std::string& key,
                                     const Allowed& a) {
  const Json* v = r.Get(key);
  if (v == nullptr || v->is_null()) return std::nullopt;
  return Checked(r, key, NumberAt(*v, r.File(), r.PathOf(key)), a);
}

std::string Num(std::optional<double> v) { return v ? fmt::format("{:.4g}", *v) : "-"; }

// {"err_max": 0.1, "srf_min": 0.8}: each threshold by its key.
Json ThresholdsJson(const CriteriaOptions& options) {
  Json thresholds = Json::object();
  for (const auto& [name, threshold] : options.thresholds) {
    thresholds[FindScore(name)->ThresholdKey()] = threshold;
  }
  return thresholds;
}

bool WithinFactor(double a, double b, double factor) {
  return a > 0 && b > 0 && std::max(a / b, b / a) <= factor * (1 + 1e-12);
}

// "unscored" or "undecided": optional (baselines written before them have none), each item an
// R_k, a count of at least 1 and a reason.
std::vector<PointsSetAside> SetAsideFromJson(JsonObjectReader& r, const std::string& key) {
  std::vector<PointsSetAside> unscored;
  const Json* list = r.Get(key);
  if (list == nullptr) return unscored;
  if (!list->is_array()) r.Fail(key, "expected a list, got " + Shown(*list));
  for (std::size_t i = 0; i < list->size(); ++i) {
    JsonObjectReader u((*list)[i], r.File(), r.PathOf(key) + "[" + std::to_string(i) + "]");
    PointsSetAside item{RequiredIn(u, "r_k", kRk), u.Integer("n_points", 0), u.Text("reason", "")};
    if (item.n_points < 1) u.Fail("n_points", "must be at least 1");
    u.Finish();
    unscored.push_back(std::move(item));
  }
  return unscored;
}

Json SetAsideToJson(const std::vector<PointsSetAside>& set_aside) {
  Json list = Json::array();
  for (const PointsSetAside& u : set_aside) {
    list.push_back({{"r_k", u.r_k}, {"n_points", u.n_points}, {"reason", u.reason}});
  }
  return list;
}

}  // namespace

Json CriteriaToJson(const std::string& study, const ValidityCriteria& c,
                    const CriteriaTolerances& t) {
  Json boundary = Json::array();
  for (const auto& b : c.boundary) {
    boundary.push_back({{"r_k", b.r_k},
                        {"n_points", b.n_points},
                        {"n_passing", b.n_passing},
                        {"r_ftrunc_min", OrNull(b.r_ftrunc_min)},
                        {"r_ftrunc_below", OrNull(b.r_ftrunc_below)},
                        {"dt_ratio_max", OrNull(b.dt_ratio_max)},
                        {"dt_ratio_above", OrNull(b.dt_ratio_above)},
                        {"largest_stable_dt_ratio", OrNull(b.largest_stable_dt_ratio)},
                        {"smallest_diverged_dt_ratio", OrNull(b.smallest_diverged_dt_ratio)}});
  }
  Json fit = nullptr;
  if (c.fit) {
    const PowerLawFit& f = *c.fit;
    fit = {{"n", f.n},
           {"knee_r_k", f.knee_r_k},
           {"p", f.p},
           {"p_stderr", f.p_stderr},
           {"p_low", f.p_low},
           {"p_high", f.p_high},
           {"confidence", c.options.confidence},
           {"c", f.c},
           {"log10_c_stderr", f.log10_c_stderr},
           {"c_envelope", f.c_envelope},
           {"rms_residual_log10", f.rms_residual_log10},
           {"sqrt_rk_inside_interval", f.p_low <= 0.5 && 0.5 <= f.p_high}};
  }
  return {{"study", study},
          {"scheme", "explicit-modal"},
          {"thresholds", ThresholdsJson(c.options)},
          {"r_ftrunc_smallest_studied", c.r_ftrunc_smallest_studied},
          {"boundary", boundary},
          {"unscored", SetAsideToJson(c.unscored)},
          {"undecided", SetAsideToJson(c.undecided)},
          {"fit", fit},
          {"dt_ratio_max", OrNull(c.dt_ratio_max)},
          {"largest_stable_dt_ratio", OrNull(c.largest_stable_dt_ratio)},
          {"smallest_diverged_dt_ratio", OrNull(c.smallest_diverged_dt_ratio)},
          {"tolerances",
           {{"p", t.p},
            {"c_envelope_factor", t.c_envelope_factor},
            {"dt_ratio_factor", t.dt_ratio_factor}}}};
}

ValidityCriteria CriteriaFromJson(const Json& json, const std::string& file,
                                  CriteriaTolerances* tolerances) {
  ValidityCriteria c;
  JsonObjectReader r(json, file, "");
  r.String("study", "");
  r.String("scheme", "");
  {
    const Json* th = r.Get("thresholds");
    if (th == nullptr) r.Fail("thresholds", "required object is missing");
    JsonObjectReader t(*th, file, r.PathOf("thresholds"));
    c.options.thresholds.clear();
    for (const ScoreDefinition& score : Scores()) {
      const std::string key = score.ThresholdKey();
      // A score judging by default was judged by every criteria file; another only when given.
      if (score.default_threshold || t.Get(key) != nullptr) {
        c.options.thresholds[std::string(score.name)] = t.RequiredNumber(key);
      }
    }
    t.Finish();
  }
  c.r_ftrunc_smallest_studied = RequiredIn(r, "r_ftrunc_smallest_studied", kRftrunc);
  if (const Json* boundary = r.Get("boundary"); boundary != nullptr && boundary->is_array()) {
    for (std::size_t i = 0; i < boundary->size(); ++i) {
      JsonObjectReader b((*boundary)[i], file,
                         r.PathOf("boundary") + "[" + std::to_string(i) + "]");
      RkBoundary rb;
      rb.r_k = RequiredIn(b, "r_k", kRk);
      rb.n_points = b.Integer("n_points", 0);
      rb.n_passing = b.Integer("n_passing", 0);
      rb.r_ftrunc_min = OptionalNumber(b, "r_ftrunc_min", kRftrunc);
      rb.r_ftrunc_below = OptionalNumber(b, "r_ftrunc_below", kRftruncBelow);
      rb.dt_ratio_max = OptionalNumber(b, "dt_ratio_max", kPassingDtRatio);
      rb.dt_ratio_above = OptionalNumber(b, "dt_ratio_above", kDtRatio);
      rb.largest_stable_dt_ratio = OptionalNumber(b, "largest_stable_dt_ratio", kDtRatio);
      rb.smallest_diverged_dt_ratio = OptionalNumber(b, "smallest_diverged_dt_ratio", kDtRatio);
      b.Finish();
      c.boundary.push_back(rb);
    }
  } else {
    r.Fail("boundary", "required list is missing");
  }
  c.unscored = SetAsideFromJson(r, "unscored");
  c.undecided = SetAsideFromJson(r, "undecided");
  if (const Json* fit = r.Get("fit"); fit != nullptr && !fit->is_null()) {
    JsonObjectReader f(*fit, file, r.PathOf("fit"));
    PowerLawFit p;
    p.n = f.Integer("n", 0);
    p.knee_r_k = RequiredIn(f, "knee_r_k", kRk);
    p.p = RequiredIn(f, "p", kExponent);
    p.p_stderr = SpreadIn(f, "p_stderr", 0.0, kSpread);
    p.p_low = SpreadIn(f, "p_low", p.p, kExponent);
    p.p_high = SpreadIn(f, "p_high", p.p, kExponent);
    c.options.confidence = f.Number("confidence", c.options.confidence);
    p.c = RequiredIn(f, "c", kCoefficient);
    p.log10_c_stderr = SpreadIn(f, "log10_c_stderr", 0.0, kSpread);
    p.c_envelope = RequiredIn(f, "c_envelope", kCoefficient);
    p.rms_residual_log10 = SpreadIn(f, "rms_residual_log10", 0.0, kSpread);
    f.Get("sqrt_rk_inside_interval");
    f.Finish();
    c.fit = p;
  }
  c.dt_ratio_max = OptionalNumber(r, "dt_ratio_max", kPassingDtRatio);
  c.largest_stable_dt_ratio = OptionalNumber(r, "largest_stable_dt_ratio", kDtRatio);
  c.smallest_diverged_dt_ratio = OptionalNumber(r, "smallest_diverged_dt_ratio", kDtRatio);
  if (const Json* t = r.Get("tolerances"); t != nullptr && tolerances != nullptr) {
    JsonObjectReader tr(*t, file, r.PathOf("tolerances"));
    tolerances->p = ReadNumber(tr, "p", tolerances->p, kSpread);
    tolerances->c_envelope_factor =
        ReadNumber(tr, "c_envelope_factor", tolerances->c_envelope_factor, kFactor);
    tolerances->dt_ratio_factor =
        ReadNumber(tr, "dt_ratio_factor", tolerances->dt_ratio_factor, kFactor);
    tr.Finish();
  }
  r.Finish();
  CheckOptions(c.options, file);
  return c;
}

namespace {

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

namespace {

// The studied truncation at `r_k` below `r_ftrunc_min`, the largest (0 when none), or the
// largest studied when r_ftrunc_min is none.
double StudiedBelow(const std::vector<ScoredPoint>& points, double r_k,
                    const std::optional<double>& r_ftrunc_min) {
  double below = 0.0;
  for (const ScoredPoint& p : points) {
    if (std::abs(p.r_k - r_k) > 1e-9 * r_k) continue;
    if (!r_ftrunc_min || p.r_ftrunc < *r_ftrunc_min * (1 - 1e-9))
      below = std::max(below, p.r_ftrunc);
  }
  return below;
}

// "(100, 215.4]", "above 1000": where a grid put a truncation boundary.
std::string Span(const ResolvedBoundary& b) {
  if (!b.value) return fmt::format("above {:.4g}", b.low);
  return fmt::format("({:.4g}, {:.4g}]", b.low, *b.value);
}

// Why the fits and the time-step bounds of two criteria cannot be set side by side: derived over
// different R_k, or with a different smallest truncation (the knee is the first R_k whose
// boundary rises above it); nullopt when they can.
std::optional<std::string> FitGridDifference(const ValidityCriteria& baseline,
                                             const ValidityCriteria& current) {
  auto r_ks = [](const ValidityCriteria& c) {
    std::vector<double> r_k;
    for (const RkBoundary& b : c.boundary) r_k.push_back(b.r_k);
    return r_k;
  };
  const std::vector<double> was = r_ks(baseline), is = r_ks(current);
  const bool same_r_k = std::ranges::equal(
      was, is, [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(x, y); });
  if (!same_r_k) {
    auto range = [](const std::vector<double>& r) {
      return r.empty() ? std::string("none")
                       : fmt::format("{:.4g} to {:.4g} ({} values)", r.front(), r.back(), r.size());
    };
    return fmt::format(
        "not comparable: grids differ at R_k (the baseline studied {}, the study {})", range(was),
        range(is));
  }
  const double a = baseline.r_ftrunc_smallest_studied, b = current.r_ftrunc_smallest_studied;
  if (std::abs(a - b) > 1e-9 * std::max(a, b)) {
    return fmt::format(
        "not comparable: grids differ at R_ftrunc (the smallest studied is {:g} in the baseline, "
        "{:g} in the study)",
        a, b);
  }
  return std::nullopt;
}

}  // namespace

BaselineCheck CheckAgainstBaseline(const ValidityCriteria& baseline, const CriteriaTolerances& t,
                                   const ValidityCriteria& current,
                                   const std::vector<ScoredPoint>& points) {
  BaselineCheck check;
  std::vector<std::string>& problems = check.contradictions;
  const std::optional<std::string> other_grid = FitGridDifference(baseline, current);
  if (other_grid) {
    check.not_comparable.push_back("criteria fit and dt/dt_sharp max: " + *other_grid);
  } else if (baseline.fit.has_value() != current.fit.has_value()) {
    problems.push_back(fmt::format("criterion fit: baseline {}, now {}",
                                   baseline.fit ? "fitted" : "none",
                                   current.fit ? "fitted" : "none"));
  } else if (baseline.fit) {
    const PowerLawFit& a = *baseline.fit;
    const PowerLawFit& b = *current.fit;
    if (std::abs(a.p - b.p) > t.p) {
      problems.push_back(
          fmt::format("criterion p: baseline {:.4f}, now {:.4f} (tolerance {:g})", a.p, b.p, t.p));
    }
    if (!WithinFactor(a.c_envelope, b.c_envelope, t.c_envelope_factor)) {
      problems.push_back(fmt::format("criterion C: baseline {:.4g}, now {:.4g} (tolerance x{:g})",
                                     a.c_envelope, b.c_envelope, t.c_envelope_factor));
    }
    if (a.knee_r_k != b.knee_r_k) {
      problems.push_back(
          fmt::format("criterion knee R_k: baseline {:.4g}, now {:.4g}", a.knee_r_k, b.knee_r_k));
    }
  }
  if (!other_grid && baseline.dt_ratio_max && current.dt_ratio_max &&
      !WithinFactor(*baseline.dt_ratio_max, *current.dt_ratio_max, t.dt_ratio_factor)) {
    problems.push_back(fmt::format("criterion dt/dt_sharp max: baseline {:.4g}, now {:.4g}",
                                   *baseline.dt_ratio_max, *current.dt_ratio_max));
  }
  for (const auto& old : baseline.boundary) {
    for (const auto& now : current.boundary) {
      if (std::abs(now.r_k - old.r_k) > 1e-9 * old.r_k) continue;
      // A baseline that did not record where its grid put the boundary is taken to share the
      // study's grid.
      const ResolvedBoundary was =
          TruncationBoundary(old, StudiedBelow(points, old.r_k, old.r_ftrunc_min));
      const ResolvedBoundary is = TruncationBoundary(now, 0.0);
      const BoundaryComparison comparison = Compare(was, is);
      if (comparison == BoundaryComparison::kAlike) continue;
      const std::string line =
          fmt::format("criterion R_ftrunc_min at R_k = {:.4g}: baseline {}, now {}", old.r_k,
                      Num(old.r_ftrunc_min), Num(now.r_ftrunc_min));
      if (comparison == BoundaryComparison::kDiffers) {
        problems.push_back(line);
      } else {
        check.not_comparable.push_back(
            fmt::format("{}: not comparable: grids differ at R_ftrunc (the baseline puts the "
                        "boundary in {}, the study in {})",
                        line, Span(was), Span(is)));
      }
    }
  }
  for (const auto& c : FindContradictions(baseline, points)) {
    problems.push_back(fmt::format("point {} (R_k = {:.4g}, R_ftrunc = {:g}): {}", c.point.point_id,
                                   c.point.r_k, c.point.r_ftrunc, c.reason));
  }
  return check;
}

}  // namespace shockmap

#include "analysis/study_diff.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "analysis/outcome_category.h"
#include "analysis/scored_points.h"
#include "analysis/study_thresholds.h"
#include "core/input_error.h"
#include "core/scheme.h"
#include "db/report_queries.h"
#include "db/study_queries.h"
#include "formats/json_reader.h"
#include "specs/study_file.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

bool Close(double x, double y, double relative_tolerance) {
  return std::abs(x - y) <= relative_tolerance * std::max(std::abs(x), std::abs(y));
}

// The stored study file of a study of the paper's problem. Throws InputError for any other
// kind.
StudySpec StoredCanonicalSpec(const std::string& database_path, const std::string& study,
                              const std::string& role) {
  const std::string file = database_path + ": stored study " + study;
  const Json stored = ParseJsonText(StoredStudySpec(database_path, study).value_or("{}"), file);
  const StudyFileKind kind = StudyKindOf(stored, file);
  if (kind != StudyFileKind::kCanonical) {
    throw InputError(fmt::format(
        "STUDY {}: study {} in {} is of kind \"{}\"; diff compares studies of the paper's "
        "problem (kind \"canonical\"), scored point by point against its reference",
        role, study, database_path, ToString(kind)));
  }
  return ParseStudySpec(stored, file);
}

// "/psd/window" -> "psd.window".
std::string Dotted(const std::string& pointer) {
  std::string path = pointer.substr(1);
  std::ranges::replace(path, '/', '.');
  return path;
}

std::map<std::string, Json> SettingsOf(const StudySpec& spec, const CriteriaOptions& options) {
  Json nested = Json::parse(SettingsKey(spec));
  nested["srf_definition"] = ToString(spec.scoring.srf_definition);
  for (const auto& [name, threshold] : options.thresholds) nested["thresholds"][name] = threshold;
  std::map<std::string, Json> settings;
  const Json flat = nested.flatten();
  for (const auto& [pointer, value] : flat.items()) settings[Dotted(pointer)] = value;
  std::set<double> windows;
  for (const StudyPoint& p : spec.points) windows.insert(p.window_s);
  settings["window_s"] = windows.size() == 1 ? Json(*windows.begin()) : Json(windows);
  return settings;
}

// The stored points of every scheme with the parameters they were asked with.
std::vector<DiffPoint> LoadDiffPoints(const std::string& database_path, const std::string& study) {
  std::vector<DiffPoint> points;
  for (Scheme scheme : {Scheme::kExplicitModal, Scheme::kImplicitFull}) {
    const Table rows = ScoredPointRows(database_path, study, ToString(scheme));
    std::map<std::int64_t, ScoredPoint> scored;
    for (ScoredPoint& p : LoadScoredPoints(database_path, study, ToString(scheme))) {
      scored.emplace(p.point_id, std::move(p));
    }
    for (std::size_t i = 0; i < rows.rows.size(); ++i) {
      const NamedRow row(rows, i);
      const auto id = std::get_if<std::int64_t>(&row["point_id"]);
      const auto found = id != nullptr ? scored.find(*id) : scored.end();
      if (found == scored.end()) continue;  // Stored between the two reads: not yet scored.
      DiffPoint p;
      p.scored = found->second;
      p.scheme = ToString(scheme);
      const auto* rule = std::get_if<std::string>(&row["dt_rule"]);
      p.dt_rule = rule != nullptr ? *rule : "";
      p.dt_asked = NumberIn(row[rule != nullptr ? "dt_factor" : "dt_asked_s"]).value_or(0.0);
      p.window_s = NumberIn(row["window_s"]).value_or(0.0);
      p.mass_damping_per_s = NumberIn(row["mass_damping_per_s"]).value_or(0.0);
      points.push_back(std::move(p));
    }
  }
  return points;
}

bool SameParameters(const DiffPoint& a, const DiffPoint& b, double tolerance) {
  return a.scheme == b.scheme && a.dt_rule == b.dt_rule &&
         Close(a.scored.r_k, b.scored.r_k, tolerance) &&
         Close(a.scored.r_ftrunc, b.scored.r_ftrunc, tolerance) &&
         Close(a.dt_asked, b.dt_asked, tolerance) && Close(a.window_s, b.window_s, tolerance) &&
         Close(a.mass_damping_per_s, b.mass_damping_per_s, tolerance);
}

std::vector<SettingDifference> SettingDifferences(const DiffedStudy& a, const DiffedStudy& b) {
  std::set<std::string> names;
  for (const auto* s : {&a.settings, &b.settings}) {
    for (const auto& [name, value] : *s) names.insert(name);
  }
  std::vector<SettingDifference> differences;
  for (const std::string& name : names) {
    const auto in_a = a.settings.find(name);
    const auto in_b = b.settings.find(name);
    const Json va = in_a != a.settings.end() ? in_a->second : Json();
    const Json vb = in_b != b.settings.end() ? in_b->second : Json();
    if (va != vb) differences.push_back({name, va, vb});
  }
  return differences;
}

std::vector<CriteriaRow> CriteriaRows(const ValidityCriteria& a, const ValidityCriteria& b,
                                      double tolerance) {
  std::vector<CriteriaRow> rows;
  for (const RkBoundary& boundary : a.boundary) rows.push_back({boundary.r_k, boundary, {}, {}});
  for (const RkBoundary& boundary : b.boundary) {
    const auto same = std::ranges::find_if(
        rows, [&](const CriteriaRow& r) { return Close(r.r_k, boundary.r_k, tolerance); });
    if (same != rows.end()) {
      same->b = boundary;
    } else {
      rows.push_back({boundary.r_k, {}, boundary, {}});
    }
  }
  std::ranges::sort(rows, {}, &CriteriaRow::r_k);
  return rows;
}

// The explicit modal points' values of `value` at `r_k` (R_ftrunc, dt / dt_sharp), ascending.
template <typename Value>
std::vector<double> StudiedAt(const DiffedStudy& s, double r_k, Value value) {
  std::vector<double> values;
  for (const DiffPoint& p : s.points) {
    if (p.scheme != ToString(Scheme::kExplicitModal) || !Close(p.scored.r_k, r_k, 1e-9)) continue;
    if (std::ranges::none_of(values, [&](double v) { return Close(v, value(p.scored), 1e-9); })) {
      values.push_back(value(p.scored));
    }
  }
  std::ranges::sort(values);
  return values;
}

// "215.4 in A only, 316.2 in B only": the values of one study only within the spans the two
// boundaries lie in (every such value when none lies there).
std::string OneStudyOnly(const std::vector<double>& in_a, const std::vector<double>& in_b,
                         const ResolvedBoundary& ba, const ResolvedBoundary& bb) {
  const double low = std::min(ba.low, bb.low), high = std::max(ba.high, bb.high);
  std::string text;
  for (const auto& [role, mine, theirs] : {std::tuple{"A", &in_a, &in_b}, {"B", &in_b, &in_a}}) {
    std::vector<std::string> only, within;
    for (double v : *mine) {
      if (std::ranges::any_of(*theirs, [&](double w) { return Close(v, w, 1e-9); })) continue;
      only.push_back(fmt::format("{:.4g}", v));
      if (v >= low * (1 - 1e-9) && v <= high * (1 + 1e-9)) within.push_back(only.back());
    }
    const auto& shown = within.empty() ? only : within;
    if (shown.empty()) continue;
    text += fmt::format("{}{} in {} only", text.empty() ? "" : ", ", fmt::join(shown, ", "), role);
  }
  return text;
}

// Why the boundaries of a row cannot be compared ("R_ftrunc 215.4 in A only, 316.2 in B only"),
// or empty when they can.
std::string GridsDiffer(const CriteriaRow& row, const DiffedStudy& a, const DiffedStudy& b) {
  std::string why;
  if (row.Truncation() == BoundaryComparison::kNotComparable) {
    auto r_ftrunc = [](const ScoredPoint& p) { return p.r_ftrunc; };
    why = "R_ftrunc " +
          OneStudyOnly(StudiedAt(a, row.r_k, r_ftrunc), StudiedAt(b, row.r_k, r_ftrunc),
                       TruncationBoundary(*row.a, 0.0), TruncationBoundary(*row.b, 0.0));
  }
  if (row.Dt() == BoundaryComparison::kNotComparable && row.a->dt_ratio_max &&
      row.b->dt_ratio_max) {
    auto ratio = [](const ScoredPoint& p) { return p.DtRatio(); };
    why += (why.empty() ? "" : "; ") + std::string("dt/dt_sharp ") +
           OneStudyOnly(StudiedAt(a, row.r_k, ratio), StudiedAt(b, row.r_k, ratio),
                        DtBoundary(*row.a), DtBoundary(*row.b));
  }
  return why;
}

// A's points matched to B's: B sorted by R_k, each A point looks among the B points of its R_k
// within the tolerance; a B point is matched once.
void MatchPoints(const DiffedStudy& a, const DiffedStudy& b, double tolerance, StudyDiff& diff) {
  std::vector<std::size_t> order(b.points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::ranges::sort(order, {}, [&](std::size_t i) { return b.points[i].scored.r_k; });
  std::vector<bool> used(b.points.size(), false);
  for (const DiffPoint& p : a.points) {
    const double low = p.scored.r_k * (1.0 - tolerance);
    auto it = std::ranges::lower_bound(order, low, {},
                                       [&](std::size_t i) { return b.points[i].scored.r_k; });
    std::optional<std::size_t> match;
    for (; it != order.end() && b.points[*it].scored.r_k <= p.scored.r_k * (1.0 + tolerance);
         ++it) {
      if (!used[*it] && SameParameters(p, b.points[*it], tolerance)) {
        match = *it;
        break;
      }
    }
    if (!match) {
      diff.only_a.push_back(p);
      continue;
    }
    used[*match] = true;
    const PointPair pair{p, b.points[*match]};
    diff.matched.push_back(pair);
    if (OutcomeCategoryOf(p.scored, a.criteria.options) !=
        OutcomeCategoryOf(pair.b.scored, b.criteria.options)) {
      diff.changed.push_back(pair);
    }
  }
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    if (!used[i]) diff.only_b.push_back(b.points[i]);
  }
}

std::string ShownSetting(const Json& v) { return v.is_null() ? "(not set)" : v.dump(); }

}  // namespace

DiffedStudy LoadDiffedStudy(const std::string& database_path, const std::string& study,
                            const std::map<std::string, double, std::less<>>& given,
                            const std::string& role) {
  DiffedStudy d;
  d.name = ResolveStudyName(database_path, study);
  d.database_path = database_path;
  const StudySpec spec = StoredCanonicalSpec(database_path, d.name, role);
  const CriteriaOptions options = StudyCriteriaOptions(database_path, d.name, given);
  d.settings = SettingsOf(spec, options);
  d.criteria = DeriveCriteria(LoadCriteriaPoints(database_path, d.name), options);
  d.points = LoadDiffPoints(database_path, d.name);
  return d;
}

bool ScoresComparableAcross(const std::string& setting) {
  return setting != "window_s" && setting != "srf_definition" && setting != "rest_duration_t1";
}

BoundaryComparison CriteriaRow::Truncation() const {
  if (!a || !b) return BoundaryComparison::kAlike;
  return Compare(TruncationBoundary(*a, 0.0), TruncationBoundary(*b, 0.0));
}

BoundaryComparison CriteriaRow::Dt() const {
  if (!a || !b) return BoundaryComparison::kAlike;
  if (a->dt_ratio_max && b->dt_ratio_max) return Compare(DtBoundary(*a), DtBoundary(*b));
  if (a->dt_ratio_max || b->dt_ratio_max) return Truncation();
  return BoundaryComparison::kAlike;
}

StudyDiff DiffStudies(const DiffedStudy& a, const DiffedStudy& b, double relative_tolerance) {
  StudyDiff diff;
  diff.settings = SettingDifferences(a, b);
  for (const SettingDifference& s : diff.settings) {
    if (ScoresComparableAcross(s.setting)) continue;
    throw InputError(fmt::format(
        "studies {} and {} differ in the scoring setting {} ({} in A, {} in B): Err and SRf "
        "scored with different {} are not comparable point by point. Compare studies scored "
        "alike (they may differ in the PSD estimate, the reference, the thresholds and the "
        "beam)",
        a.name, b.name, s.setting, ShownSetting(s.a), ShownSetting(s.b),
        s.setting == "window_s" ? "windows" : "settings"));
  }
  diff.criteria = CriteriaRows(a.criteria, b.criteria, relative_tolerance);
  for (CriteriaRow& row : diff.criteria) row.grids_differ = GridsDiffer(row, a, b);
  MatchPoints(a, b, relative_tolerance, diff);
  return diff;
}

std::string OutcomeOf(const DiffPoint& p, const CriteriaOptions& options) {
  return OutcomeLabels()[static_cast<std::size_t>(OutcomeCategoryOf(p.scored, options))];
}

}  // namespace shockmap

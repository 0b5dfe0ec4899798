#include "views/study_diff.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <tuple>

#include "analysis/scored_points.h"
#include "analysis/study_thresholds.h"
#include "core/input_error.h"
#include "core/scheme.h"
#include "db/report_queries.h"
#include "db/study_queries.h"
#include "formats/json_reader.h"
#include "formats/study_file.h"
#include "formats/table_output.h"
#include "views/map_grid.h"

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

std::string Shown(const std::optional<double>& v) {
  return v ? fmt::format("{:.6g}", *v) : std::string("none");
}

std::string ShownSetting(const Json& v) { return v.is_null() ? "(not set)" : v.dump(); }

// The thresholded scores, in registry order.
std::vector<const ScoreDefinition*> JudgedScores(const DiffedStudy& a, const DiffedStudy& b) {
  std::vector<const ScoreDefinition*> scores;
  for (const ScoreDefinition& score : Scores()) {
    if (a.criteria.options.thresholds.contains(score.name) ||
        b.criteria.options.thresholds.contains(score.name)) {
      scores.push_back(&score);
    }
  }
  return scores;
}

std::string FitText(const ValidityCriteria& c) {
  if (!c.fit) return "no fit: fewer than two R_k have a boundary above the smallest truncation";
  return fmt::format(
      "R_ftrunc = {:.3g} R_k^{:.3f} above the knee R_k = {:.4g} (p in [{:.3f}, {:.3f}])",
      c.fit->c_envelope, c.fit->p, c.fit->knee_r_k, c.fit->p_low, c.fit->p_high);
}

std::string DtText(const ValidityCriteria& c) {
  return c.dt_ratio_max
             ? fmt::format("dt <= {:.4g} dt_sharp at every R_k with a boundary", *c.dt_ratio_max)
             : std::string("no dt passes at every R_k");
}

// How far a score moved between the matched points scored in both.
struct ScoreShift {
  int n_scored = 0, n_moved = 0;
  double largest = 0.0;
  const PointPair* where = nullptr;
};

ScoreShift ShiftOf(const StudyDiff& diff, const ScoreDefinition& score) {
  ScoreShift shift;
  for (const PointPair& pair : diff.matched) {
    const auto va = pair.a.scored.scores[score.name];
    const auto vb = pair.b.scored.scores[score.name];
    if (!va || !vb) continue;
    ++shift.n_scored;
    const double moved = *vb - *va;
    if (moved != 0.0) ++shift.n_moved;
    if (std::abs(moved) > std::abs(shift.largest)) {
      shift.largest = moved;
      shift.where = &pair;
    }
  }
  return shift;
}

Json BoundaryJson(const std::optional<RkBoundary>& b) {
  if (!b) return nullptr;
  auto optional = [](const std::optional<double>& v) { return v ? Json(*v) : Json(); };
  return {{"n_points", b->n_points},
          {"n_passing", b->n_passing},
          {"r_ftrunc_min", optional(b->r_ftrunc_min)},
          {"dt_ratio_max", optional(b->dt_ratio_max)}};
}

Json FitJson(const ValidityCriteria& c) {
  Json j{{"dt_ratio_max", c.dt_ratio_max ? Json(*c.dt_ratio_max) : Json()}};
  j["fit"] = c.fit ? Json{{"p", c.fit->p},
                          {"p_low", c.fit->p_low},
                          {"p_high", c.fit->p_high},
                          {"c_envelope", c.fit->c_envelope},
                          {"knee_r_k", c.fit->knee_r_k}}
                   : Json();
  return j;
}

Json PointJson(const DiffPoint& p) {
  return {{"scheme", p.scheme},
          {"r_k", p.scored.r_k},
          {"r_ftrunc", p.scored.r_ftrunc},
          {"dt_rule", p.dt_rule.empty() ? Json() : Json(p.dt_rule)},
          {p.dt_rule.empty() ? "dt_s" : "dt_factor", p.dt_asked},
          {"window_s", p.window_s},
          {"mass_damping_per_s", p.mass_damping_per_s}};
}

Json OutcomeJson(const DiffPoint& p, const DiffedStudy& study) {
  Json j{{"point_id", p.scored.point_id},
         {"outcome", OutcomeOf(p, study.criteria.options)},
         {"status", ToString(p.scored.status)}};
  for (const ScoreDefinition& score : Scores()) {
    const auto v = p.scored.scores[score.name];
    j[std::string(score.name)] = v ? Json(*v) : Json();
  }
  return j;
}

}  // namespace

DiffedStudy LoadDiffedStudy(const std::string& database_path, const std::string& study,
                            const std::map<std::string, double, std::less<>>& given,
                            const std::string& role) {
  DiffedStudy d;
  d.name = ResolveStudyName(database_path, study);
  d.database_path = database_path;
  const StudySpec spec = StoredCanonicalSpec(database_path, d.name, role);
  const CriteriaOptions options = StudyCriteriaOptions(database_path, d.name, given);
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
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
  return OutcomeCategories()[static_cast<std::size_t>(OutcomeCategoryOf(p.scored, options))].label;
}

std::string PointLabel(const DiffPoint& p) {
  std::string label = p.scheme == ToString(Scheme::kExplicitModal) ? "" : p.scheme + " ";
  label += fmt::format("R_k {:.6g}, R_ftrunc {:.6g}, dt ", p.scored.r_k, p.scored.r_ftrunc);
  label += p.dt_rule.empty() ? fmt::format("{:.4g} s", p.dt_asked)
                             : fmt::format("{:.4g} dt_{}", p.dt_asked, p.dt_rule);
  if (p.mass_damping_per_s != 0.0) label += fmt::format(", damping {:g}/s", p.mass_damping_per_s);
  return label;
}

std::string DiffText(const DiffedStudy& a, const DiffedStudy& b, const StudyDiff& diff) {
  std::ostringstream out;
  out << fmt::format("diff: A = study {} ({}), B = study {} ({})\n", a.name, a.database_path,
                     b.name, b.database_path);
  if (diff.settings.empty()) out << "  settings     alike\n";
  for (std::size_t i = 0; i < diff.settings.size(); ++i) {
    const SettingDifference& s = diff.settings[i];
    out << fmt::format("  {}{}: {} in A, {} in B\n", i == 0 ? "settings     " : "             ",
                       s.setting, ShownSetting(s.a), ShownSetting(s.b));
  }
  out << fmt::format("  thresholds   A: {}; B: {}\n", ThresholdsText(a.criteria.options, false),
                     ThresholdsText(b.criteria.options, false));

  out << "\ncriteria at each R_k: the smallest passing R_ftrunc and the largest passing "
         "dt/dt_sharp (`criteria derive`)\n";
  WriteTable(DiffCriteriaTable(diff), TableFormat::kTable, out);
  out << fmt::format("  fit          A: {}\n               B: {}\n", FitText(a.criteria),
                     FitText(b.criteria));
  out << fmt::format("  dt           A: {}\n               B: {}\n", DtText(a.criteria),
                     DtText(b.criteria));
  const auto boundary_moves = std::ranges::count_if(
      diff.criteria, [](const CriteriaRow& r) { return r.TruncationDiffers() || r.DtDiffers(); });
  const auto not_comparable =
      std::ranges::count_if(diff.criteria, [](const CriteriaRow& r) { return !r.Comparable(); });
  out << fmt::format("  boundary     differs at {} of {} R_k", boundary_moves,
                     diff.criteria.size());
  if (not_comparable > 0) {
    out << fmt::format(
        "; not comparable at {}: the grids differ where the boundary is decided (the table's "
        "last column)",
        not_comparable);
  }
  out << '\n';

  out << fmt::format(
      "\npoints: {} in A, {} in B, {} at the same parameters; {} changed outcome, {} in A only, "
      "{} in B only\n",
      a.points.size(), b.points.size(), diff.matched.size(), diff.changed.size(),
      diff.only_a.size(), diff.only_b.size());
  for (const ScoreDefinition* score : JudgedScores(a, b)) {
    const ScoreShift shift = ShiftOf(diff, *score);
    out << fmt::format("  {:<12} changed at {} of {} points scored in both", score->label,
                       shift.n_moved, shift.n_scored);
    if (shift.where != nullptr) {
      out << fmt::format(", most by {:+.3g} at {}", shift.largest, PointLabel(shift.where->a));
    }
    out << '\n';
  }
  if (!diff.changed.empty()) {
    Table changed{{"point", "outcome A", "outcome B"}, {}};
    for (const ScoreDefinition* score : JudgedScores(a, b)) {
      changed.columns.push_back(std::string(score->label) + " A");
      changed.columns.push_back(std::string(score->label) + " B");
    }
    for (const PointPair& pair : diff.changed) {
      std::vector<TableCell> row{PointLabel(pair.a), OutcomeOf(pair.a, a.criteria.options),
                                 OutcomeOf(pair.b, b.criteria.options)};
      for (const ScoreDefinition* score : JudgedScores(a, b)) {
        for (const DiffPoint* p : {&pair.a, &pair.b}) {
          const auto v = p->scored.scores[score->name];
          row.emplace_back(v ? fmt::format("{:.4g}", *v) : std::string("-"));
        }
      }
      changed.rows.push_back(std::move(row));
    }
    WriteTable(changed, TableFormat::kTable, out);
  }
  for (const auto& [role, only] : {std::pair{"A", &diff.only_a}, std::pair{"B", &diff.only_b}}) {
    constexpr std::size_t kListed = 10;
    for (std::size_t i = 0; i < only->size() && i < kListed; ++i) {
      out << fmt::format("  {}{}\n", i == 0 ? fmt::format("in {} only    ", role) : "             ",
                         PointLabel((*only)[i]));
    }
    if (only->size() > kListed) {
      out << fmt::format("               ... and {} more (--format csv lists every point)\n",
                         only->size() - kListed);
    }
  }
  return out.str();
}

Table DiffCriteriaTable(const StudyDiff& diff) {
  Table t{{"R_k", "R_ftrunc A", "R_ftrunc B", "dt/dt_sharp A", "dt/dt_sharp B", "differs"}, {}};
  for (const CriteriaRow& r : diff.criteria) {
    auto side = [](const std::optional<RkBoundary>& b, bool truncation) {
      if (!b) return std::string("not studied");
      return Shown(truncation ? b->r_ftrunc_min : b->dt_ratio_max);
    };
    std::string differs = r.TruncationDiffers() ? "R_ftrunc" : "";
    if (r.DtDiffers()) differs += differs.empty() ? "dt" : ", dt";
    if (!r.Comparable()) {
      differs +=
          (differs.empty() ? "" : "; ") + ("not comparable: grids differ at " + r.grids_differ);
    }
    t.rows.push_back({fmt::format("{:.6g}", r.r_k), side(r.a, true), side(r.b, true),
                      side(r.a, false), side(r.b, false), differs});
  }
  return t;
}

Json DiffToJson(const DiffedStudy& a, const DiffedStudy& b, const StudyDiff& diff) {
  Json j{{"a", {{"study", a.name}, {"database", a.database_path}}},
         {"b", {{"study", b.name}, {"database", b.database_path}}}};
  j["settings_differing"] = Json::array();
  for (const SettingDifference& s : diff.settings) {
    j["settings_differing"].push_back({{"setting", s.setting}, {"a", s.a}, {"b", s.b}});
  }
  j["thresholds"] = {{"a", a.criteria.options.thresholds}, {"b", b.criteria.options.thresholds}};
  j["criteria"] = {{"a", FitJson(a.criteria)}, {"b", FitJson(b.criteria)}};
  j["criteria"]["by_r_k"] = Json::array();
  for (const CriteriaRow& r : diff.criteria) {
    j["criteria"]["by_r_k"].push_back(
        {{"r_k", r.r_k},
         {"a", BoundaryJson(r.a)},
         {"b", BoundaryJson(r.b)},
         {"r_ftrunc_differs", r.TruncationDiffers()},
         {"dt_differs", r.DtDiffers()},
         {"comparable", r.Comparable()},
         {"grids_differ", r.Comparable() ? Json() : Json(r.grids_differ)}});
  }
  Json& points = j["points"];
  points = {{"in_a", a.points.size()},  {"in_b", b.points.size()}, {"matched", diff.matched.size()},
            {"changed", Json::array()}, {"only_a", Json::array()}, {"only_b", Json::array()}};
  for (const PointPair& pair : diff.changed) {
    Json p = PointJson(pair.a);
    p["a"] = OutcomeJson(pair.a, a);
    p["b"] = OutcomeJson(pair.b, b);
    points["changed"].push_back(p);
  }
  for (const DiffPoint& p : diff.only_a) points["only_a"].push_back(PointJson(p));
  for (const DiffPoint& p : diff.only_b) points["only_b"].push_back(PointJson(p));
  return j;
}

Table DiffPointTable(const DiffedStudy& a, const DiffedStudy& b, const StudyDiff& diff) {
  Table t{{"scheme", "r_k", "r_ftrunc", "dt_rule", "dt_asked", "window_s", "mass_damping_per_s",
           "studied_in", "outcome_a", "outcome_b", "outcome_changed"},
          {}};
  for (const ScoreDefinition& score : Scores()) {
    t.columns.push_back(std::string(score.name) + "_a");
    t.columns.push_back(std::string(score.name) + "_b");
  }
  // Cells are set in place: GCC 12 warns falsely on moving a TableCell built by a conditional.
  auto add = [&](const DiffPoint& p, const DiffPoint* in_a, const DiffPoint* in_b) {
    std::vector<TableCell> row{p.scheme,   p.scored.r_k, p.scored.r_ftrunc,   p.dt_rule,
                               p.dt_asked, p.window_s,   p.mass_damping_per_s};
    if (p.dt_rule.empty()) row[3] = std::string("seconds");
    row.emplace_back(std::string(in_a && in_b ? "both" : (in_a ? "A" : "B")));
    for (const DiffPoint* side : {in_a, in_b}) {
      row.emplace_back();
      if (side) row.back() = OutcomeOf(*side, (side == in_a ? a : b).criteria.options);
    }
    row.emplace_back();
    if (in_a && in_b) row.back() = std::int64_t{row[8] != row[9]};
    for (const ScoreDefinition& score : Scores()) {
      for (const DiffPoint* side : {in_a, in_b}) {
        row.emplace_back();
        if (const auto v = side ? side->scored.scores[score.name] : std::nullopt) row.back() = *v;
      }
    }
    t.rows.push_back(std::move(row));
  };
  for (const PointPair& pair : diff.matched) add(pair.a, &pair.a, &pair.b);
  for (const DiffPoint& p : diff.only_a) add(p, &p, nullptr);
  for (const DiffPoint& p : diff.only_b) add(p, nullptr, &p);
  return t;
}

}  // namespace shockmap

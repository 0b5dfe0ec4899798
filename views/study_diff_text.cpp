#include "views/study_diff_text.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/scheme.h"
#include "formats/table_output.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

std::string ShownSetting(const Json& v) { return v.is_null() ? "(not set)" : v.dump(); }

std::string Shown(const std::optional<double>& v) {
  return v ? fmt::format("{:.6g}", *v) : std::string("none");
}

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

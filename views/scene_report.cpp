// The report's sections for a scene study (declared in views/html_report.h).

#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "db/report_queries.h"
#include "formats/counted.h"
#include "views/html_report.h"
#include "views/html_text.h"
#include "views/map_grid.h"
#include "views/sweep_outcome_map.h"

namespace shockmap {
namespace {

std::size_t ColumnOf(const Table& r, const std::string& name) {
  return static_cast<std::size_t>(std::ranges::find(r.columns, name) - r.columns.begin());
}

// A stored row's status and scores, as the criteria judge them.
ScoredPoint Judged(const Table& results, const std::vector<TableCell>& row) {
  ScoredPoint p;
  p.status =
      RunStatusFromString(CellText(row[ColumnOf(results, "status")])).value_or(RunStatus::kFailed);
  for (const ScoreDefinition& score : Scores()) {
    const std::size_t c = ColumnOf(results, std::string(score.name));
    if (c < row.size()) {
      if (const auto* v = std::get_if<double>(&row[c])) p.scores.Set(score.name, *v);
    }
  }
  return p;
}

// The outcome of a stored row: "passes", "fails thresholds", or its status when it did not run
// to the end (views/map_grid.h).
std::string OutcomeOf(const Table& results, const std::vector<TableCell>& row,
                      const CriteriaOptions& thresholds) {
  return OutcomeCategories()[OutcomeCategoryOf(Judged(results, row), thresholds)].label;
}

// Points by status and outcome, counted from the stored rows: a run that ended ok still fails
// when a score misses its threshold.
Table Outcomes(const Table& results, const CriteriaOptions& thresholds) {
  std::map<std::pair<std::string, std::string>, std::int64_t> counts;
  for (const auto& row : results.rows) {
    ++counts[{CellText(row[ColumnOf(results, "status")]), OutcomeOf(results, row, thresholds)}];
  }
  Table out;
  out.columns = {"status", "outcome", "points"};
  for (const auto& [key, n] : counts) out.rows.push_back({key.first, key.second, n});
  return out;
}

// "0 of 16 points pass Err <= 0.1, SRf >= 0.8; 16 ran to the end and fail them (16 by Err)".
std::string OutcomeSentence(const Table& results, const CriteriaOptions& thresholds) {
  int passing = 0, failing = 0, other = 0;
  std::map<std::string, int> failing_by;  // By score label.
  for (const auto& row : results.rows) {
    const ScoredPoint p = Judged(results, row);
    if (p.status != RunStatus::kOk) {
      ++other;
    } else if (thresholds.Passes(p)) {
      ++passing;
    } else {
      ++failing;
      for (const auto& [name, threshold] : thresholds.thresholds) {
        const ScoreDefinition* score = FindScore(name);
        const std::optional<double> v = p.scores[name];
        if (v ? !score->Meets(*v, threshold) : score->required) {
          ++failing_by[std::string(score->label)];
        }
      }
    }
  }
  std::string by;
  for (const auto& [label, n] : failing_by) {
    by += fmt::format("{}{} by {}", by.empty() ? "" : ", ", n, label);
  }
  return fmt::format(
      "<p class=\"verdict\" id=\"verdict-text\">{} of {} pass {}; {} ran to the end and fail "
      "them{}; {} did not run to the end.</p>\n",
      passing, Counted(static_cast<long long>(results.rows.size()), "point"),
      HtmlEscaped(ThresholdsText(thresholds, false)), failing,
      by.empty() ? "" : " (" + HtmlEscaped(by) + ")", other);
}

// The swept paths, in the study's order.
std::vector<std::string> SweptPaths(const SceneStudySpec& spec) {
  std::vector<std::string> paths;
  if (!spec.points.empty()) {
    for (const auto& [path, value] : spec.points.front()) paths.push_back(path);
  }
  return paths;
}

// Each stored point with the swept values its parameters_json holds (a missing or non-numeric
// one is left out, and the map says so).
std::vector<SweepPoint> SweepPoints(const SceneStudySpec& spec, const Table& results) {
  std::vector<SweepPoint> points;
  for (const auto& row : results.rows) {
    SweepPoint& p = points.emplace_back();
    p.scored = Judged(results, row);
    if (const auto* id = std::get_if<std::int64_t>(&row[ColumnOf(results, "point_id")])) {
      p.scored.point_id = *id;
    }
    const auto parameters =
        nlohmann::json::parse(CellText(row[ColumnOf(results, "parameters_json")]), nullptr, false);
    for (const std::string& path : SweptPaths(spec)) {
      if (parameters.is_object() && parameters.contains(path) && parameters[path].is_number()) {
        p.parameters.emplace_back(path, parameters[path].get<double>());
      }
    }
  }
  return points;
}

std::string ValidityMap(const SceneStudySpec& spec, const Table& results,
                        const CriteriaOptions& thresholds) {
  const std::string maps =
      HtmlSweepOutcomeMaps(SweepPoints(spec, results), thresholds, "sweep-map");
  if (maps.empty()) return "<p>The study sweeps no parameter.</p>\n";
  return fmt::format(
             "<p>Every point over the swept settings, coloured by its outcome against {}; hover "
             "a cell for its values.</p>\n",
             HtmlEscaped(ThresholdsText(thresholds, false))) +
         maps;
}

// The points with each swept parameter as its own column (from parameters_json), then their
// scores and costs.
Table PointsWithParameters(const SceneStudySpec& spec, const Table& results,
                           const CriteriaOptions& thresholds) {
  std::vector<std::string> shown = {"status"};
  for (const ScoreDefinition& score : Scores()) shown.emplace_back(score.name);
  for (const char* name : {"dt_used_s", "steps", "wall_s", "max_energy_ratio", "largest_force_n",
                           "largest_force_zone", "n_shocks", "first_shock_peak_n", "message"}) {
    shown.emplace_back(name);
  }
  const std::vector<std::string> paths = SweptPaths(spec);
  Table out;
  out.columns.push_back("point_id");
  out.columns.insert(out.columns.end(), paths.begin(), paths.end());
  out.columns.push_back("outcome");
  out.columns.insert(out.columns.end(), shown.begin(), shown.end());
  for (const auto& row : results.rows) {
    auto& cells = out.rows.emplace_back();
    cells.push_back(row[ColumnOf(results, "point_id")]);
    const auto parameters =
        nlohmann::json::parse(CellText(row[ColumnOf(results, "parameters_json")]), nullptr, false);
    for (const std::string& path : paths) {
      TableCell value;  // NULL unless the point sets the parameter.
      if (parameters.is_object() && parameters.contains(path) && parameters[path].is_number()) {
        value = parameters[path].get<double>();
      }
      cells.push_back(value);
    }
    cells.emplace_back(std::in_place_type<std::string>, OutcomeOf(results, row, thresholds));
    for (const std::string& name : shown) {
      const std::size_t c = ColumnOf(results, name);
      cells.push_back(c < row.size() ? row[c] : TableCell());
    }
  }
  return out;
}

std::string ForceMaps(const ReportContext& ctx, const std::vector<SceneForceMap>& maps) {
  if (maps.empty()) return "<p>No contact-force map was drawn.</p>\n";
  std::string html =
      "<p>The largest contact force of every zone over the run (paper Fig. 5b), at the "
      "settings each point is scored against (the study's reference).</p>\n";
  for (const SceneForceMap& m : maps) {
    html += EmbeddedFigure(m.png, m.label, PlotFiles(m.png, ctx.dir));
  }
  return html;
}

}  // namespace

std::vector<ReportSection> SceneSections(const ReportContext& ctx, const SceneStudySpec& spec,
                                         const std::vector<SceneForceMap>& maps) {
  const Table results = StudyResultRows(ctx.database_path, ctx.study, kScenePoints);
  if (results.rows.empty()) {
    throw InputError("study \"" + ctx.study + "\" has no stored point to report on");
  }
  const ReportTables tables = LoadReportTables(ctx.database_path, ctx.study);
  const std::string about = fmt::format(
      "<p>{}</p><p>Each point is the scene <code>{}</code> with the swept parameters set, scored "
      "against the same scene at {}: Err on the displacement <code>{}</code>, SRf on the first "
      "shock of zone <code>{}</code>, over {:g} s.</p>\n",
      HtmlEscaped(spec.description), HtmlEscaped(spec.scene_file),
      HtmlEscaped(ParametersJson(spec.reference)), HtmlEscaped(spec.scoring.displacement),
      HtmlEscaped(spec.scoring.zone), spec.scoring.window_s);
  return {
      {"outcomes", "Outcomes",
       OutcomeSentence(results, ctx.thresholds) + about +
           SortableTable(Outcomes(results, ctx.thresholds), "outcomes-table",
                         "Points by status and outcome")},
      {"validity-map", "Validity map", ValidityMap(spec, results, ctx.thresholds)},
      {"points", "Points",
       SortableTable(PointsWithParameters(spec, results, ctx.thresholds), "points-table",
                     "Every stored point, its swept parameters as columns")},
      {"contact-forces", "Contact-force maps", ForceMaps(ctx, maps)},
      {"provenance", "Provenance",
       SortableTable(tables.provenance, "provenance-table", "Runs of the study")},
      {"study-file", "Study file", Preformatted(tables.spec_json)},
  };
}

}  // namespace shockmap

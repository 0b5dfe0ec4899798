// The report's sections for a scene study (declared in views/html_report.h).

#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "db/report_queries.h"
#include "views/html_report.h"
#include "views/html_text.h"

namespace shockmap {
namespace {

std::size_t ColumnOf(const Table& r, const std::string& name) {
  return static_cast<std::size_t>(std::ranges::find(r.columns, name) - r.columns.begin());
}

// Points by status, counted from the stored rows.
Table Outcomes(const Table& results) {
  std::map<std::string, std::int64_t> counts;
  for (const auto& row : results.rows) ++counts[CellText(row[ColumnOf(results, "status")])];
  Table out;
  out.columns = {"status", "points"};
  for (const auto& [status, n] : counts) out.rows.push_back({status, n});
  return out;
}

// The points with each swept parameter as its own column (from parameters_json), then their
// scores and costs.
Table PointsWithParameters(const SceneStudySpec& spec, const Table& results) {
  std::vector<std::string> shown = {"status"};
  for (const ScoreDefinition& score : Scores()) shown.emplace_back(score.name);
  for (const char* name : {"dt_used_s", "steps", "wall_s", "max_energy_ratio", "largest_force_n",
                           "largest_force_zone", "n_shocks", "first_shock_peak_n", "message"}) {
    shown.emplace_back(name);
  }
  std::vector<std::string> paths;
  if (!spec.points.empty()) {
    for (const auto& [path, value] : spec.points.front()) paths.push_back(path);
  }
  Table out;
  out.columns.push_back("point_id");
  out.columns.insert(out.columns.end(), paths.begin(), paths.end());
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
       about + SortableTable(Outcomes(results), "outcomes-table", "Points by status")},
      {"points", "Points",
       "<div class=\"scroll\">" +
           SortableTable(PointsWithParameters(spec, results), "points-table",
                         "Every stored point, its swept parameters as columns") +
           "</div>\n"},
      {"contact-forces", "Contact-force maps", ForceMaps(ctx, maps)},
      {"provenance", "Provenance",
       SortableTable(tables.provenance, "provenance-table", "Runs of the study")},
      {"study-file", "Study file", Preformatted(tables.spec_json)},
  };
}

}  // namespace shockmap

#include "db/result_views.h"

#include <algorithm>
#include <cctype>
#include <iterator>

#include "db/point_tables.h"
#include "records/canonical_records.h"
#include "records/ensemble_records.h"
#include "records/scene_records.h"

namespace shockmap {
namespace {

// The paper's problem: a point's parameters and status, its scores, its reference's convergence
// and cost, the run that computed it.
ResultView Results() {
  return {"results",
          1,
          {"st.name AS study",
           "p.point_id",
           "p.r_k",
           "p.r_ftrunc",
           "p.scheme",
           "p.dt_rule",
           "p.dt_factor",
           "p.dt_asked_s",
           "p.window_s",
           "p.mass_damping_per_s",
           "p.status",
           "p.message",
           "sc.err",
           "sc.srf",
           "sc.n_modes",
           "sc.n_elements",
           "sc.n_dofs",
           "sc.dt_requested_s",
           "sc.dt_used_s",
           "sc.dt_paper_s",
           "sc.dt_sharp_s",
           "sc.steps",
           "sc.wall_s",
           "sc.cpu_s",
           "sc.max_energy_ratio",
           "sc.n_shocks",
           "sc.first_shock_start_s",
           "sc.first_shock_impulse_n_s",
           "sc.first_shock_peak_n",
           "sc.first_shock_duration_s",
           "sc.first_shock_rebounds",
           "r.r_fref",
           "r.r_fref_check",
           "r.convergence AS ref_convergence",
           "r.n_transitions AS ref_transitions",
           "r.wall_s AS ref_wall_s",
           "ru.code_version",
           "p.host",
           "p.rank",
           "p.updated_utc",
           "sc.srf_definition",
           "sc.pfr",
           "sc.spread_runs",
           "sc.err_spread_low",
           "sc.err_spread_high",
           "sc.srf_spread_low",
           "sc.srf_spread_high",
           "sc.pfr_spread_low",
           "sc.pfr_spread_high",
           "r.estimate_tip AS ref_estimate_tip",
           "r.estimate_impulse AS ref_estimate_impulse",
           "r.estimate_err AS ref_estimate_err"},
          {{"p", ColumnNames(kPointParameterColumns), {"n_elements_asked"}, ""},
           {"sc", ColumnNames(kScoreColumns), {"reference_id", "shocks_json"}, ""},
           {"r",
            ColumnNames(kReferenceColumns),
            {"reference_key", "r_k", "window_s", "n_modes_free", "n_modes_contact", "output_dt_s",
             "tip_m", "force_n", "shocks_json"},
            "ref_"}},
          "points p\n"
          "JOIN studies st ON st.study_id = p.study_id\n"
          "LEFT JOIN scores sc ON sc.point_id = p.point_id\n"
          "LEFT JOIN reference_runs r ON r.reference_id = sc.reference_id\n"
          "LEFT JOIN runs ru ON ru.run_id = p.run_id"};
}

// Scene sweeps: a point's parameters, status and scores (one table), its reference's parameters
// and cost, the run that computed it.
ResultView SceneResults() {
  std::vector<std::string> point_columns = ColumnNames(kScenePointParameterColumns);
  std::ranges::copy(ColumnNames(kSceneScoreColumns), std::back_inserter(point_columns));
  return {"scene_results",
          2,
          {"st.name AS study",
           "p.point_id",
           "p.parameters_json",
           "p.status",
           "p.message",
           "p.err",
           "p.srf",
           "p.coordinates",
           "p.zones",
           "p.dt_used_s",
           "p.dt_paper_s",
           "p.dt_sharp_s",
           "p.steps",
           "p.wall_s",
           "p.cpu_s",
           "p.max_energy_ratio",
           "p.largest_force_n",
           "p.largest_force_zone",
           "p.n_shocks",
           "p.first_shock_peak_n",
           "p.first_shock_impulse_n_s",
           "r.parameters_json AS reference_parameters_json",
           "r.wall_s AS ref_wall_s",
           "ru.code_version",
           "p.host",
           "p.rank",
           "p.updated_utc",
           "p.pfr"},
          {{"p", point_columns, {"reference_id"}, ""},
           {"r",
            ColumnNames(kSceneReferenceColumns),
            {"reference_key", "status", "message", "output_dt_s", "displacement_m", "force_n",
             "steps", "max_energy_ratio"},
            "ref_"}},
          "scene_points p\n"
          "JOIN studies st ON st.study_id = p.study_id\n"
          "LEFT JOIN scene_references r ON r.reference_id = p.reference_id\n"
          "LEFT JOIN runs ru ON ru.run_id = p.run_id"};
}

// Ensembles: a member's state, setting, index, status and cost, its largest force over its zones,
// the run that computed it.
ResultView EnsembleResults() {
  std::vector<std::string> member_columns = ColumnNames(kEnsembleMemberParameterColumns);
  std::ranges::copy(ColumnNames(kEnsembleMemberColumns), std::back_inserter(member_columns));
  return {"ensemble_results",
          8,
          {"st.name AS study", "p.point_id", "p.state", "p.setting_json", "p.member", "p.status",
           "p.message", "p.member_seed", "p.coordinates", "p.dt_used_s", "p.steps", "p.wall_s",
           "p.cpu_s", "p.max_energy_ratio",
           "(SELECT max(z.max_force_n) FROM ensemble_member_zones z WHERE z.point_id = "
           "p.point_id) AS largest_force_n",
           "ru.code_version", "p.host", "p.rank", "p.updated_utc"},
          {{"p", member_columns, {"reference_id"}, ""}},
          "ensemble_members p\n"
          "JOIN studies st ON st.study_id = p.study_id\n"
          "LEFT JOIN runs ru ON ru.run_id = p.run_id"};
}

// The expression of a view's column: "r.wall_s" of "r.wall_s AS ref_wall_s".
std::string_view ExpressionOf(std::string_view column) {
  const std::size_t as = column.rfind(" AS ");
  return as == std::string_view::npos ? column : column.substr(0, as);
}

}  // namespace

std::span<const ResultView> ResultViews() {
  static const std::vector<ResultView> views{Results(), SceneResults(), EnsembleResults()};
  return views;
}

std::vector<std::string> ViewColumns(const ResultView& view) {
  std::vector<std::string> columns(view.shown.begin(), view.shown.end());
  const std::size_t shown = columns.size();
  for (const ViewSource& source : view.sources) {
    for (const std::string& column : source.columns) {
      const std::string expression = std::string(source.alias) + "." + column;
      const bool listed =
          std::ranges::any_of(columns.begin(), columns.begin() + shown,
                              [&](const std::string& c) { return ExpressionOf(c) == expression; });
      if (listed || std::ranges::count(source.left_out, column) > 0) continue;
      columns.push_back(source.prefix.empty()
                            ? expression
                            : expression + " AS " + std::string(source.prefix) + column);
    }
  }
  return columns;
}

std::string CreateViewSql(const ResultView& view) {
  std::string select;
  for (const std::string& column : ViewColumns(view)) {
    select += (select.empty() ? "" : ", ") + column;
  }
  return "CREATE VIEW " + std::string(view.name) + " AS\nSELECT " + select + "\nFROM " +
         std::string(view.joins);
}

std::string WithoutLayout(std::string_view sql) {
  std::string text;
  bool space = false;
  for (char c : sql) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      space = true;
      continue;
    }
    if (space && !text.empty()) text += ' ';
    space = false;
    text += c;
  }
  return text;
}

void DropDeclaredViews(Connection& c) {
  for (const PointTable* table : PointTables()) {
    if (table->parameter_view) {
      c.Execute("DROP VIEW IF EXISTS " + std::string(table->parameter_view->name));
    }
  }
  for (const ResultView& view : ResultViews()) {
    c.Execute("DROP VIEW IF EXISTS " + std::string(view.name));
  }
}

void CreateDeclaredViews(Connection& c) {
  for (const ResultView& view : ResultViews()) c.Execute(CreateViewSql(view));
  for (const PointTable* table : PointTables()) RefreshParameterView(c, *table);
}

}  // namespace shockmap

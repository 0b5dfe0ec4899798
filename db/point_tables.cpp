#include "db/point_tables.h"

#include <array>

#include "records/canonical_records.h"
#include "records/ensemble_records.h"
#include "records/scene_records.h"

namespace shockmap {

const PointTable kCanonicalPoints{"points",  "canonical", ColumnNames(kPointParameterColumns),
                                  "results", {},          std::nullopt};

const PointTable kScenePoints{"scene_points",
                              "scene_sweep",
                              ColumnNames(kScenePointParameterColumns),
                              "scene_results",
                              {},
                              ParameterView{"scene_params", "parameters_json", 6}};

const PointTable kEnsembleMembers{
    "ensemble_members", "scene_ensemble",          ColumnNames(kEnsembleMemberParameterColumns),
    "ensemble_results", {"state", "setting_json"}, std::nullopt};

std::span<const PointTable* const> PointTables() {
  static const std::array<const PointTable*, 3> tables{&kCanonicalPoints, &kScenePoints,
                                                       &kEnsembleMembers};
  return tables;
}

namespace {

// `text` with every `quote` doubled, between two of them: an SQL literal (') or identifier (").
std::string Quoted(const std::string& text, char quote) {
  std::string s(1, quote);
  for (char c : text) s += c == quote ? std::string(2, c) : std::string(1, c);
  return s + quote;
}

}  // namespace

std::string ParameterViewSql(Connection& c, const PointTable& table) {
  const ParameterView& view = *table.parameter_view;
  const std::string json = std::string(view.json_column);
  std::string columns;
  Statement paths = c.Prepare("SELECT DISTINCT j.key FROM " + std::string(table.name) +
                              " p, json_each(p." + json + ") j ORDER BY j.key");
  while (paths.Step()) {
    const std::string path = paths.GetText(0);
    columns += ", json_extract(r." + json + ", " + Quoted("$.\"" + path + "\"", '\'') + ") AS " +
               Quoted("params_" + path, '"');
  }
  return "CREATE VIEW " + std::string(view.name) + " AS SELECT r.*" + columns + " FROM " +
         std::string(table.results_view) + " r";
}

void RefreshParameterView(Connection& c, const PointTable& table) {
  if (!table.parameter_view) return;
  c.Execute("DROP VIEW IF EXISTS " + std::string(table.parameter_view->name));
  c.Execute(ParameterViewSql(c, table));
}

}  // namespace shockmap

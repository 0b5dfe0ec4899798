#pragma once
// The registry of study kinds' tables: for each kind of study, the table of its points, its
// view of results and how `study status` breaks its points down. Whatever concerns every kind
// (the study engine's point lifecycle, `study status`, where points were computed, the views
// written again as points arrive, the report's rows) iterates PointTables() instead of naming a
// kind's table; a new kind of study adds its entry in db/point_tables.cpp.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "db/sqlite_handle.h"

namespace shockmap {

// A view whose columns follow the data: `name` is the kind's results view with one more column
// params_<path> per path of the JSON objects of `json_column` over every stored point (as
// Optuna's params_*; NULL where a point has no such path). Written again whenever points are
// added.
struct ParameterView {
  std::string_view name;
  std::string_view json_column;
  int since = 0;  // The schema version that added it.
};

// A table of study points. Its lifecycle columns are the same for every kind: point_id,
// study_id, point_key, reference_key, status, message, run_id, updated_utc, host, rank. The
// parameter columns are the kind's (its parameter record's column table), bound in this order.
struct PointTable {
  std::string_view name;
  std::string_view kind;  // The study file's "kind" (specs/study_file.h).
  std::vector<std::string> parameter_columns;
  std::string_view results_view;  // One row per point, with its study's name (column study).
  // Parameter columns `study status` also counts the points by (ensemble members by clearance
  // state and setting); none for a kind whose points a study's totals describe.
  std::vector<std::string_view> progress_by;
  std::optional<ParameterView> parameter_view;
};

extern const PointTable kCanonicalPoints;  // Studies of the paper's problem.
extern const PointTable kScenePoints;      // Scene sweeps.
extern const PointTable kEnsembleMembers;  // Ensembles of a scene.

// Every kind's table, in the order the kinds were added.
std::span<const PointTable* const> PointTables();

// Writes the table's parameter view again, with the paths of the points stored now (nothing
// for a table without one).
void RefreshParameterView(Connection& c, const PointTable& table);
// The CREATE VIEW statement RefreshParameterView runs for the points stored now.
std::string ParameterViewSql(Connection& c, const PointTable& table);

}  // namespace shockmap

#pragma once
// The points and references of scene studies in the study database (schema version 2): written
// by the one StudyDatabase writer, one transaction per call.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/study_database.h"

namespace shockmap {

// The points table of scene studies; its one parameter column holds the point's parameters as
// JSON ({"solver.r_ftrunc": 30, ...}).
extern const PointTable kScenePoints;

struct SceneScoreRow {
  std::int64_t reference_id = 0;
  std::optional<double> err, srf;
  int coordinates = 0, zones = 0;
  double dt_used_s = 0.0, dt_paper_s = 0.0, dt_sharp_s = 0.0;
  std::int64_t steps = 0;
  double wall_s = 0.0, cpu_s = 0.0, max_energy_ratio = 0.0;
  double largest_force_n = 0.0;
  std::string largest_force_zone;
  int n_shocks = 0;  // Of the scored zone.
  std::optional<double> first_shock_peak_n, first_shock_impulse_n_s;
};

// Writes the view scene_params again: scene_results with one column params_<path> per
// parameter path of any scene study (json_extract of parameters_json; NULL where a study does
// not sweep it), in the order of the paths.
void RefreshSceneParamsView(Connection& c);
// The CREATE VIEW statement RefreshSceneParamsView runs for the points stored now.
std::string SceneParamsViewSql(Connection& c);

struct SceneReferenceRow {
  std::int64_t reference_id = 0;
  std::string reference_key, parameters_json, status, message;
  double output_dt_s = 0.0;
  std::vector<double> displacement_m, force_n;  // The scored point and zone, from t = 0.
  std::int64_t steps = 0;
  double wall_s = 0.0, max_energy_ratio = 0.0;
};

// Sets the point's score columns from `score` (NULL when it was not computed), on the writer's
// connection inside StorePointOutcome's transaction.
void WriteScore(Connection& c, std::int64_t point_id, const std::optional<SceneScoreRow>& score);
std::optional<SceneReferenceRow> FindSceneReference(StudyDatabase& db, const std::string& key);
// Stores a new reference and returns its id.
std::int64_t StoreSceneReference(StudyDatabase& db, const SceneReferenceRow& reference,
                                 std::int64_t run_id);

}  // namespace shockmap

#pragma once
// The stored records of scene studies: a point's parameters and scores (table scene_points, the
// scores NULL until it is computed) and the refined runs it is scored against (table
// scene_references), each with its column table (records/columns.h).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "records/columns.h"

namespace shockmap {

struct ScenePointParameters {
  std::string parameters_json;  // {"solver.r_ftrunc": 30, ...}
};

inline constexpr Column<ScenePointParameters> kScenePointParameterColumns[] = {
    {"parameters_json", &ScenePointParameters::parameters_json, "",
     "the swept values by path, `{\"solver.r_ftrunc\": 30.0, ...}`"},
};

// Each score of the registry (validation/scores.h) that scene studies carry is an optional real
// column named after it.
struct SceneScoreRow {
  std::int64_t reference_id = 0;
  std::optional<double> err, srf, pfr;
  int coordinates = 0, zones = 0;
  double dt_used_s = 0.0, dt_paper_s = 0.0, dt_sharp_s = 0.0;
  std::int64_t steps = 0;
  double wall_s = 0.0, cpu_s = 0.0, max_energy_ratio = 0.0;
  double largest_force_n = 0.0;
  std::string largest_force_zone;
  int n_shocks = 0;  // Of the scored zone.
  std::optional<double> first_shock_peak_n, first_shock_impulse_n_s;
};

inline constexpr Column<SceneScoreRow> kSceneScoreColumns[] = {
    {"reference_id", &SceneScoreRow::reference_id, "",
     "the row of `scene_references` it was scored against"},
    {"err", &SceneScoreRow::err, "", "Err (eq. 8) on the scored displacement",
     ValueRange::kFraction},
    {"srf", &SceneScoreRow::srf, "", "SRf (eq. 9) on the scored zone", ValueRange::kFraction},
    {"pfr", &SceneScoreRow::pfr, "",
     "peak-force ratio of the scored zone's first shock (NULL before schema 10)",
     ValueRange::kFraction},
    {"coordinates", &SceneScoreRow::coordinates, "", "modal coordinates of the model",
     ValueRange::kNonNegative},
    {"zones", &SceneScoreRow::zones, "", "contact zones of the model", ValueRange::kNonNegative},
    {"dt_used_s", &SceneScoreRow::dt_used_s, "s", "time step used", ValueRange::kNonNegative},
    {"dt_paper_s", &SceneScoreRow::dt_paper_s, "s", "the bound 1/(4 f_trunc)",
     ValueRange::kNonNegative},
    {"dt_sharp_s", &SceneScoreRow::dt_sharp_s, "s", "the bound 2/ω_max", ValueRange::kNonNegative},
    {"steps", &SceneScoreRow::steps, "", "time steps taken", ValueRange::kNonNegative},
    {"wall_s", &SceneScoreRow::wall_s, "s", "wall time of the run", ValueRange::kNonNegative},
    {"cpu_s", &SceneScoreRow::cpu_s, "s", "CPU time of the run", ValueRange::kNonNegative},
    {"max_energy_ratio", &SceneScoreRow::max_energy_ratio, "",
     "largest total energy over the initial energy"},
    {"largest_force_n", &SceneScoreRow::largest_force_n, "N",
     "the largest contact force over every zone", ValueRange::kNonNegative},
    {"largest_force_zone", &SceneScoreRow::largest_force_zone, "", "the zone where it occurred"},
    {"n_shocks", &SceneScoreRow::n_shocks, "", "shocks of the scored zone",
     ValueRange::kNonNegative},
    {"first_shock_peak_n", &SceneScoreRow::first_shock_peak_n, "N",
     "the peak force of its first shock", ValueRange::kNonNegative},
    {"first_shock_impulse_n_s", &SceneScoreRow::first_shock_impulse_n_s, "N s",
     "the impulse of its first shock", ValueRange::kNonNegative},
};

// The same scene run with the study's reference settings.
struct SceneReferenceRow {
  std::int64_t reference_id = 0;  // Its key in the database, given when it is stored.
  std::string reference_key, parameters_json, status, message;
  double output_dt_s = 0.0;
  std::vector<double> displacement_m, force_n;  // The scored point and zone, from t = 0.
  std::int64_t steps = 0;
  double wall_s = 0.0, max_energy_ratio = 0.0;
};

inline constexpr Column<SceneReferenceRow> kSceneReferenceColumns[] = {
    {"reference_key", &SceneReferenceRow::reference_key, "",
     "the scene, scoring and parameters as JSON, unique"},
    {"parameters_json", &SceneReferenceRow::parameters_json, "",
     "the point's parameters with the study's `reference` settings over them"},
    {"status", &SceneReferenceRow::status, "", "its run status"},
    {"message", &SceneReferenceRow::message, "", "why it failed or diverged"},
    {"output_dt_s", &SceneReferenceRow::output_dt_s, "s",
     "the sampling step of the two signals below", ValueRange::kNonNegative},
    {"displacement_m", &SceneReferenceRow::displacement_m, "m",
     "**blob**: the scored displacement output"},
    {"force_n", &SceneReferenceRow::force_n, "N", "**blob**: the scored zone's contact force"},
    {"steps", &SceneReferenceRow::steps, "", "time steps taken", ValueRange::kNonNegative},
    {"wall_s", &SceneReferenceRow::wall_s, "s", "wall time of the run", ValueRange::kNonNegative},
    {"max_energy_ratio", &SceneReferenceRow::max_energy_ratio, "",
     "largest total energy over the initial energy"},
};

}  // namespace shockmap

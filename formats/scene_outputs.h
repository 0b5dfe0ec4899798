#pragma once
// What `shockmap simulate` writes: the summary of a scene run as JSON, and the requested
// histories and per-zone statistics as CSV files. Nothing unrequested is written.

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/output_columns.h"
#include "compare/scene_run.h"

namespace shockmap {

// One zone's impact statistics: the columns of impact_statistics.csv (kImpactStatisticsColumns,
// none as null), but the window as one pair window_s and the wear volume only where the scene
// has a wear law; wear_available and impacts_listed beside them.
nlohmann::json ImpactStatisticsToJson(const ZoneImpactStatistics& zone);

// A member per column of kSceneRunColumns (compare/output_columns.h: status, time step and
// bounds, model size, timings), then the wear law and the power laws' bound at
// the penetrations reached when the scene has them, and per zone the maximum force, shock
// statistics and impact statistics (with the wear volume) when they were requested.
nlohmann::json SceneRunToJson(const Scene& scene, const SceneRun& run);

// Writes into `dir` (created): summary.json always; displacements.csv (t_s, then each observed
// point's displacement and velocity), contact_forces.csv (t_s, one column per zone),
// energies.csv, max_contact_force.csv (one row per zone with its location), shocks.csv (one
// row per shock), impact_statistics.csv (one row per zone, with its wear volume when the scene
// states a wear law) and impacts.csv (one row per impact of the zones listed) when requested.
// Returns the files written. Throws InputError naming a file that cannot be written.
std::vector<std::filesystem::path> WriteSceneOutputs(const Scene& scene, const SceneRun& run,
                                                     const std::filesystem::path& dir);

}  // namespace shockmap

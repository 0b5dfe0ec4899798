#include "compare/scene_scoring.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "compare/output_columns.h"
#include "compare/score_columns.h"

namespace shockmap {
namespace {

// Cost, bounds and the largest force of a run; the first shock of the scored zone. The columns
// `simulate`'s summary also writes (the model's size, the step's bounds, the step count, the
// times, the energy ratio) come from kSceneRunColumns.
SceneScoreRow Measure(const Scene& scene, const SceneRun& run) {
  SceneScoreRow score;
  SetColumnsFromOutputs(score, kSceneScoreColumns, SceneRunOutput{scene, run}, kSceneRunColumns);
  score.dt_used_s = run.result.summary.dt_used_s;
  const auto largest =
      std::max_element(run.max_contact_force_n.begin(), run.max_contact_force_n.end());
  score.largest_force_n = *largest;
  score.largest_force_zone =
      scene.zones[static_cast<std::size_t>(largest - run.max_contact_force_n.begin())].name;
  const auto& shocks = run.shocks[0];
  score.n_shocks = static_cast<int>(shocks.size());
  if (!shocks.empty()) {
    score.first_shock_peak_n = shocks.front().peak_force_n;
    score.first_shock_impulse_n_s = shocks.front().impulse_n_s;
  }
  return score;
}

}  // namespace

SceneScore ScoreSceneRun(const Scene& scene, const SceneRun& run,
                         const SceneReferenceRow& reference, const SceneScoringOptions& options) {
  const RunSummary& s = run.result.summary;
  SceneScore out{s.status, s.message, Measure(scene, run)};
  if (s.status == RunStatus::kOk && options.window_s < s.dt_requested_s) {
    out.status = RunStatus::kFailed;
    out.message =
        fmt::format("the window {:g} s is shorter than one time step ({:g} s): nothing to score",
                    options.window_s, s.dt_requested_s);
  } else if (s.status == RunStatus::kOk) {
    const UniformSignal reference_displacement{0.0, reference.output_dt_s,
                                               reference.displacement_m};
    const UniformSignal reference_force{0.0, reference.output_dt_s, reference.force_n};
    ShockSegmentationOptions segmentation;
    segmentation.rest_duration_s = options.rest_duration_s;
    const std::vector<Shock> reference_shocks =
        SegmentShocks(reference_force, segmentation, std::numeric_limits<double>::infinity());
    const UniformSignal& displacement = run.result.displacement_m[0];
    SetScoreColumns(
        out.row, kSceneScoreColumns,
        ComputeScores({.displacement = displacement,
                       .reference_displacement = reference_displacement,
                       .end_s = std::min(displacement.EndTime(), reference_displacement.EndTime()),
                       .force = run.result.contact_force_n[0],
                       .shocks = run.shocks[0],
                       .reference_force = reference_force,
                       .reference_shocks = reference_shocks,
                       .segmentation = segmentation}));
  }
  return out;
}

std::vector<EnsembleZoneRow> MemberZoneRows(const Scene& scene, const SceneRun& run) {
  std::vector<EnsembleZoneRow> zones(run.max_contact_force_n.size());
  for (std::size_t i = 0; i < zones.size(); ++i) {
    // The run's largest force over its whole time, where the statistics' is over their window.
    zones[i].max_force_n = run.max_contact_force_n[i];
    if (i >= run.impact_statistics.size()) continue;
    SetColumnsFromOutputs(zones[i], kEnsembleZoneColumns,
                          ZoneImpactStatistics{run.impact_statistics[i], scene.wear},
                          kImpactStatisticsColumns, {"max_force_n"});
  }
  return zones;
}

std::vector<EnsembleImpactRow> MemberImpactRows(const Scene& scene, const SceneRun& run) {
  std::vector<EnsembleImpactRow> rows;
  if (run.impact_statistics.empty()) return rows;
  for (const int zone : scene.outputs.impact_table_zones) {
    const auto& records = run.impact_statistics[static_cast<std::size_t>(zone)].records;
    for (std::size_t k = 0; k < records.size(); ++k) {
      EnsembleImpactRow& row = rows.emplace_back();
      row.zone = zone;
      row.impact = static_cast<std::int64_t>(k) + 1;
      SetColumnsFromOutputs(row, kEnsembleImpactColumns, records[k], kImpactRecordColumns);
    }
  }
  return rows;
}

}  // namespace shockmap

#include "compare/scene_scoring.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "compare/score_columns.h"

namespace shockmap {
namespace {

// Cost, bounds and the largest force of a run; the first shock of the scored zone.
SceneScoreRow Measure(const Scene& scene, const SceneRun& run) {
  const RunSummary& s = run.result.summary;
  SceneScoreRow score;
  score.coordinates = run.coordinates;
  score.zones = static_cast<int>(scene.zones.size());
  score.dt_used_s = s.dt_used_s;
  score.dt_paper_s = run.bounds.dt_paper_s;
  score.dt_sharp_s = run.bounds.dt_sharp_s;
  score.steps = s.steps_taken;
  score.wall_s = s.wall_s;
  score.cpu_s = s.cpu_s;
  score.max_energy_ratio = s.max_energy_ratio;
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
    EnsembleZoneRow& z = zones[i];
    z.max_force_n = run.max_contact_force_n[i];
    if (i >= run.impact_statistics.size()) continue;
    const ImpactStatistics& s = run.impact_statistics[i];
    z.impacts = s.impacts;
    z.impacts_per_s = s.impacts_per_s;
    z.rebounds_per_impact = s.rebounds_per_impact;
    z.mean_impact_duration_s = s.mean_impact_duration_s;
    z.longest_impact_duration_s = s.longest_impact_duration_s;
    z.contact_time_fraction = s.contact_time_fraction;
    z.mean_force_n = s.mean_force_n;
    z.mean_force_in_contact_n = s.mean_force_in_contact_n;
    z.rms_force_n = s.rms_force_n;
    z.impulse_n_s = s.impulse_n_s;
    if (s.wear_available) z.wear_work_rate_w = s.wear_work_rate_w;
    if (scene.wear && s.wear_available)
      z.wear_volume_m3 = ArchardWearVolume(*scene.wear, s.wear_work_rate_w);
    if (std::isfinite(s.friction_power_w)) z.friction_power_w = s.friction_power_w;
  }
  return zones;
}

std::vector<EnsembleImpactRow> MemberImpactRows(const Scene& scene, const SceneRun& run) {
  std::vector<EnsembleImpactRow> rows;
  if (run.impact_statistics.empty()) return rows;
  for (const int zone : scene.outputs.impact_table_zones) {
    const auto& records = run.impact_statistics[static_cast<std::size_t>(zone)].records;
    for (std::size_t k = 0; k < records.size(); ++k) {
      const ImpactRecord& r = records[k];
      EnsembleImpactRow& row = rows.emplace_back();
      row.zone = zone;
      row.impact = static_cast<std::int64_t>(k) + 1;
      row.start_s = r.start_s;
      row.duration_s = r.duration_s;
      row.peak_force_n = r.peak_force_n;
      row.peak_time_s = r.peak_time_s;
      row.impulse_n_s = r.impulse_n_s;
      if (std::isfinite(r.impact_speed_m_s)) row.impact_speed_m_s = r.impact_speed_m_s;
      row.rebounds = r.contacts - 1;
      row.truncated = r.truncated ? 1 : 0;
    }
  }
  return rows;
}

}  // namespace shockmap

#include "engine/scene_study_runner.h"

#include <algorithm>
#include <map>
#include <memory>
#include <thread>

#include "compare/scene_run.h"
#include "core/cpu_timer.h"
#include "db/scene_points.h"
#include "engine/progress_reporter.h"
#include "engine/provenance.h"
#include "engine/worker_pool.h"
#include "formats/json_reader.h"
#include "validation/impulse_ratio.h"
#include "validation/spectral_error.h"

namespace shockmap {
namespace {

struct PointTask {
  ScenePointRow row;
  SceneParameters parameters;
};

struct PointOutcome {
  std::int64_t point_id = 0;
  std::string status = "failed";
  std::string message;
  std::optional<SceneScoreRow> score;
};

// The reference as stored: the scored histories, whatever its status.
SceneReferenceRow ComputeReference(const SceneStudySpec& spec, const std::string& key,
                                   const SceneParameters& parameters) {
  SceneReferenceRow ref;
  ref.reference_key = key;
  ref.parameters_json = ParametersJson(parameters);
  ref.status = "failed";
  try {
    const SceneRun run = RunScene(ScoredScene(spec, parameters));
    const RunSummary& s = run.result.summary;
    ref.status = ToString(s.status);
    ref.message = s.message;
    ref.output_dt_s = run.result.displacement_m[0].dt_s;
    ref.displacement_m = run.result.displacement_m[0].values;
    ref.force_n = run.result.contact_force_n[0].values;
    ref.steps = s.steps_taken;
    ref.wall_s = s.wall_s;
    ref.max_energy_ratio = s.max_energy_ratio;
  } catch (const std::exception& e) {
    ref.message = e.what();
  }
  return ref;
}

PointOutcome ScorePoint(const SceneStudySpec& spec, const PointTask& task,
                        const SceneReferenceRow& ref) {
  PointOutcome out;
  out.point_id = task.row.point_id;
  if (ref.status != "ok") {
    out.message = "reference " + ref.status + ": " + ref.message;
    return out;
  }
  try {
    const Scene scene = ScoredScene(spec, task.parameters);
    const SceneRun run = RunScene(scene);
    const RunSummary& s = run.result.summary;
    SceneScoreRow score;
    score.reference_id = ref.reference_id;
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
    out.status = ToString(s.status);
    out.message = s.message;
    if (s.status == RunStatus::kOk) {
      const UniformSignal ref_displacement{0.0, ref.output_dt_s, ref.displacement_m};
      const UniformSignal ref_force{0.0, ref.output_dt_s, ref.force_n};
      ShockSegmentationOptions segmentation;
      segmentation.rest_duration_s = spec.scoring.rest_duration_s;
      const double end =
          std::min(run.result.displacement_m[0].EndTime(), ref_displacement.EndTime());
      score.err =
          SpectralError(run.result.displacement_m[0], ref_displacement, 0.0, end, PsdOptions{});
      score.srf = FirstShockImpulseRatio(
          shocks, SegmentShocks(ref_force, segmentation, std::numeric_limits<double>::infinity()));
    }
    out.score = score;
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void CheckSettingsUnchanged(StudyDatabase& db, const SceneStudySpec& spec) {
  const auto stored = db.StoredSpec(spec.name);
  if (!stored) return;
  const nlohmann::json previous =
      ParseJsonText(*stored, db.Raw().Path() + ": stored study " + spec.name);
  if (!IsSceneStudy(previous)) {
    throw InputError(spec.file + ": study \"" + spec.name + "\" already exists in " +
                     db.Raw().Path() +
                     " as a study of the paper's problem; give this one a new name");
  }
  if (previous.value("settings", nlohmann::json()) !=
      nlohmann::json::parse(SceneSettingsKey(spec))) {
    throw InputError(spec.file + ": study \"" + spec.name + "\" already exists in " +
                     db.Raw().Path() +
                     " with another scene, reference or scoring; its stored scores depend on them. "
                     "Give the study a new name (the sweep may change freely).");
  }
}

}  // namespace

StudyRunSummary RunSceneStudy(const SceneStudySpec& spec, const StudyRunOptions& options) {
  const CpuTimer timer;
  StudyRunSummary summary;
  summary.jobs = WorkerCount(options);
  summary.points_in_study = spec.points.size();

  StudyDatabase db(options.database_path);
  CheckSettingsUnchanged(db, spec);
  const std::int64_t study_id = db.UpsertStudy(spec.name, spec.spec_json);

  std::map<std::string, const SceneParameters*> by_key;
  std::vector<ScenePointRow> rows;
  for (const SceneParameters& p : spec.points) {
    const std::string key = ParametersJson(p);
    by_key[key] = &p;
    rows.push_back({0, key, SceneReferenceKey(spec, ReferenceParameters(spec, p)), key});
  }
  AddScenePoints(db, study_id, rows);
  const Provenance provenance = CurrentProvenance(summary.jobs);
  summary.points_reclaimed = db.ReclaimStalePoints(study_id, provenance.host, PointTable::kScene);
  std::vector<PointTask> to_compute;
  for (auto& row : ScenePointsToCompute(db, study_id, options.retry_failed)) {
    const auto it = by_key.find(row.point_key);
    if (it != by_key.end()) to_compute.push_back({std::move(row), *it->second});
  }
  const std::int64_t run_id = db.BeginRun(study_id, provenance);

  // Phase 1: references, each once per database.
  std::map<std::string, SceneReferenceRow> references;
  std::vector<std::pair<std::string, SceneParameters>> missing;
  for (const PointTask& t : to_compute) {
    const std::string& key = t.row.reference_key;
    if (references.contains(key)) continue;
    if (auto stored = FindSceneReference(db, key)) {
      references[key] = std::move(*stored);
      ++summary.references_reused;
    } else {
      references[key] = {};
      missing.emplace_back(key, ReferenceParameters(spec, t.parameters));
    }
  }
  const CpuTimer reference_timer;
  RunOnWorkers(
      missing.size(), summary.jobs,
      [&](std::size_t i) { return ComputeReference(spec, missing[i].first, missing[i].second); },
      [&](SceneReferenceRow row) {
        row.reference_id = StoreSceneReference(db, row, run_id);
        references[row.reference_key] = std::move(row);
        ++summary.references_computed;
      });
  summary.reference_wall_s = reference_timer.WallSeconds();

  // Phase 2: points; each finished point is committed on its own.
  const CpuTimer point_timer;
  std::vector<std::int64_t> ids;
  for (const auto& t : to_compute) ids.push_back(t.row.point_id);
  db.MarkRunning(ids, run_id, PointTable::kScene);
  ProgressReporter progress(static_cast<long>(to_compute.size()), stderr, options.progress);
  RunOnWorkers(
      to_compute.size(), summary.jobs,
      [&](std::size_t i) {
        const PointTask& t = to_compute[i];
        return ScorePoint(spec, t, references.at(t.row.reference_key));
      },
      [&](PointOutcome out) {
        StoreSceneResult(db, out.point_id, run_id, out.status, out.message, out.score);
        CountOutcome(out.status, summary);
        progress.Update(static_cast<long>(summary.points_computed), summary.diverged,
                        summary.failed);
      });
  progress.Finish(static_cast<long>(summary.points_computed), summary.diverged, summary.failed);
  summary.point_wall_s = point_timer.WallSeconds();
  db.EndRun(run_id);
  summary.wall_s = timer.WallSeconds();
  return summary;
}

}  // namespace shockmap

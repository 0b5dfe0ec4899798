#include "engine/study_runner.h"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/cpu_timer.h"
#include "engine/progress_reporter.h"
#include "engine/provenance.h"
#include "engine/reference_store.h"
#include "engine/worker_pool.h"
#include "formats/comparison_json.h"

namespace shockmap {
namespace {

struct ReferenceTask {
  std::string key;
  StudyPoint point;  // Any point that needs this reference.
};

struct ReferenceOutcome {
  std::string key;
  std::shared_ptr<const ReferenceRun> run;  // Null when it could not be computed.
  std::string error;
  double r_k = 0.0, window_s = 0.0;
};

struct StoredReference {
  std::int64_t id = 0;
  std::shared_ptr<const ReferenceRun> run;
  std::string error;
};

struct PointOutcome {
  std::int64_t point_id = 0;
  std::string status;
  std::string message;
  std::optional<ScoreRow> score;
};

ScoreRow ToScoreRow(const ComparisonResult& r, std::int64_t reference_id) {
  ScoreRow s;
  s.reference_id = reference_id;
  s.err = r.err;
  s.srf = r.srf;
  s.n_modes = r.n_modes;
  s.n_elements = r.n_elements;
  s.n_dofs = r.n_dofs;
  s.dt_requested_s = r.numerical.dt_requested_s;
  s.dt_used_s = r.numerical.dt_used_s;
  s.dt_paper_s = r.bounds.dt_paper_s;
  s.dt_sharp_s = r.bounds.dt_sharp_s;
  s.steps = r.numerical.steps_taken;
  s.wall_s = r.numerical.wall_s;
  s.cpu_s = r.numerical.cpu_s;
  s.max_energy_ratio = r.numerical.max_energy_ratio;
  s.n_shocks = static_cast<int>(r.shocks_numerical.size());
  nlohmann::json shocks = nlohmann::json::array();
  for (const auto& shock : r.shocks_numerical) shocks.push_back(ShockToJson(shock));
  s.shocks_json = shocks.dump();
  if (!r.shocks_numerical.empty()) {
    const Shock& f = r.shocks_numerical.front();
    s.first_shock =
        ShockColumns{f.start_s, f.impulse_n_s, f.peak_force_n, f.Duration(), f.Rebounds()};
  }
  return s;
}

void CheckSettingsUnchanged(StudyDatabase& db, const StudySpec& spec) {
  const auto stored = db.StoredSpec(spec.name);
  if (!stored) return;
  if (nlohmann::json::parse(*stored).contains("scene")) {
    throw InputError(spec.file + ": study \"" + spec.name + "\" already exists in " +
                     db.Raw().Path() + " as a scene study; give this one a new name");
  }
  const StudySpec previous = ParseStudySpec(nlohmann::json::parse(*stored), db.Raw().Path());
  if (SettingsKey(previous) != SettingsKey(spec)) {
    throw InputError(spec.file + ": study \"" + spec.name + "\" already exists in " +
                     db.Raw().Path() +
                     " with other problem or scoring settings; its stored scores depend on them. "
                     "Give the study a new name (grid axes may change freely).");
  }
}

}  // namespace

int WorkerCount(const StudyRunOptions& options) {
  return options.jobs > 0 ? options.jobs
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void CountOutcome(const std::string& status, StudyRunSummary& summary) {
  ++summary.points_computed;
  if (status == "ok") ++summary.ok;
  if (status == "diverged") ++summary.diverged;
  if (status == "failed") ++summary.failed;
  if (status == "reference_unconverged") ++summary.reference_unconverged;
}

StudyRunSummary RunStudy(const StudySpec& spec, const StudyRunOptions& options) {
  const CpuTimer timer;
  StudyRunSummary summary;
  summary.jobs = WorkerCount(options);
  summary.points_in_study = spec.points.size();

  StudyDatabase db(options.database_path);
  CheckSettingsUnchanged(db, spec);
  const std::int64_t study_id = db.UpsertStudy(spec.name, spec.spec_json);

  std::map<std::string, const StudyPoint*> by_key;
  std::vector<PointParameters> rows;
  for (const StudyPoint& p : spec.points) {
    const std::string key = PointKey(p);
    by_key[key] = &p;
    PointParameters r;
    r.point_key = key;
    r.reference_key = ReferenceKey(spec, p);
    r.r_k = p.r_k;
    r.r_ftrunc = p.r_ftrunc;
    r.scheme = ToString(p.scheme);
    if (p.dt.dt_s) {
      r.dt_asked_s = p.dt.dt_s;
    } else {
      r.dt_rule = ToString(p.dt.rule);
      r.dt_factor = p.dt.factor;
    }
    r.window_s = p.window_s;
    r.n_elements_asked = p.n_elements;
    r.mass_damping_per_s = p.mass_damping_per_s;
    rows.push_back(std::move(r));
  }
  db.AddPoints(study_id, rows);
  const Provenance provenance = CurrentProvenance(summary.jobs);
  summary.points_reclaimed = db.ReclaimStalePoints(study_id, provenance.host);

  // Points of the study that this spec still lists (an axis value removed from the file keeps
  // its stored points but computes nothing new for them).
  std::vector<PointRow> to_compute;
  for (auto& row : db.PointsToCompute(study_id, options.retry_failed)) {
    if (by_key.contains(row.parameters.point_key)) to_compute.push_back(std::move(row));
  }
  const std::int64_t run_id = db.BeginRun(study_id, provenance);

  // Phase 1: references, each once per database.
  std::map<std::string, StoredReference> references;
  std::vector<ReferenceTask> missing;
  for (const auto& row : to_compute) {
    const std::string& key = row.parameters.reference_key;
    if (references.contains(key)) continue;
    if (auto stored = db.FindReference(key)) {
      references[key] = {stored->reference_id,
                         std::make_shared<const ReferenceRun>(FromReferenceRow(*stored)), ""};
      ++summary.references_reused;
    } else {
      references[key] = {};
      missing.push_back({key, *by_key.at(row.parameters.point_key)});
    }
  }
  // Longest first (cost grows with the truncation), so no worker is left with the longest alone.
  std::ranges::stable_sort(missing, std::greater{}, [&](const ReferenceTask& t) {
    return spec.scoring.reference.RFref(t.point.r_k);
  });
  const CpuTimer reference_timer;
  RunOnWorkers(
      missing.size(), summary.jobs,
      [&](std::size_t i) {
        const ReferenceTask& t = missing[i];
        ReferenceOutcome out{t.key, nullptr, "", t.point.r_k, t.point.window_s};
        try {
          const ComparisonOptions o = OptionsOf(spec, t.point);
          out.run = std::make_shared<const ReferenceRun>(ComputeReferenceRun(
              ProblemOf(spec, t.point), o.reference, o.window_s, o.Shocks(spec.problem.F1Hz())));
        } catch (const std::exception& e) {
          out.error = std::string("reference: ") + e.what();
        }
        return out;
      },
      [&](ReferenceOutcome out) {
        StoredReference& stored = references[out.key];
        if (out.run) {
          stored.id =
              db.StoreReference(ToReferenceRow(*out.run, out.key, out.r_k, out.window_s), run_id);
          stored.run = std::move(out.run);
          ++summary.references_computed;
        } else {
          stored.error = std::move(out.error);
        }
      });
  summary.reference_wall_s = reference_timer.WallSeconds();

  // Phase 2: points; each finished point is committed on its own.
  const CpuTimer point_timer;
  std::vector<std::int64_t> ids;
  for (const auto& row : to_compute) ids.push_back(row.point_id);
  db.MarkRunning(ids, run_id);
  ProgressReporter progress(static_cast<long>(to_compute.size()), stderr, options.progress);
  RunOnWorkers(
      to_compute.size(), summary.jobs,
      [&](std::size_t i) {
        const PointRow& row = to_compute[i];
        const StudyPoint& point = *by_key.at(row.parameters.point_key);
        const StoredReference& ref = references.at(row.parameters.reference_key);
        PointOutcome out{row.point_id, "failed", "", std::nullopt};
        if (!ref.run) {
          out.message = ref.error;
          return out;
        }
        try {
          const ComparisonResult r =
              ScoreAgainstReference(ProblemOf(spec, point), OptionsOf(spec, point), ref.run);
          out.status = ToString(r.status);
          out.message = r.message;
          out.score = ToScoreRow(r, ref.id);
        } catch (const std::exception& e) {
          out.message = e.what();
        }
        return out;
      },
      [&](PointOutcome out) {
        db.StoreResult(out.point_id, run_id, out.status, out.message, out.score);
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

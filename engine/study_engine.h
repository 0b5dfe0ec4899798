#pragma once
// The one study engine: runs any study kind (engine/study_kind.h) into a database. It computes
// what is missing, each reference once per database and each finished point in its own
// transaction; workers compute, the calling thread alone writes. Resumable: a rerun takes up
// the points a dead or stopped run left, and one run at a time holds the database (its lease,
// db/study_database.h).

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/cpu_timer.h"
#include "core/input_error.h"
#include "engine/progress_reporter.h"
#include "engine/provenance.h"
#include "engine/stop_request.h"
#include "engine/study_kind.h"
#include "engine/worker_pool.h"

namespace shockmap {

struct StudyRunOptions {
  std::string database_path = kDefaultDatabasePath;
  int jobs = 0;  // 0: one worker per hardware thread.
  bool retry_failed = false;
  bool progress = true;  // On stderr.
};

struct StudyRunSummary {
  std::string study;
  std::size_t points_in_study = 0;
  std::size_t points_to_compute = 0;  // Found pending (or failed, with retry) at the start.
  std::size_t points_computed = 0;
  long ok = 0, diverged = 0, failed = 0, reference_unconverged = 0;
  int references_computed = 0, references_reused = 0;
  int points_reclaimed = 0;  // Left 'running' by a dead or stopped run, taken up again.
  int jobs = 0;
  int stop_signal = 0;  // The signal that interrupted the run, or 0.
  double wall_s = 0.0;
  double reference_wall_s = 0.0;  // Wall time of the reference phase.
  double point_wall_s = 0.0;      // Wall time of the point phase.
};

// The workers a run uses: options.jobs, or one per hardware thread.
int WorkerCount(const StudyRunOptions& options);

// Counts one finished point in the summary by its stored status.
void CountOutcome(RunStatus status, StudyRunSummary& summary);

// Throws InputError when the study is stored with other settings, DbError on database faults
// (another run holding the database among them).
template <StudyKind Kind>
StudyRunSummary RunStudyKind(const Kind& kind, const StudyRunOptions& options);

// ---------------------------------------------------------------------------------------------

namespace detail {

template <StudyKind Kind>
class StudyRun {
 public:
  StudyRun(const Kind& kind, const StudyRunOptions& options)
      : kind_(kind), options_(options), db_(options.database_path) {
    summary_.study = kind.Header().name;
    summary_.jobs = WorkerCount(options);
    summary_.points_in_study = kind.Points().size();
  }

  StudyRunSummary Run() {
    const CpuTimer timer;
    Register();
    try {
      ComputeReferences();
      ComputePoints();
    } catch (...) {
      db_.ReleaseRunningPoints(kind_.Table(), run_id_);
      db_.EndRun(run_id_, RunEnd::kFailed);
      throw;
    }
    if (summary_.stop_signal != 0) db_.ReleaseRunningPoints(kind_.Table(), run_id_);
    db_.EndRun(run_id_, summary_.stop_signal != 0 ? RunEnd::kInterrupted : RunEnd::kCompleted);
    summary_.wall_s = timer.WallSeconds();
    return summary_;
  }

 private:
  using Point = typename Kind::Point;
  using Reference = typename Kind::Reference;
  using Outcome = typename Kind::Outcome;

  struct ReferenceSlot {
    std::int64_t id = 0;
    std::shared_ptr<const Reference> reference;  // Null when it could not be computed.
    std::string error;
  };
  struct ComputedReference {
    std::string key;
    std::optional<Reference> reference;
    std::string error;
  };

  // The study, its points and this run's lease; the points this spec lists that are to compute.
  void Register() {
    const StudyHeader& header = kind_.Header();
    if (const auto stored = db_.StoredSpec(header.name)) {
      kind_.CheckStoredSpec(*stored, options_.database_path);
    }
    const std::int64_t study_id = db_.UpsertStudy(header.name, header.spec_json);
    std::vector<NewPoint> rows;
    for (const Point& p : kind_.Points()) {
      rows.push_back(kind_.Describe(p));
      by_key_[rows.back().point_key] = &p;
    }
    db_.AddPoints(kind_.Table(), study_id, rows);
    run_id_ = db_.BeginRun(study_id, CurrentProvenance(summary_.jobs));
    summary_.points_reclaimed = db_.ReclaimStalePoints(kind_.Table(), study_id, run_id_);
    // A point whose value was removed from the file keeps its row but is not computed.
    for (PendingPoint& p : db_.PointsToCompute(kind_.Table(), study_id, options_.retry_failed)) {
      if (by_key_.contains(p.point_key)) to_compute_.push_back(std::move(p));
    }
    summary_.points_to_compute = to_compute_.size();
  }

  // Phase 1: each reference once per database, longest first so no worker is left alone with
  // the longest at the end.
  void ComputeReferences() {
    std::vector<const Point*> missing;
    for (const PendingPoint& p : to_compute_) {
      if (references_.contains(p.reference_key)) continue;
      ReferenceSlot& slot = references_[p.reference_key];
      if (auto stored = kind_.FindReference(db_, p.reference_key)) {
        slot.id = stored->id;
        slot.reference = std::make_shared<const Reference>(std::move(stored->value));
        ++summary_.references_reused;
      } else {
        missing.push_back(by_key_.at(p.point_key));
      }
    }
    std::ranges::stable_sort(missing, std::greater{},
                             [&](const Point* p) { return kind_.ReferenceCost(*p); });
    const CpuTimer timer;
    RunOnWorkers(
        missing.size(), summary_.jobs, [&](std::size_t i) { return Compute(*missing[i]); },
        [&](ComputedReference c) { StoreReference(std::move(c)); }, [&] { return Poll(); });
    summary_.reference_wall_s = timer.WallSeconds();
  }

  ComputedReference Compute(const Point& point) const {
    ComputedReference c{kind_.Describe(point).reference_key, std::nullopt, ""};
    try {
      c.reference.emplace(kind_.ComputeReference(point));
    } catch (const std::exception& e) {
      c.error = std::string("reference: ") + e.what();
    }
    return c;
  }

  void StoreReference(ComputedReference c) {
    ReferenceSlot& slot = references_[c.key];
    if (!c.reference) {
      slot.error = std::move(c.error);
      return;
    }
    slot.id = kind_.StoreReference(db_, *c.reference, run_id_);
    slot.reference = std::make_shared<const Reference>(std::move(*c.reference));
    ++summary_.references_computed;
  }

  // Phase 2: the points; each finished point is committed on its own.
  void ComputePoints() {
    if (summary_.stop_signal != 0) return;
    const CpuTimer timer;
    std::vector<std::int64_t> ids;
    for (const PendingPoint& p : to_compute_) ids.push_back(p.point_id);
    db_.MarkRunning(kind_.Table(), ids, run_id_);
    ProgressReporter progress(static_cast<long>(to_compute_.size()), stderr, options_.progress);
    RunOnWorkers(
        to_compute_.size(), summary_.jobs, [&](std::size_t i) { return Score(to_compute_[i]); },
        [&](std::pair<std::int64_t, Outcome> out) {
          kind_.StoreOutcome(db_, out.first, run_id_, out.second);
          CountOutcome(out.second.status, summary_);
          progress.Update(static_cast<long>(summary_.points_computed), summary_.diverged,
                          summary_.failed);
        },
        [&] { return Poll(); });
    progress.Finish(static_cast<long>(summary_.points_computed), summary_.diverged,
                    summary_.failed);
    summary_.point_wall_s = timer.WallSeconds();
  }

  std::pair<std::int64_t, Outcome> Score(const PendingPoint& p) const {
    const Point& point = *by_key_.at(p.point_key);
    const ReferenceSlot& slot = references_.at(p.reference_key);
    if (!slot.reference) return {p.point_id, Outcome{RunStatus::kFailed, slot.error, std::nullopt}};
    return {p.point_id, kind_.Score(point, *slot.reference, slot.id)};
  }

  // On the writer between results: renews the lease, and says whether to stop.
  bool Poll() {
    if (heartbeat_.WallSeconds() >= kHeartbeatPeriodS) {
      db_.Heartbeat(run_id_);
      heartbeat_ = CpuTimer();
    }
    summary_.stop_signal = StopSignal();
    return summary_.stop_signal != 0;
  }

  const Kind& kind_;
  const StudyRunOptions& options_;
  StudyDatabase db_;
  StudyRunSummary summary_;
  std::int64_t run_id_ = 0;
  std::map<std::string, const Point*> by_key_;
  std::vector<PendingPoint> to_compute_;
  std::map<std::string, ReferenceSlot> references_;
  CpuTimer heartbeat_;
};

}  // namespace detail

template <StudyKind Kind>
StudyRunSummary RunStudyKind(const Kind& kind, const StudyRunOptions& options) {
  return detail::StudyRun<Kind>(kind, options).Run();
}

}  // namespace shockmap

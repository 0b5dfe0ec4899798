#pragma once
// The one study engine: runs any study kind (engine/study_kind.h) into a database. It computes
// what is missing, each reference once per database and the finished points stored in groups,
// one transaction each (kMaxGroup, kGroupLatencyS); workers compute, the calling thread alone
// writes. Resumable: a rerun takes up the points a dead or stopped run left, and one run at a
// time holds the database (its lease, db/study_database.h).

#include <algorithm>
#include <concepts>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "core/cpu_timer.h"
#include "core/input_error.h"
#include "engine/progress_reporter.h"
#include "engine/provenance.h"
#include "engine/remote_workers.h"
#include "engine/stop_request.h"
#include "engine/study_kind.h"
#include "engine/task_queue.h"
#include "engine/worker_pool.h"

namespace shockmap {

// The writer stores finished points in groups, one transaction each: a group is stored once it
// holds kMaxGroup points or kGroupLatencyS after the previous one was (checked as each result
// arrives and as the writer polls), and before the run ends. A point computed but not yet
// stored when the process dies is computed again when the run resumes.
inline constexpr std::size_t kMaxGroup = 256;
inline constexpr double kGroupLatencyS = 0.1;

struct StudyRunOptions {
  std::string database_path = kDefaultDatabasePath;
  int jobs = 0;  // 0: one worker per hardware thread.
  bool retry_failed = false;
  bool progress = true;          // On stderr.
  ProgressListener on_progress;  // Told of each phase's progress too, when given.
  // The worker ranks of an MPI job (rank 0 runs the engine), or null: this process's threads.
  RemoteWorkers* remote = nullptr;
};

struct StudyRunSummary {
  std::string study;
  std::size_t points_in_study = 0;
  std::size_t points_to_compute = 0;  // Found pending (or failed, with retry) at the start.
  std::size_t points_computed = 0;
  long ok = 0, diverged = 0, unstable = 0, failed = 0, reference_unconverged = 0;
  int references_computed = 0, references_reused = 0;
  // Of the references computed now: not converged by the kind's own check (scored as
  // reference_unconverged), and failed (their points fail).
  int references_unconverged = 0, references_failed = 0;
  int points_reclaimed = 0;  // Left 'running' by a dead or stopped run, taken up again.
  int jobs = 0;              // Worker threads in all.
  int worker_ranks = 0;      // Of an MPI job; 0 in a local run.
  // Tasks a stopped MPI job handed out and got no answer for: "point 17 on rank 2 (host h)".
  std::vector<std::string> abandoned;
  // How the study's previous run ended when it did not complete (db UnfinishedLastRun).
  std::string previous_run;
  MessageTotals messages;  // Of an MPI job.
  int stop_signal = 0;     // The signal that interrupted the run, or 0.
  double wall_s = 0.0;
  // Wall time until the last reference computed now was stored, and until the last point was;
  // a point starts as soon as its reference is stored, so the two overlap.
  double reference_wall_s = 0.0;
  double point_wall_s = 0.0;
};

// The workers a run uses: options.jobs, or one per hardware thread.
int WorkerCount(const StudyRunOptions& options);

// Counts one finished point in the summary by its stored status.
void CountOutcome(RunStatus status, StudyRunSummary& summary);
// The points computed so far by status, "ok 12, diverged 3, unstable 0, failed 0,
// reference_unconverged 1": the point phase's progress detail and the summary's outcomes.
std::string OutcomeCounts(const StudyRunSummary& summary);

// Throws InputError when the study is stored with other settings, DbError on database faults
// (another run holding the database among them), NoWorkerRankLeft when every worker rank of an
// MPI job fell silent (the run then ends interrupted, its points pending again).
template <StudyKind Kind>
StudyRunSummary RunStudyKind(const Kind& kind, const StudyRunOptions& options);

// On MPI ranks 1..N-1: computes the tasks rank 0's RunStudyKind sends, until it ends the job.
template <StudyKind Kind>
void ServeStudyKind(const Kind& kind, RemoteWorkers& remote);

// ---------------------------------------------------------------------------------------------

namespace detail {

// What workers compute, the same in threads and on worker ranks, and the bytes it travels as.
// A reference task is [0][point index]; a score task is [1][point index][reference key][its id]
// [error][has reference][reference bytes when the rank does not hold it yet].
template <StudyKind Kind>
struct Work {
  using Point = typename Kind::Point;
  using Reference = typename Kind::Reference;
  using Outcome = typename Kind::Outcome;
  enum TaskType : std::uint8_t { kReferenceTask = 0, kScoreTask = 1 };

  struct ComputedReference {
    std::string key;
    std::optional<Reference> reference;
    std::string error;
  };
  // A reference as the points that need it see it: null when it could not be computed.
  struct ReferenceSlot {
    std::int64_t id = 0;
    std::shared_ptr<const Reference> reference;
    std::string error;
  };

  static ComputedReference ComputeReference(const Kind& kind, const Point& point) {
    ComputedReference c{kind.Describe(point).reference_key, std::nullopt, ""};
    try {
      c.reference.emplace(kind.ComputeReference(point));
    } catch (const std::exception& e) {
      c.error = std::string("reference: ") + e.what();
    }
    return c;
  }
  // A kind may tell whether a reference passed its own convergence check
  // (`bool ReferenceConverged(const Reference&) const`); progress counts those that did not.
  static bool Unconverged(const Kind& kind, const Reference& reference) {
    if constexpr (requires {
                    { kind.ReferenceConverged(reference) } -> std::convertible_to<bool>;
                  }) {
      return !kind.ReferenceConverged(reference);
    } else {
      return false;
    }
  }
  static Outcome Score(const Kind& kind, const Point& point, const ReferenceSlot& slot) {
    if (!slot.reference) return Outcome{RunStatus::kFailed, slot.error, std::nullopt};
    return kind.Score(point, *slot.reference, slot.id);
  }

  static void EncodeComputed(const Kind& kind, const ComputedReference& c, ByteWriter& out) {
    out.Put(c.key);
    out.Put(c.error);
    out.Put(static_cast<std::uint8_t>(c.reference.has_value()));
    if (c.reference) kind.EncodeReference(*c.reference, out);
  }
  static ComputedReference DecodeComputed(const Kind& kind, ByteReader& in) {
    ComputedReference c;
    c.key = in.GetString();
    c.error = in.GetString();
    if (in.Get<std::uint8_t>() != 0) c.reference.emplace(kind.DecodeReference(in));
    return c;
  }
};

template <StudyKind Kind>
class StudyRun {
 public:
  StudyRun(const Kind& kind, const StudyRunOptions& options)
      : kind_(kind), options_(options), remote_(options.remote), db_(options.database_path) {
    summary_.study = kind.Header().name;
    summary_.jobs =
        remote_ ? remote_->WorkerRanks() * remote_->ThreadsPerRank() : WorkerCount(options);
    summary_.worker_ranks = remote_ ? remote_->WorkerRanks() : 0;
    summary_.points_in_study = kind.Points().size();
    local_origin_ = {CurrentProvenance(summary_.jobs).host, 0};
  }

  StudyRunSummary Run() {
    const CpuTimer timer;
    Register();
    try {
      Compute();
    } catch (const NoWorkerRankLeft& e) {
      StoreFinished();
      db_.ReleaseRunningPoints(kind_.Table(), run_id_);
      db_.EndRun(run_id_, RunEnd::kInterrupted, e.what());
      throw;
    } catch (const std::exception& e) {
      // The run row keeps why it failed (a corrupt stored reference, say), for `study status`
      // and the run that takes its points up.
      db_.ReleaseRunningPoints(kind_.Table(), run_id_);
      db_.EndRun(run_id_, RunEnd::kFailed, e.what());
      throw;
    } catch (...) {
      db_.ReleaseRunningPoints(kind_.Table(), run_id_);
      db_.EndRun(run_id_, RunEnd::kFailed, "an unknown error");
      throw;
    }
    if (summary_.stop_signal == 0) {
      db_.EndRun(run_id_, RunEnd::kCompleted);
    } else {
      db_.ReleaseRunningPoints(kind_.Table(), run_id_);
      db_.EndRun(run_id_, RunEnd::kInterrupted, StopMessage());
    }
    summary_.wall_s = timer.WallSeconds();
    if (remote_) summary_.messages = remote_->Totals();
    return summary_;
  }

 private:
  using W = Work<Kind>;
  using Point = typename Kind::Point;
  using Reference = typename Kind::Reference;
  using Outcome = typename Kind::Outcome;
  using ComputedReference = typename W::ComputedReference;
  using ReferenceSlot = typename W::ReferenceSlot;

  // Throws InputError when the study is stored as another kind, or with another value of a
  // lifelong setting (its stored scores would no longer match its spec), naming the setting.
  void CheckStoredSpec(const std::string& text) const {
    const StudyHeader& h = kind_.Header();
    const std::string& db = options_.database_path;
    const nlohmann::json stored = ParseJsonText(text, db + ": stored study " + h.name);
    const std::string exists = h.file + ": study \"" + h.name + "\" already exists in " + db;
    if (StudyKindOf(stored, db) != Kind::kFileKind) {
      throw InputError(exists + " as a study of another kind; give this one a new name");
    }
    if (const auto change = kind_.ChangedSetting(stored, db)) {
      throw InputError(exists + " with " + change->key + " = " + change->stored +
                       ", where this file gives " + change->given +
                       ": its stored scores depend on that setting, which may not change under "
                       "the same name. Give the study a new name to run it with the new value (" +
                       std::string(Kind::kChangeableSettings) + " may change freely).");
    }
  }

  // The study, its points and this run's lease; the points this spec lists that are to compute.
  void Register() {
    const StudyHeader& header = kind_.Header();
    if (const auto stored = db_.StoredSpec(header.name)) CheckStoredSpec(*stored);
    std::vector<NewPoint> rows;
    const auto& points = kind_.Points();
    for (std::size_t i = 0; i < points.size(); ++i) {
      rows.push_back(kind_.Describe(points[i]));
      by_key_[rows.back().point_key] = i;
    }
    const RegisteredRun run = db_.RegisterRun(
        {header.name, header.spec_json, kind_.Table(), rows, CurrentProvenance(summary_.jobs)});
    const std::int64_t study_id = run.study_id;
    run_id_ = run.run_id;
    summary_.previous_run = run.previous_run;
    summary_.points_reclaimed = db_.ReclaimStalePoints(kind_.Table(), study_id, run_id_);
    // A point whose value was removed from the file keeps its row but is not computed.
    for (PendingPoint& p : db_.PointsToCompute(kind_.Table(), study_id, options_.retry_failed)) {
      if (by_key_.contains(p.point_key)) to_compute_.push_back(std::move(p));
    }
    summary_.points_to_compute = to_compute_.size();
  }

  const Point& PointOf(const PendingPoint& p) const {
    return kind_.Points()[by_key_.at(p.point_key)];
  }

  // For each task of Compute() (TaskQueue), the task it waits for: none for the references'
  // tasks, the task of its reference for a point whose reference is computed now; and its
  // group, the reference it needs: that task, or a number past the tasks' indices for each
  // reference read from the database.
  struct TaskOrder {
    std::vector<std::size_t> after, group;
  };

  // Runs local(i) for every task i of `order` (TaskQueue: each once the task it waits for is
  // consumed) on this process's threads, or the task encode(i, rank) on the worker ranks whose
  // answer decode(i, bytes) reads back; each result reaches consume(result, where it was
  // computed) on this thread, the one writer. `what(i)` names a task a stopped MPI job got no
  // answer for, or one a lost worker rank held.
  template <typename Result, typename Local, typename Encode, typename Decode, typename Consume,
            typename What>
  void Distribute(const TaskOrder& order, Local local, Encode encode, Decode decode,
                  Consume consume, What what) {
    if (remote_ == nullptr) {
      RunOnWorkers(
          order.after, summary_.jobs, local,
          [&](Result r) { consume(std::move(r), local_origin_); }, [&] { return Poll(); });
      return;
    }
    const auto abandoned = remote_->Run(
        order.after, order.group, encode,
        [&](std::size_t i, std::string_view bytes, int rank) {
          ByteReader in(bytes);
          Result r = decode(i, in);
          in.ExpectEnd();
          consume(std::move(r), remote_->OriginOf(rank));
        },
        [&] { return Poll(); }, what);
    for (const AbandonedTask& t : abandoned) {
      const PointOrigin o = remote_->OriginOf(t.rank);
      summary_.abandoned.push_back(what(t.index) + " on rank " + std::to_string(t.rank) +
                                   " (host " + o.host + ")");
    }
  }

  // The references the points to compute need and the database lacks (indices in
  // kind_.Points(), one per reference key), longest first so that no worker is left alone with
  // the longest at the end; the stored ones are read into references_.
  std::vector<std::size_t> MissingReferences() {
    std::vector<std::size_t> missing;
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
                             [&](std::size_t i) { return kind_.ReferenceCost(kind_.Points()[i]); });
    return missing;
  }

  // The order of Compute()'s tasks (TaskOrder).
  TaskOrder TaskOrderOf(const std::vector<std::size_t>& missing) const {
    std::map<std::string, std::size_t> group_of;  // Reference key -> its task, or past them.
    for (std::size_t k = 0; k < missing.size(); ++k) {
      group_of[kind_.Describe(kind_.Points()[missing[k]]).reference_key] = k;
    }
    const std::size_t n_tasks = missing.size() + to_compute_.size();
    TaskOrder order{std::vector<std::size_t>(missing.size(), TaskQueue::kNoWait),
                    std::vector<std::size_t>(missing.size(), TaskQueue::kNoWait)};
    for (const PendingPoint& p : to_compute_) {
      const std::size_t group =
          group_of.emplace(p.reference_key, n_tasks + group_of.size()).first->second;
      order.after.push_back(group < missing.size() ? group : TaskQueue::kNoWait);
      order.group.push_back(group);
    }
    return order;
  }

  // Each missing reference once per database, then the points, stored in groups: tasks
  // [0, R) compute the R missing references, task R + j scores to_compute_[j] and waits for its
  // reference's task, if any, so that a point starts as soon as its reference is stored.
  void Compute() {
    const CpuTimer timer;
    const std::vector<std::size_t> missing = MissingReferences();
    const std::size_t n_references = missing.size();
    const auto& points = kind_.Points();
    const TaskOrder order = TaskOrderOf(missing);
    std::vector<std::int64_t> ids;
    for (const PendingPoint& p : to_compute_) ids.push_back(p.point_id);
    db_.MarkRunning(kind_.Table(), ids, run_id_);
    ProgressReporter reference_progress("references", "done", static_cast<double>(n_references),
                                        stderr, options_.progress, options_.on_progress);
    ProgressReporter point_progress("points", "done", static_cast<double>(to_compute_.size()),
                                    stderr, options_.progress, options_.on_progress);
    // While references are computed the points wait on them: no rate of theirs foretells the
    // rest until the last reference is stored.
    if (n_references > 0) point_progress.HoldEstimate();
    auto reference_detail = [&] {
      return "unconverged " + std::to_string(summary_.references_unconverged) + ", failed " +
             std::to_string(summary_.references_failed);
    };
    auto references_done = [&] {
      return summary_.references_computed + summary_.references_failed;
    };
    auto finish_references = [&] {
      reference_progress.Finish(references_done(), reference_detail());
      point_progress.StartEstimate(static_cast<double>(summary_.points_computed));
      summary_.reference_wall_s = timer.WallSeconds();
    };
    using Scored = std::pair<std::int64_t, Outcome>;  // point_id, outcome
    using Result = std::variant<ComputedReference, Scored>;
    auto point_of_task = [&](std::size_t i) -> const PendingPoint& {
      return to_compute_[i - n_references];
    };
    Distribute<Result>(
        order,
        [&](std::size_t i) -> Result {
          if (i < n_references) return W::ComputeReference(kind_, points[missing[i]]);
          const PendingPoint& p = point_of_task(i);
          return Scored{p.point_id, W::Score(kind_, PointOf(p), references_.at(p.reference_key))};
        },
        [&](std::size_t i, int rank) {
          if (i >= n_references) return ScoreTask(point_of_task(i), rank);
          ByteWriter out;
          out.Put(static_cast<std::uint8_t>(W::kReferenceTask));
          out.Put(static_cast<std::uint64_t>(missing[i]));
          return out.Take();
        },
        [&](std::size_t i, ByteReader& in) -> Result {
          if (i < n_references) return W::DecodeComputed(kind_, in);
          return Scored{point_of_task(i).point_id, DecodeOutcome(kind_, in)};
        },
        [&](Result result, const PointOrigin& origin) {
          if (auto* c = std::get_if<ComputedReference>(&result)) {
            StoreReference(std::move(*c), origin);
            reference_progress.Update(references_done(), reference_detail());
            if (references_done() == static_cast<int>(n_references)) finish_references();
            return;
          }
          auto& [point_id, outcome] = std::get<Scored>(result);
          CountOutcome(outcome.status, summary_);
          finished_.push_back({point_id, origin, std::move(outcome)});
          if (finished_.size() >= kMaxGroup) StoreFinished();
          point_progress.Update(static_cast<double>(summary_.points_computed),
                                OutcomeCounts(summary_));
        },
        [&](std::size_t i) {
          if (i >= n_references) return "point " + std::to_string(point_of_task(i).point_id);
          return "the reference of point " + kind_.Describe(points[missing[i]]).point_key;
        });
    StoreFinished();
    if (references_done() < static_cast<int>(n_references)) finish_references();
    point_progress.Finish(static_cast<double>(summary_.points_computed), OutcomeCounts(summary_));
    summary_.point_wall_s = timer.WallSeconds();
  }

  // A worker rank keeps the references it computed or was sent.
  void StoreReference(ComputedReference c, const PointOrigin& origin) {
    ReferenceSlot& slot = references_[c.key];
    if (!c.reference) {
      slot.error = std::move(c.error);
      ++summary_.references_failed;
      return;
    }
    if (W::Unconverged(kind_, *c.reference)) ++summary_.references_unconverged;
    slot.id = kind_.StoreReference(db_, *c.reference, run_id_);
    slot.reference = std::make_shared<const Reference>(std::move(*c.reference));
    ++summary_.references_computed;
    if (remote_) held_.insert({origin.rank, c.key});
  }

  std::string ScoreTask(const PendingPoint& p, int rank) {
    const ReferenceSlot& slot = references_.at(p.reference_key);
    ByteWriter out;
    out.Put(static_cast<std::uint8_t>(W::kScoreTask));
    out.Put(static_cast<std::uint64_t>(by_key_.at(p.point_key)));
    out.Put(p.reference_key);
    out.Put(slot.id);
    out.Put(slot.error);
    const bool send = slot.reference && held_.insert({rank, p.reference_key}).second;
    out.Put(static_cast<std::uint8_t>(send));
    if (send) kind_.EncodeReference(*slot.reference, out);
    return out.Take();
  }

  // Why the run stopped, stored with it: an MPI launcher may no longer show rank 0's output.
  std::string StopMessage() const {
    std::string m = std::string(SignalName(summary_.stop_signal)) + " received";
    for (std::size_t i = 0; i < summary_.abandoned.size(); ++i) {
      m += (i == 0 ? "; no answer for " : ", ") + summary_.abandoned[i];
    }
    return m;
  }

  // The finished points not yet stored, in one transaction.
  void StoreFinished() {
    if (!finished_.empty()) {
      StoreOutcomes<Kind>(kind_, db_, run_id_, finished_);
      finished_.clear();
    }
    since_stored_ = CpuTimer();
  }

  // On the writer after each result and while it waits: stores the finished points once
  // kGroupLatencyS has passed since the last group, renews the lease, and says whether to stop.
  bool Poll() {
    if (since_stored_.WallSeconds() >= kGroupLatencyS) StoreFinished();
    if (heartbeat_.WallSeconds() >= kHeartbeatPeriodS) {
      db_.Heartbeat(run_id_);
      heartbeat_ = CpuTimer();
    }
    summary_.stop_signal = StopSignal();
    return summary_.stop_signal != 0;
  }

  const Kind& kind_;
  const StudyRunOptions& options_;
  RemoteWorkers* remote_;
  StudyDatabase db_;
  StudyRunSummary summary_;
  PointOrigin local_origin_;
  std::int64_t run_id_ = 0;
  std::map<std::string, std::size_t> by_key_;  // Point key -> index in kind_.Points().
  std::vector<PendingPoint> to_compute_;
  std::map<std::string, ReferenceSlot> references_;
  std::set<std::pair<int, std::string>> held_;  // (worker rank, reference key) it holds.
  std::vector<FinishedPoint<Kind>> finished_;   // Computed, not yet stored.
  CpuTimer since_stored_;
  CpuTimer heartbeat_;
};

// Executes the tasks of StudyRun on a worker rank, keeping every reference it computed or was
// sent for the score tasks that follow. Thread-safe: a rank may run tasks on several threads.
template <StudyKind Kind>
class StudyWorker {
 public:
  explicit StudyWorker(const Kind& kind) : kind_(kind) {}

  // Throws std::runtime_error on a malformed task (never sent by the same build).
  std::string Execute(std::string_view task) {
    ByteReader in(task);
    const auto type = in.Get<std::uint8_t>();
    const auto& point = kind_.Points().at(static_cast<std::size_t>(in.Get<std::uint64_t>()));
    ByteWriter out;
    if (type == W::kReferenceTask) {
      typename W::ComputedReference c = W::ComputeReference(kind_, point);
      if (c.reference) Keep(c.key, *c.reference);
      W::EncodeComputed(kind_, c, out);
    } else {
      EncodeOutcome(kind_, W::Score(kind_, point, Slot(in)), out);
    }
    return out.Take();
  }

 private:
  using W = Work<Kind>;

  typename W::ReferenceSlot Slot(ByteReader& in) {
    const std::string key = in.GetString();
    typename W::ReferenceSlot slot;
    slot.id = in.Get<std::int64_t>();
    slot.error = in.GetString();
    if (in.Get<std::uint8_t>() != 0) Keep(key, kind_.DecodeReference(in));
    in.ExpectEnd();
    if (slot.error.empty()) {
      // Another thread of this rank may still be decoding it from the task that brought it.
      std::unique_lock lock(mutex_);
      kept_.wait(lock, [&] { return held_.contains(key); });
      slot.reference = held_.at(key);
    }
    return slot;
  }

  void Keep(const std::string& key, typename Kind::Reference reference) {
    auto kept = std::make_shared<const typename Kind::Reference>(std::move(reference));
    const std::lock_guard lock(mutex_);
    held_[key] = std::move(kept);
    kept_.notify_all();
  }

  const Kind& kind_;
  std::mutex mutex_;
  std::condition_variable kept_;
  std::map<std::string, std::shared_ptr<const typename Kind::Reference>> held_;
};

}  // namespace detail

template <StudyKind Kind>
StudyRunSummary RunStudyKind(const Kind& kind, const StudyRunOptions& options) {
  return detail::StudyRun<Kind>(kind, options).Run();
}

template <StudyKind Kind>
void ServeStudyKind(const Kind& kind, RemoteWorkers& remote) {
  detail::StudyWorker<Kind> worker(kind);
  remote.Serve([&](std::string_view task) { return worker.Execute(task); });
}

}  // namespace shockmap

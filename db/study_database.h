#pragma once
// The writer's view of a study database. Exactly one StudyDatabase (one connection, one thread)
// writes; workers never touch SQLite. Every method that writes is one transaction, so a process
// killed at any moment leaves every point either as it was or completely stored.
//
// What is common to every study kind lives here: studies, runs (with the writer's lease) and the
// life of a point (pending -> running -> its outcome). Each kind keeps its own parameters,
// scores and references (db/canonical_points.h, db/scene_points.h) in its own point table.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "db/sqlite_handle.h"

namespace shockmap {

inline constexpr const char* kDefaultDatabasePath = "shockmap.db";

// A run holds the database while its heartbeat is younger than this: a second run is refused
// until then, and takes over the points of a run whose heartbeat is older (a killed process,
// a restarted container, a stopped process). The writer beats every kHeartbeatPeriodS.
inline constexpr double kLeaseGraceS = 30.0;
inline constexpr double kHeartbeatPeriodS = 5.0;

struct Provenance {
  std::string code_version, compiler, build_type, host;
  std::int64_t pid = 0;
  int jobs = 1;
};

// Where a point was computed: the host and the MPI rank (0 in a local run).
struct PointOrigin {
  std::string host;
  int rank = 0;
};

// A table of study points. Its lifecycle columns are the same for every kind: point_id,
// study_id, point_key, reference_key, status, message, run_id, updated_utc. The parameter
// columns are the kind's, bound in this order.
struct PointTable {
  std::string_view name;
  std::vector<std::string_view> parameter_columns;
  // Views to write again when points are added (inside AddPoints' transaction), or null.
  void (*refresh_views)(Connection& c) = nullptr;
};

// A point to register: its key within the study, the key of its reference (equal keys share
// one reference across studies) and its parameter values in the table's column order.
struct NewPoint {
  std::string point_key;
  std::string reference_key;
  std::vector<SqlValue> parameters;
};

// A point waiting to be computed.
struct PendingPoint {
  std::int64_t point_id = 0;
  std::string point_key;
  std::string reference_key;
};

// How a run ended, stored in runs.end_reason.
enum class RunEnd { kCompleted, kInterrupted, kFailed };

class StudyDatabase {
 public:
  // Opens or creates `path` in WAL mode and migrates it. Throws DbError (see MigrateToCurrent).
  explicit StudyDatabase(const std::string& path);

  // Creates the study or, when it exists, records its latest spec. Returns study_id.
  std::int64_t UpsertStudy(const std::string& name, const std::string& spec_json);
  std::optional<std::string> StoredSpec(const std::string& name);

  // Takes the writer's lease: throws DbError naming the holder (run, host, pid, heartbeat age)
  // when another run's heartbeat is younger than kLeaseGraceS. Returns the new run_id.
  std::int64_t BeginRun(std::int64_t study_id, const Provenance& provenance);
  // Renews the lease. Throws DbError when another run has taken it over (this process was
  // stopped for longer than the grace period): it must stop writing.
  void Heartbeat(std::int64_t run_id);
  // `message` says why a run that did not complete ended.
  void EndRun(std::int64_t run_id, RunEnd end, const std::string& message = "");
  // The last run of the study when it did not complete ("run 3 (host h, pid 42) interrupted:
  // ..."), for the run that takes up its points. Call before BeginRun.
  std::optional<std::string> UnfinishedLastRun(std::int64_t study_id);

  // Inserts the points not yet in the study as 'pending'; returns how many were new.
  int AddPoints(const PointTable& table, std::int64_t study_id,
                const std::vector<NewPoint>& points);
  // Points left 'running' by any run but `run_id` go back to 'pending'; the caller holds the
  // lease, so their runs are gone. Returns how many.
  int ReclaimStalePoints(const PointTable& table, std::int64_t study_id, std::int64_t run_id);
  // 'pending' points (and 'failed' ones when retry_failed), in point_id order.
  std::vector<PendingPoint> PointsToCompute(const PointTable& table, std::int64_t study_id,
                                            bool retry_failed);
  void MarkRunning(const PointTable& table, const std::vector<std::int64_t>& point_ids,
                   std::int64_t run_id);
  // Points of `run_id` still 'running' go back to 'pending' (an interrupted run). Returns how
  // many.
  int ReleaseRunningPoints(const PointTable& table, std::int64_t run_id);

  // For the kinds' own tables in db/ (canonical_points, scene_points) only.
  Connection& Raw() { return db_; }

 private:
  // Running points matching `condition` (its ? bound to `ids`) back to 'pending'.
  template <typename... Ids>
  int BackToPending(const PointTable& table, std::string_view condition, Ids... ids);

  Connection db_;
};

// Stores a point's final status and origin in one transaction with whatever `write_score` writes
// on the same connection (the kind's score row), and counts it in its run.
template <typename WriteScore>
void StorePointOutcome(StudyDatabase& db, const PointTable& table, std::int64_t point_id,
                       std::int64_t run_id, const PointOrigin& origin, std::string_view status,
                       std::string_view message, WriteScore write_score);

// Runs one INSERT with `values` bound in order, in its own transaction; returns the new rowid.
template <typename... T>
std::int64_t InsertRow(StudyDatabase& db, std::string_view sql, const T&... values) {
  Connection& c = db.Raw();
  Transaction t(c);
  c.Prepare(sql).BindAll(values...).Run();
  const std::int64_t id = c.LastInsertRowId();
  t.Commit();
  return id;
}

// The row of `sql` (one ? bound to `key`) read into `members` of a Row in column order, with
// `key_member` set to the key; nullopt when there is none.
template <typename Row, typename... M>
std::optional<Row> FindRow(StudyDatabase& db, std::string_view sql, const std::string& key,
                           std::string Row::*key_member, M Row::*... members) {
  Statement s = db.Raw().Prepare(sql);
  s.Bind(1, key);
  if (!s.Step()) return std::nullopt;
  Row row;
  row.*key_member = key;
  s.ReadColumns((row.*members)...);
  return row;
}

// Seconds since the Unix epoch (the clock of the writer's heartbeat).
double UnixNow();

// The current UTC time as ISO 8601 with milliseconds.
std::string UtcNow();

namespace detail {
void UpdatePointStatus(Connection& c, const PointTable& table, std::int64_t point_id,
                       std::int64_t run_id, const PointOrigin& origin, std::string_view status,
                       std::string_view message);
}  // namespace detail

template <typename WriteScore>
void StorePointOutcome(StudyDatabase& db, const PointTable& table, std::int64_t point_id,
                       std::int64_t run_id, const PointOrigin& origin, std::string_view status,
                       std::string_view message, WriteScore write_score) {
  Connection& c = db.Raw();
  Transaction t(c);
  write_score(c);
  detail::UpdatePointStatus(c, table, point_id, run_id, origin, status, message);
  t.Commit();
}

}  // namespace shockmap

#pragma once
// The writer's view of a study database. Exactly one StudyDatabase (one connection, one thread)
// writes; workers never touch SQLite. Every method that writes is one transaction, so a process
// killed at any moment leaves every point either as it was or completely stored.
//
// What is common to every study kind lives here: studies, runs (with the writer's lease) and the
// life of a point (pending -> running -> its outcome) in the kind's point table
// (db/point_tables.h). Each kind keeps its own scores and references (db/canonical_points.h,
// db/scene_points.h, db/ensemble_members.h).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "db/point_tables.h"
#include "db/sqlite_handle.h"
#include "db/stored_record.h"

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

// What a run registers before it computes (StudyDatabase::RegisterRun): its study, the points
// its spec lists in `table`, and where it runs.
struct RunRegistration {
  std::string study_name, spec_json;
  const PointTable& table;
  const std::vector<NewPoint>& points;
  Provenance provenance;
};

// A registered run: its study and run ids, and how the study's previous run ended when it did
// not complete ("run 3 (host h, pid 42) interrupted: ...", empty otherwise), for the run that
// takes up its points.
struct RegisteredRun {
  std::int64_t study_id = 0, run_id = 0;
  std::string previous_run;
};

// How a run ended, stored in runs.end_reason.
enum class RunEnd { kCompleted, kInterrupted, kFailed };

class StudyDatabase {
 public:
  // Opens or creates `path` in WAL mode and migrates it. Throws DbError (see MigrateToCurrent).
  explicit StudyDatabase(const std::string& path);

  std::optional<std::string> StoredSpec(const std::string& name);

  // Registers a run in one IMMEDIATE transaction: takes the writer's lease first (throws
  // DbError naming the holder, its run, host, pid and heartbeat age, when another run's
  // heartbeat is younger than kLeaseGraceS, having written nothing), then creates the study or
  // records its latest spec, inserts the points not yet in the study as 'pending' (writing the
  // table's parameter view again) and opens the run's row.
  RegisteredRun RegisterRun(const RunRegistration& registration);
  // Renews the lease. Throws DbError when another run has taken it over (this process was
  // stopped for longer than the grace period): it must stop writing.
  void Heartbeat(std::int64_t run_id);
  // `message` says why a run that did not complete ended.
  void EndRun(std::int64_t run_id, RunEnd end, const std::string& message = "");
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

  // For the kinds' own tables in db/ (canonical_points, scene_points, ensemble_members) only.
  Connection& Raw() { return db_; }

 private:
  // Running points matching `condition` (its ? bound to `ids`) back to 'pending'.
  template <typename... Ids>
  int BackToPending(const PointTable& table, std::string_view condition, Ids... ids);

  Connection db_;
};

// A finished point's final status as its point table stores it.
struct PointStatus {
  std::int64_t point_id = 0;
  PointOrigin origin;
  std::string status;
  std::string_view message;  // Valid until it is stored.
};

// Stores `count` finished points in one transaction: write(c, i) writes point i's own rows on
// the connection (the kind's score row) and returns its status, stored with its origin; the run
// counts them done. All or none of them are stored, so a killed writer leaves each point either
// as it was (computed again when the run resumes) or completely stored.
template <typename Write>
void StorePointOutcomes(StudyDatabase& db, const PointTable& table, std::int64_t run_id,
                        std::size_t count, Write write);

// Seconds since the Unix epoch (the clock of the writer's heartbeat).
double UnixNow();

// The current UTC time as ISO 8601 with milliseconds.
std::string UtcNow();

// Stores a computed reference `row` (a record with its column table and a reference_id
// member: the rows of reference_runs, scene_references and ensemble_references) in `table`
// with the run that computed it and the time, in its own transaction. Returns its new id.
template <typename Row>
std::int64_t InsertReference(StudyDatabase& db, std::string_view table, const Row& row,
                             const auto& columns, std::int64_t run_id) {
  Connection& c = db.Raw();
  Transaction t(c);
  Statement insert =
      c.Prepare("INSERT INTO " + std::string(table) + "(" + ColumnList(columns) +
                ", run_id, created_utc) VALUES (" + Placeholders(std::size(columns) + 2) + ")");
  const int next = BindRecord(insert, 1, row, columns);
  insert.Bind(next, run_id).Bind(next + 1, UtcNow()).Run();
  const std::int64_t id = c.LastInsertRowId();
  t.Commit();
  return id;
}

// The reference of `table` whose reference_key is `key`, with its id; nothing when none is
// stored. `what` names it in a refusal of a corrupt row ("reference 7").
template <typename Row>
std::optional<Row> FindReferenceRow(StudyDatabase& db, std::string_view table,
                                    std::string_view what, const std::string& key,
                                    const auto& columns) {
  Statement s = db.Raw().Prepare("SELECT reference_id, " + ColumnList(columns) + " FROM " +
                                 std::string(table) + " WHERE reference_key = ?");
  s.Bind(1, key);
  if (!s.Step()) return std::nullopt;
  Row row;
  s.ReadColumn(0, row.reference_id);
  ReadRecord(s, 1, row, columns, db.Raw().Path(),
             [&] { return std::string(what) + " " + std::to_string(row.reference_id); });
  return row;
}

namespace detail {
// The statement UpdatePointStatus runs on `table`, built once per group.
std::string PointStatusUpdate(const PointTable& table);
void UpdatePointStatus(Statement& update, std::int64_t run_id, const PointStatus& point,
                       std::string_view now_utc);
void CountPointsDone(Connection& c, std::int64_t run_id, std::size_t count);
}  // namespace detail

template <typename Write>
void StorePointOutcomes(StudyDatabase& db, const PointTable& table, std::int64_t run_id,
                        std::size_t count, Write write) {
  Connection& c = db.Raw();
  const std::string now = UtcNow();
  const std::string update = detail::PointStatusUpdate(table);
  Transaction t(c);
  for (std::size_t i = 0; i < count; ++i) {
    const PointStatus point = write(c, i);
    detail::UpdatePointStatus(c.Cached(update), run_id, point, now);
  }
  detail::CountPointsDone(c, run_id, count);
  t.Commit();
}

}  // namespace shockmap

#include "db/study_database.h"

#include <signal.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

#include <fmt/format.h>

#include "db/schema.h"

namespace shockmap {

std::string UtcNow() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto ms =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  char out[40];
  std::snprintf(out, sizeof out, "%s.%03dZ", text, static_cast<int>(ms));
  return out;
}

double UnixNow() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

namespace {

// WAL is kept in the file, so it is set once, on a new database. Switching needs the file to
// itself, and SQLite does not wait for that (a busy handler could deadlock there): while
// another process opens the same new file, try again for up to the busy timeout.
void UseWriteAheadLog(Connection& db) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  for (;;) {
    {
      Statement mode = db.Prepare("PRAGMA journal_mode");
      if (mode.Step() && mode.GetText(0) == "wal") return;
    }  // Finalized: a live statement would hold a read transaction.
    try {
      db.Execute("PRAGMA journal_mode = WAL");
      return;
    } catch (const DbError&) {
      if (std::chrono::steady_clock::now() > deadline) throw;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

StudyDatabase::StudyDatabase(const std::string& path)
    : db_(path, Connection::Mode::kReadWriteCreate) {
  MigrateToCurrent(db_);
  UseWriteAheadLog(db_);
  // With WAL, NORMAL loses no committed transaction on a process kill, only on power loss.
  db_.Execute("PRAGMA synchronous = NORMAL");
  db_.Execute("PRAGMA foreign_keys = ON");
}

std::optional<std::string> StudyDatabase::StoredSpec(const std::string& name) {
  Statement s = db_.Prepare("SELECT spec_json FROM studies WHERE name = ?");
  s.Bind(1, name);
  if (!s.Step()) return std::nullopt;
  return s.GetText(0);
}

namespace {

// Creates the study or, when it exists, records its latest spec. Returns study_id. Inside the
// caller's transaction.
std::int64_t UpsertStudy(Connection& db, const std::string& name, const std::string& spec_json) {
  const std::string now = UtcNow();
  db.Prepare(
        "INSERT INTO studies(name, spec_json, created_utc, updated_utc) VALUES (?, ?, ?, ?) "
        "ON CONFLICT(name) DO UPDATE SET spec_json = excluded.spec_json, "
        "updated_utc = excluded.updated_utc WHERE spec_json != excluded.spec_json")
      .Bind(1, name)
      .Bind(2, spec_json)
      .Bind(3, now)
      .Bind(4, now)
      .Run();
  Statement id = db.Prepare("SELECT study_id FROM studies WHERE name = ?");
  id.Bind(1, name).Step();
  return id.GetInt(0);
}

// True when the process has exited but was not yet reaped by its parent (a zombie: an MPI
// rank killed with its launcher still winding the job down).
bool Zombie(std::int64_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  std::getline(stat, line);
  const auto close = line.rfind(')');
  return close != std::string::npos && line.size() > close + 2 && line[close + 2] == 'Z';
}

// True when `pid` on this host is known to be gone (a killed run): its lease ends at once
// instead of after the grace period.
bool ProcessGone(const std::string& holder_host, std::int64_t pid, const std::string& our_host) {
  if (holder_host != our_host) return false;
  return (kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) || Zombie(pid);
}

// Throws naming the run that holds the lease, if one does.
void CheckNoLiveHolder(Connection& db, const std::string& our_host) {
  Statement live = db.Prepare(
      "SELECT run_id, host, pid, heartbeat_unix_s FROM runs "
      "WHERE ended_utc IS NULL AND heartbeat_unix_s > ? ORDER BY run_id DESC LIMIT 1");
  live.Bind(1, UnixNow() - kLeaseGraceS);
  if (!live.Step() || ProcessGone(live.GetText(1), live.GetInt(2), our_host)) return;
  throw DbError(fmt::format(
      "{}: run {} (host {}, pid {}) is writing this database (last heartbeat {:.0f} s ago); "
      "one writer at a time: wait for it to end, or stop it (its points are taken over {:.0f} s "
      "after its last heartbeat)",
      db.Path(), live.GetInt(0), live.GetText(1), live.GetInt(2), UnixNow() - live.GetDouble(3),
      kLeaseGraceS));
}

// Ends every run row left open (their processes are gone: the caller holds the lease) and
// opens this run's. Returns its run_id. Inside the caller's transaction.
std::int64_t InsertRun(Connection& db, std::int64_t study_id, const Provenance& p) {
  db.Prepare("UPDATE runs SET ended_utc = ?, end_reason = 'abandoned' WHERE ended_utc IS NULL")
      .Bind(1, UtcNow())
      .Run();
  db.Prepare(
        "INSERT INTO runs(study_id, code_version, compiler, build_type, host, pid, jobs, "
        "started_utc, heartbeat_unix_s) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .Bind(1, study_id)
      .Bind(2, p.code_version)
      .Bind(3, p.compiler)
      .Bind(4, p.build_type)
      .Bind(5, p.host)
      .Bind(6, p.pid)
      .Bind(7, p.jobs)
      .Bind(8, UtcNow())
      .Bind(9, UnixNow())
      .Run();
  return db.LastInsertRowId();
}

// The study's last run when it did not complete (RegisteredRun::previous_run), empty otherwise.
std::string UnfinishedLastRun(Connection& db, std::int64_t study_id) {
  Statement s = db.Prepare(
      "SELECT run_id, host, pid, coalesce(end_reason, 'abandoned'), coalesce(end_message, '') "
      "FROM runs WHERE study_id = ? ORDER BY run_id DESC LIMIT 1");
  s.Bind(1, study_id);
  if (!s.Step() || s.GetText(3) == "completed") return "";
  const std::string message = s.GetText(4);
  return fmt::format("run {} (host {}, pid {}) {}{}", s.GetInt(0), s.GetText(1), s.GetInt(2),
                     s.GetText(3) == "abandoned" ? "was killed" : s.GetText(3),
                     message.empty() ? "" : ": " + message);
}

// Inserts the points not yet in the study as 'pending' and writes the table's parameter view
// again. Inside the caller's transaction.
void InsertPoints(Connection& db, const PointTable& table, std::int64_t study_id,
                  const std::vector<NewPoint>& points) {
  std::string columns, placeholders;
  for (std::string_view c : table.parameter_columns) {
    columns += fmt::format(", {}", c);
    placeholders += ", ?";
  }
  Statement insert = db.Prepare(
      fmt::format("INSERT OR IGNORE INTO {}(study_id, point_key, reference_key, updated_utc{}) "
                  "VALUES (?, ?, ?, ?{})",
                  table.name, columns, placeholders));
  const std::string now = UtcNow();
  for (const NewPoint& p : points) {
    insert.Bind(1, study_id).Bind(2, p.point_key).Bind(3, p.reference_key).Bind(4, now);
    for (std::size_t i = 0; i < p.parameters.size(); ++i) {
      insert.BindValue(static_cast<int>(5 + i), p.parameters[i]);
    }
    insert.Run();
  }
  RefreshParameterView(db, table);
}

}  // namespace

RegisteredRun StudyDatabase::RegisterRun(const RunRegistration& r) {
  // One IMMEDIATE transaction, the lease checked before anything is written: two runs starting
  // together are serialized by SQLite, the second sees the first, and a refused run has
  // changed nothing (neither the study's stored spec nor its points).
  Transaction t(db_);
  CheckNoLiveHolder(db_, r.provenance.host);
  RegisteredRun run;
  run.study_id = UpsertStudy(db_, r.study_name, r.spec_json);
  InsertPoints(db_, r.table, run.study_id, r.points);
  run.previous_run = UnfinishedLastRun(db_, run.study_id);
  run.run_id = InsertRun(db_, run.study_id, r.provenance);
  t.Commit();
  return run;
}

void StudyDatabase::Heartbeat(std::int64_t run_id) {
  Transaction t(db_);
  db_.Prepare("UPDATE runs SET heartbeat_unix_s = ? WHERE run_id = ? AND ended_utc IS NULL")
      .Bind(1, UnixNow())
      .Bind(2, run_id)
      .Run();
  if (sqlite3_changes(db_.Raw()) == 0) {
    throw DbError(db_.Path() + ": run " + std::to_string(run_id) +
                  " lost the database to a later run (this process was stopped for longer than " +
                  fmt::format("{:.0f}", kLeaseGraceS) + " s); its remaining points are theirs");
  }
  t.Commit();
}

void StudyDatabase::EndRun(std::int64_t run_id, RunEnd end, const std::string& message) {
  static constexpr const char* kReasons[] = {"completed", "interrupted", "failed"};
  db_.Prepare("UPDATE runs SET ended_utc = ?, end_reason = ?, end_message = ? WHERE run_id = ?")
      .Bind(1, UtcNow())
      .Bind(2, kReasons[static_cast<int>(end)])
      .Bind(3, message)
      .Bind(4, run_id)
      .Run();
}

template <typename... Ids>
int StudyDatabase::BackToPending(const PointTable& table, std::string_view condition, Ids... ids) {
  Transaction t(db_);
  db_.Prepare(fmt::format("UPDATE {} SET status = 'pending', updated_utc = ? "
                          "WHERE status = 'running' AND {}",
                          table.name, condition))
      .BindAll(UtcNow(), ids...)
      .Run();
  const int changed = sqlite3_changes(db_.Raw());
  t.Commit();
  return changed;
}

int StudyDatabase::ReclaimStalePoints(const PointTable& table, std::int64_t study_id,
                                      std::int64_t run_id) {
  return BackToPending(table, "study_id = ? AND run_id IS NOT ?", study_id, run_id);
}

std::vector<PendingPoint> StudyDatabase::PointsToCompute(const PointTable& table,
                                                         std::int64_t study_id, bool retry_failed) {
  Statement s = db_.Prepare(
      fmt::format("SELECT point_id, point_key, reference_key FROM {} "
                  "WHERE study_id = ? AND (status = 'pending' OR (? AND status = 'failed')) "
                  "ORDER BY point_id",
                  table.name));
  s.Bind(1, study_id).Bind(2, retry_failed ? 1 : 0);
  std::vector<PendingPoint> rows;
  while (s.Step()) rows.push_back({s.GetInt(0), s.GetText(1), s.GetText(2)});
  return rows;
}

void StudyDatabase::MarkRunning(const PointTable& table, const std::vector<std::int64_t>& point_ids,
                                std::int64_t run_id) {
  Transaction t(db_);
  Statement s = db_.Prepare(
      fmt::format("UPDATE {} SET status = 'running', run_id = ?, message = '', updated_utc = ? "
                  "WHERE point_id = ?",
                  table.name));
  const std::string now = UtcNow();
  for (auto id : point_ids) {
    s.Bind(1, run_id).Bind(2, now).Bind(3, id);
    s.Run();
  }
  t.Commit();
}

int StudyDatabase::ReleaseRunningPoints(const PointTable& table, std::int64_t run_id) {
  return BackToPending(table, "run_id = ?", run_id);
}

namespace detail {

std::string PointStatusUpdate(const PointTable& table) {
  return fmt::format(
      "UPDATE {} SET status = ?, message = ?, run_id = ?, updated_utc = ?, host = ?, rank = ? "
      "WHERE point_id = ?",
      table.name);
}

void UpdatePointStatus(Statement& update, std::int64_t run_id, const PointStatus& point,
                       std::string_view now_utc) {
  update.Bind(1, point.status)
      .Bind(2, point.message)
      .Bind(3, run_id)
      .Bind(4, now_utc)
      .Bind(5, point.origin.host)
      .Bind(6, point.origin.rank)
      .Bind(7, point.point_id)
      .Run();
}

void CountPointsDone(Connection& c, std::int64_t run_id, std::size_t count) {
  c.Cached("UPDATE runs SET points_done = points_done + ? WHERE run_id = ?")
      .Bind(1, static_cast<std::int64_t>(count))
      .Bind(2, run_id)
      .Run();
}

}  // namespace detail

}  // namespace shockmap

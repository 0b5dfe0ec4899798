#include "db/study_database.h"

#include <signal.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <ctime>

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

StudyDatabase::StudyDatabase(const std::string& path)
    : db_(path, Connection::Mode::kReadWriteCreate) {
  MigrateToCurrent(db_);
  db_.Execute("PRAGMA journal_mode = WAL");
  // With WAL, NORMAL loses no committed transaction on a process kill, only on power loss.
  db_.Execute("PRAGMA synchronous = NORMAL");
  db_.Execute("PRAGMA foreign_keys = ON");
}

std::optional<std::int64_t> StudyDatabase::FindStudy(const std::string& name) {
  Statement s = db_.Prepare("SELECT study_id FROM studies WHERE name = ?");
  s.Bind(1, name);
  if (!s.Step()) return std::nullopt;
  return s.GetInt(0);
}

std::optional<std::string> StudyDatabase::StoredSpec(const std::string& name) {
  Statement s = db_.Prepare("SELECT spec_json FROM studies WHERE name = ?");
  s.Bind(1, name);
  if (!s.Step()) return std::nullopt;
  return s.GetText(0);
}

std::int64_t StudyDatabase::UpsertStudy(const std::string& name, const std::string& spec_json) {
  Transaction t(db_);
  const std::string now = UtcNow();
  db_.Prepare(
         "INSERT INTO studies(name, spec_json, created_utc, updated_utc) VALUES (?, ?, ?, ?) "
         "ON CONFLICT(name) DO UPDATE SET spec_json = excluded.spec_json, "
         "updated_utc = excluded.updated_utc WHERE spec_json != excluded.spec_json")
      .Bind(1, name)
      .Bind(2, spec_json)
      .Bind(3, now)
      .Bind(4, now)
      .Run();
  t.Commit();
  return *FindStudy(name);
}

int StudyDatabase::AddPoints(std::int64_t study_id, const std::vector<PointParameters>& points) {
  Transaction t(db_);
  Statement insert = db_.Prepare(
      "INSERT OR IGNORE INTO points(study_id, point_key, reference_key, r_k, r_ftrunc, scheme, "
      "dt_rule, dt_factor, dt_asked_s, window_s, n_elements_asked, mass_damping_per_s, "
      "updated_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  const std::string now = UtcNow();
  int added = 0;
  for (const auto& p : points) {
    insert.Bind(1, study_id)
        .Bind(2, p.point_key)
        .Bind(3, p.reference_key)
        .Bind(4, p.r_k)
        .Bind(5, p.r_ftrunc)
        .Bind(6, p.scheme)
        .Bind(7, p.dt_rule)
        .Bind(8, p.dt_factor)
        .Bind(9, p.dt_asked_s)
        .Bind(10, p.window_s)
        .Bind(11, p.n_elements_asked)
        .Bind(12, p.mass_damping_per_s)
        .Bind(13, now);
    insert.Run();
    added += sqlite3_changes(db_.Raw());
  }
  t.Commit();
  return added;
}

std::int64_t StudyDatabase::BeginRun(std::int64_t study_id, const Provenance& p) {
  db_.Prepare(
         "INSERT INTO runs(study_id, code_version, compiler, build_type, host, pid, jobs, "
         "started_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
      .Bind(1, study_id)
      .Bind(2, p.code_version)
      .Bind(3, p.compiler)
      .Bind(4, p.build_type)
      .Bind(5, p.host)
      .Bind(6, p.pid)
      .Bind(7, p.jobs)
      .Bind(8, UtcNow())
      .Run();
  return db_.LastInsertRowId();
}

void StudyDatabase::EndRun(std::int64_t run_id) {
  db_.Prepare("UPDATE runs SET ended_utc = ? WHERE run_id = ?")
      .Bind(1, UtcNow())
      .Bind(2, run_id)
      .Run();
}

namespace {

std::string TableName(PointTable table) {
  return table == PointTable::kScene ? "scene_points" : "points";
}

}  // namespace

int StudyDatabase::ReclaimStalePoints(std::int64_t study_id, const std::string& host,
                                      PointTable table) {
  Statement running = db_.Prepare(
      "SELECT DISTINCT ru.run_id, ru.host, ru.pid, ru.ended_utc IS NOT NULL FROM " +
      TableName(table) +
      " p JOIN runs ru ON ru.run_id = p.run_id WHERE p.study_id = ? AND p.status = 'running'");
  running.Bind(1, study_id);
  std::vector<std::int64_t> stale_runs;
  while (running.Step()) {
    const bool ended = running.GetInt(3) != 0;
    const bool same_host = running.GetText(1) == host;
    const auto pid = static_cast<pid_t>(running.GetInt(2));
    const bool process_gone = same_host && kill(pid, 0) != 0 && errno == ESRCH;
    if (ended || process_gone) stale_runs.push_back(running.GetInt(0));
  }
  int reclaimed = 0;
  Transaction t(db_);
  Statement reset = db_.Prepare("UPDATE " + TableName(table) +
                                " SET status = 'pending', updated_utc = ? "
                                "WHERE study_id = ? AND status = 'running' AND run_id = ?");
  for (auto run_id : stale_runs) {
    reset.Bind(1, UtcNow()).Bind(2, study_id).Bind(3, run_id);
    reset.Run();
    reclaimed += sqlite3_changes(db_.Raw());
  }
  t.Commit();
  return reclaimed;
}

std::vector<PointRow> StudyDatabase::PointsToCompute(std::int64_t study_id, bool retry_failed) {
  Statement s = db_.Prepare(
      "SELECT point_id, point_key, reference_key, r_k, r_ftrunc, scheme, dt_rule, dt_factor, "
      "dt_asked_s, window_s, n_elements_asked, mass_damping_per_s, status FROM points "
      "WHERE study_id = ? AND (status = 'pending' OR (? AND status = 'failed')) "
      "ORDER BY point_id");
  s.Bind(1, study_id).Bind(2, retry_failed ? 1 : 0);
  std::vector<PointRow> rows;
  while (s.Step()) {
    PointRow r;
    r.point_id = s.GetInt(0);
    PointParameters& p = r.parameters;
    p.point_key = s.GetText(1);
    p.reference_key = s.GetText(2);
    p.r_k = s.GetDouble(3);
    p.r_ftrunc = s.GetDouble(4);
    p.scheme = s.GetText(5);
    if (!s.IsNull(6)) p.dt_rule = s.GetText(6);
    p.dt_factor = s.GetOptionalDouble(7);
    p.dt_asked_s = s.GetOptionalDouble(8);
    p.window_s = s.GetDouble(9);
    p.n_elements_asked = static_cast<int>(s.GetInt(10));
    p.mass_damping_per_s = s.GetDouble(11);
    r.status = s.GetText(12);
    rows.push_back(std::move(r));
  }
  return rows;
}

void StudyDatabase::MarkRunning(const std::vector<std::int64_t>& point_ids, std::int64_t run_id,
                                PointTable table) {
  Transaction t(db_);
  Statement s = db_.Prepare("UPDATE " + TableName(table) +
                            " SET status = 'running', run_id = ?, message = '', updated_utc = ? "
                            "WHERE point_id = ?");
  const std::string now = UtcNow();
  for (auto id : point_ids) {
    s.Bind(1, run_id).Bind(2, now).Bind(3, id);
    s.Run();
  }
  t.Commit();
}

void StudyDatabase::StoreResult(std::int64_t point_id, std::int64_t run_id,
                                const std::string& status, const std::string& message,
                                const std::optional<ScoreRow>& score) {
  Transaction t(db_);
  db_.Prepare("DELETE FROM scores WHERE point_id = ?").Bind(1, point_id).Run();
  if (score) {
    const ScoreRow& c = *score;
    Statement insert = db_.Prepare(
        "INSERT INTO scores(point_id, reference_id, err, srf, n_modes, n_elements, n_dofs, "
        "dt_requested_s, dt_used_s, dt_paper_s, dt_sharp_s, steps, wall_s, cpu_s, "
        "max_energy_ratio, n_shocks, first_shock_start_s, first_shock_impulse_n_s, "
        "first_shock_peak_n, first_shock_duration_s, first_shock_rebounds, shocks_json) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    insert.Bind(1, point_id)
        .Bind(2, c.reference_id)
        .Bind(3, c.err)
        .Bind(4, c.srf)
        .Bind(5, c.n_modes)
        .Bind(6, c.n_elements)
        .Bind(7, c.n_dofs)
        .Bind(8, c.dt_requested_s)
        .Bind(9, c.dt_used_s)
        .Bind(10, c.dt_paper_s)
        .Bind(11, c.dt_sharp_s)
        .Bind(12, c.steps)
        .Bind(13, c.wall_s)
        .Bind(14, c.cpu_s)
        .Bind(15, c.max_energy_ratio)
        .Bind(16, c.n_shocks);
    if (c.first_shock) {
      insert.Bind(17, c.first_shock->start_s)
          .Bind(18, c.first_shock->impulse_n_s)
          .Bind(19, c.first_shock->peak_n)
          .Bind(20, c.first_shock->duration_s)
          .Bind(21, c.first_shock->rebounds);
    } else {
      for (int i = 17; i <= 21; ++i) insert.BindNull(i);
    }
    insert.Bind(22, c.shocks_json).Run();
  }
  db_.Prepare(
         "UPDATE points SET status = ?, message = ?, run_id = ?, updated_utc = ? "
         "WHERE point_id = ?")
      .Bind(1, status)
      .Bind(2, message)
      .Bind(3, run_id)
      .Bind(4, UtcNow())
      .Bind(5, point_id)
      .Run();
  db_.Prepare("UPDATE runs SET points_done = points_done + 1 WHERE run_id = ?")
      .Bind(1, run_id)
      .Run();
  t.Commit();
}

std::optional<ReferenceRow> StudyDatabase::FindReference(const std::string& reference_key) {
  Statement s = db_.Prepare(
      "SELECT reference_id, r_k, r_fref, r_fref_check, window_s, convergence, n_modes_free, "
      "n_modes_contact, n_transitions, wall_s, output_dt_s, tip_m, force_n, shocks_json "
      "FROM reference_runs WHERE reference_key = ?");
  s.Bind(1, reference_key);
  if (!s.Step()) return std::nullopt;
  ReferenceRow r;
  r.reference_id = s.GetInt(0);
  r.reference_key = reference_key;
  r.r_k = s.GetDouble(1);
  r.r_fref = s.GetDouble(2);
  r.r_fref_check = s.GetDouble(3);
  r.window_s = s.GetDouble(4);
  r.convergence = s.GetDouble(5);
  r.n_modes_free = static_cast<int>(s.GetInt(6));
  r.n_modes_contact = static_cast<int>(s.GetInt(7));
  r.n_transitions = static_cast<int>(s.GetInt(8));
  r.wall_s = s.GetDouble(9);
  r.output_dt_s = s.GetDouble(10);
  r.tip_m = s.GetBlob(11);
  r.force_n = s.GetBlob(12);
  r.shocks_json = s.GetText(13);
  return r;
}

std::int64_t StudyDatabase::StoreReference(const ReferenceRow& r, std::int64_t run_id) {
  Transaction t(db_);
  db_.Prepare(
         "INSERT INTO reference_runs(reference_key, r_k, r_fref, r_fref_check, window_s, "
         "convergence, n_modes_free, n_modes_contact, n_transitions, wall_s, output_dt_s, tip_m, "
         "force_n, shocks_json, run_id, created_utc) "
         "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .Bind(1, r.reference_key)
      .Bind(2, r.r_k)
      .Bind(3, r.r_fref)
      .Bind(4, r.r_fref_check)
      .Bind(5, r.window_s)
      .Bind(6, r.convergence)
      .Bind(7, r.n_modes_free)
      .Bind(8, r.n_modes_contact)
      .Bind(9, r.n_transitions)
      .Bind(10, r.wall_s)
      .Bind(11, r.output_dt_s)
      .Bind(12, r.tip_m)
      .Bind(13, r.force_n)
      .Bind(14, r.shocks_json)
      .Bind(15, run_id)
      .Bind(16, UtcNow())
      .Run();
  const std::int64_t id = db_.LastInsertRowId();
  t.Commit();
  return id;
}

std::vector<StatusCount> StudyDatabase::CountByStatus(const std::optional<std::string>& study) {
  Statement s = db_.Prepare(
      "SELECT st.name, p.status, count(*) FROM (SELECT study_id, status FROM points UNION ALL "
      "SELECT study_id, status FROM scene_points) p JOIN studies st USING (study_id) "
      "WHERE ? IS NULL OR st.name = ? GROUP BY st.name, p.status ORDER BY st.name, p.status");
  s.Bind(1, study).Bind(2, study);
  std::vector<StatusCount> counts;
  while (s.Step()) counts.push_back({s.GetText(0), s.GetText(1), s.GetInt(2)});
  return counts;
}

}  // namespace shockmap

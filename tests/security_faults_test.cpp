// Faults that used to stall or corrupt a study: points held by a run that is gone (a restarted
// container, a reused pid), two runs on one database, a stopped run, and the signals that end
// a run. Each must leave every point stored once, every run row closed, and a clear word.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <thread>

#include "db/read_only_query.h"
#include "db/sqlite_handle.h"
#include "tests/database_rows.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::Count;
using testing::kInterruptibleStudy;
using testing::ReadBytes;
using testing::RunShockmap;
using testing::WriteText;

class StudyFaults : public testing::TempDirTest {
 protected:
  std::string Spec(const char* json) {
    const std::string spec = Path("study.json");
    WriteText(spec, json);
    return spec;
  }
};

// Eight explicit points with cheap references: a fraction of a second in all.
constexpr const char* kSmallStudy = R"({
  "name": "small",
  "scoring": {"window_s": 0.02, "reference": {"r_fref_min": 300, "r_fref_per_sqrt_rk": 3}},
  "grids": [{"rk": [10, 100, 1000, 3000], "rftrunc": [10, 30]}]
})";

std::map<std::string, std::string> Outcomes(const std::string& db) {
  const Table r = RunReadOnlyQuery(
      db,
      "SELECT p.point_key, p.status || ' ' || quote(s.err) || ' ' || quote(s.srf) || ' ' || "
      "quote(s.steps) FROM points p LEFT JOIN scores s USING (point_id)");
  std::map<std::string, std::string> m;
  for (const auto& row : r.rows) m[std::get<std::string>(row[0])] = std::get<std::string>(row[1]);
  return m;
}

// `shockmap study run SPEC --db DB --quiet` in a child process writing its output to `log`.
pid_t StartStudy(const std::string& spec, const std::string& db, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    freopen(log.c_str(), "w", stdout);
    dup2(fileno(stdout), fileno(stderr));
    execl(SHOCKMAP_BIN, SHOCKMAP_BIN, "study", "run", spec.c_str(), "--db", db.c_str(), "--jobs",
          "2", "--quiet", static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// Waits until `db` holds at least `stored` finished points (or 60 s pass).
void WaitForStoredPoints(const std::string& db, std::int64_t stored) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    try {
      if (Count(db, "SELECT count(*) FROM points WHERE status NOT IN ('pending', 'running')") >=
          stored)
        return;
    } catch (const std::exception&) {
      // Not created or not migrated yet.
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

// A live run of another host (node-17, pid 4242, heartbeat now) holds `db`'s lease.
void HoldByAnotherHost(const std::string& db) {
  Connection c(db, Connection::Mode::kReadWriteCreate);
  c.Execute(
      "INSERT INTO runs(study_id, code_version, compiler, build_type, host, pid, jobs, "
      "started_utc, heartbeat_unix_s) SELECT study_id, 'x', 'x', 'x', 'node-17', 4242, 1, "
      "'2026-01-01T00:00:00.000Z', unixepoch('now') FROM studies");
}

int ExitCodeOf(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// After a container restart the host name and the pid namespace change: the points left
// 'running' belong to a run whose process cannot be checked, but whose heartbeat stopped.
TEST_F(StudyFaults, PointsOfARunGoneWithItsContainerAreTakenOverOnceItsHeartbeatIsOld) {
  const std::string spec = Spec(kSmallStudy), db = Path("s.db");
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + db + " --quiet").exit_code, 0);
  const auto whole = Outcomes(db);
  {
    Connection c(db, Connection::Mode::kReadWriteCreate);
    // pid 1 exists in every namespace: the old same-host liveness check would trust it.
    c.Execute(
        "INSERT INTO runs(study_id, code_version, compiler, build_type, host, pid, jobs, "
        "started_utc, heartbeat_unix_s) SELECT study_id, 'x', 'x', 'x', 'old-container', 1, 1, "
        "'2026-01-01T00:00:00.000Z', 1000 FROM studies");
    c.Execute("UPDATE points SET status = 'running', run_id = last_insert_rowid()");
    c.Execute("DELETE FROM scores");
  }
  const auto rerun = RunShockmap("study run " + spec + " --db " + db + " --quiet");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_NE(rerun.output.find("8 computed now"), std::string::npos) << rerun.output;
  EXPECT_NE(rerun.output.find("resumed      8 points"), std::string::npos) << rerun.output;
  EXPECT_EQ(Outcomes(db), whole);
  EXPECT_EQ(Count(db, "SELECT count(*) FROM runs WHERE ended_utc IS NULL"), 0);
}

// A run whose heartbeat is recent holds the database, wherever it runs: a second run is
// refused with the holder's host and pid, writes nothing, and `study status` names it.
TEST_F(StudyFaults, ASecondWriterIsRefusedNamingTheHolderAndWritesNothing) {
  const std::string spec = Spec(kSmallStudy), db = Path("s.db");
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + db + " --quiet").exit_code, 0);
  HoldByAnotherHost(db);
  {
    Connection c(db, Connection::Mode::kReadWriteCreate);
    c.Execute("UPDATE points SET status = 'pending' WHERE point_id = 1");
  }
  const std::string before = ReadBytes(db);
  const auto refused = RunShockmap("study run " + spec + " --db " + db + " --quiet");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("host node-17, pid 4242"), std::string::npos) << refused.output;
  EXPECT_EQ(refused.output.find("UNIQUE"), std::string::npos) << refused.output;
  EXPECT_EQ(Count(db, "SELECT count(*) FROM points WHERE status = 'pending'"), 1);
  EXPECT_EQ(Count(db, "SELECT count(*) FROM runs"), 2);
  const auto status = RunShockmap("study status --db " + db);
  EXPECT_NE(status.output.find("being written by run 2 (host node-17, pid 4242)"),
            std::string::npos)
      << status.output;
}

// A run refused because another holds the database writes nothing at all, whatever it asks:
// neither another study's registration, nor an extended grid's new points, nor a changed
// threshold in the stored study file (which `criteria derive` would then judge with).
TEST_F(StudyFaults, ARefusedRunRegistersNothingAndLeavesTheStoredStudyFileAsItWas) {
  const std::string spec = Spec(kSmallStudy), db = Path("s.db");
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + db + " --quiet").exit_code, 0);
  HoldByAnotherHost(db);
  const std::string before = ReadBytes(db);
  const auto stored = [&] {
    return testing::Rows(db, "SELECT name, spec_json, updated_utc FROM studies ORDER BY name");
  };
  const auto studies = stored();
  const std::string other = R"({
    "name": "other",
    "grids": [{"rk": [10, 100], "rftrunc": [10, 30, 100]}]
  })";
  const std::string extended = R"({
    "name": "small",
    "scoring": {"window_s": 0.02, "reference": {"r_fref_min": 300, "r_fref_per_sqrt_rk": 3}},
    "grids": [{"rk": [10, 100, 1000, 3000, 10000], "rftrunc": [10, 30, 100]}]
  })";
  const std::string rethresholded = R"({
    "name": "small",
    "scoring": {"window_s": 0.02, "reference": {"r_fref_min": 300, "r_fref_per_sqrt_rk": 3},
                "thresholds": {"err_max": 0.5}},
    "grids": [{"rk": [10, 100, 1000, 3000], "rftrunc": [10, 30]}]
  })";
  for (const std::string& json : {other, extended, rethresholded}) {
    const std::string changed = Path("changed.json");
    WriteText(changed, json);
    const auto refused = RunShockmap("study run " + changed + " --db " + db + " --quiet");
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(refused.output.find("one writer at a time"), std::string::npos) << refused.output;
    EXPECT_EQ(stored(), studies) << json;
    EXPECT_EQ(Count(db, "SELECT count(*) FROM points"), 8) << json;
    EXPECT_TRUE(ReadBytes(db) == before) << json;
  }
}

// Twenty times, two runs start together on a fresh database: no raw SQLite error, every point
// computed and stored once, every run row closed.
TEST_F(StudyFaults, TwoRunsStartedTogetherNeverComputeAPointTwice) {
  const std::string spec = Spec(kSmallStudy);
  for (int trial = 0; trial < 20; ++trial) {
    const std::string db = Path("t" + std::to_string(trial) + ".db");
    const std::string log_a = Path("a.log"), log_b = Path("b.log");
    const pid_t a = StartStudy(spec, db, log_a), b = StartStudy(spec, db, log_b);
    const int code_a = ExitCodeOf(a), code_b = ExitCodeOf(b);
    const std::string out = ReadBytes(log_a) + ReadBytes(log_b);
    for (const char* raw : {"UNIQUE", "already exists", "(in: "}) {
      EXPECT_EQ(out.find(raw), std::string::npos) << "trial " << trial << ": " << out;
    }
    EXPECT_TRUE(code_a == 0 || code_b == 0) << out;
    for (int code : {code_a, code_b}) {
      if (code != 0) {
        EXPECT_EQ(code, 2) << out;
        EXPECT_NE(out.find("is writing this database"), std::string::npos) << out;
      }
    }
    EXPECT_EQ(Count(db, "SELECT count(*) FROM points WHERE status IN ('pending', 'running')"), 0);
    EXPECT_EQ(Count(db, "SELECT sum(points_done) FROM runs"), 8) << "trial " << trial;
    EXPECT_EQ(Count(db, "SELECT count(*) FROM runs WHERE ended_utc IS NULL"), 0);
  }
}

// A stopped (SIGSTOP) run still holds the database while its heartbeat is within the grace
// period: a second run is refused, and the stopped one completes once continued.
TEST_F(StudyFaults, AStoppedRunIsNamedAndFinishesWhenContinued) {
  const std::string spec = Spec(kInterruptibleStudy), db = Path("s.db");
  const pid_t pid = StartStudy(spec, db, Path("run.log"));
  WaitForStoredPoints(db, 2);
  kill(pid, SIGSTOP);
  const auto second = RunShockmap("study run " + spec + " --db " + db + " --quiet");
  kill(pid, SIGCONT);
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("pid " + std::to_string(pid)), std::string::npos) << second.output;
  EXPECT_EQ(ExitCodeOf(pid), 0) << ReadBytes(Path("run.log"));
  EXPECT_EQ(Count(db, "SELECT count(*) FROM points WHERE status IN ('pending', 'running')"), 0);
}

// SIGTERM, SIGINT and SIGHUP end a run cleanly: what was stored is said, the run row is
// closed as interrupted, no point stays 'running', and a rerun completes the study with the
// outcomes of an uninterrupted run.
TEST_F(StudyFaults, SignalsEndARunCleanlyAndTheRerunCompletesIt) {
  const std::string spec = Spec(kInterruptibleStudy), whole = Path("whole.db");
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + whole + " --quiet").exit_code, 0);
  for (const auto& [signal, name] :
       {std::pair{SIGTERM, "SIGTERM"}, std::pair{SIGINT, "SIGINT"}, std::pair{SIGHUP, "SIGHUP"}}) {
    const std::string db = Path(std::string(name) + ".db"), log = Path("run.log");
    const pid_t pid = StartStudy(spec, db, log);
    WaitForStoredPoints(db, 2);
    kill(pid, signal);
    EXPECT_EQ(ExitCodeOf(pid), 128 + signal) << name;
    const std::string out = ReadBytes(log);
    EXPECT_NE(out.find(std::string(name) + " received"), std::string::npos) << out;
    EXPECT_NE(out.find("run the study again to resume"), std::string::npos) << out;
    EXPECT_EQ(Count(db, "SELECT count(*) FROM points WHERE status = 'running'"), 0) << name;
    EXPECT_EQ(Count(db, "SELECT count(*) FROM runs WHERE end_reason = 'interrupted'"), 1) << name;
    const auto rerun = RunShockmap("study run " + spec + " --db " + db + " --quiet");
    ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
    EXPECT_EQ(Outcomes(db), Outcomes(whole)) << name;
  }
}

}  // namespace
}  // namespace shockmap

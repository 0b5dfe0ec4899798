// Studies on MPI ranks (docs/cluster.md): `mpirun -np 3 shockmap study run` stores what the
// threaded run stores; a worker rank or rank 0 killed with SIGKILL loses nothing, and a rerun
// completes the study; a worker rank stopped with SIGSTOP hangs nothing (its task goes to
// another rank, or the run ends interrupted when no rank is left), nor does `mpirun` after it
// (3 jobs, 20 in mpi_long_test, each ending with exit code 1); a second job on the database is
// refused naming the holder. Skipped in a build without MPI.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "db/read_only_query.h"
#include "tests/database_rows.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::Count;
using testing::kSlowStudy;
using testing::ReadBytes;
using testing::Rows;
using testing::RunShell;
using testing::RunShockmap;
using testing::WriteText;

constexpr const char* kMpiexec = SHOCKMAP_MPIEXEC;  // Empty without MPI.
// What a container on a 2-core machine needs (docs/cluster.md).
constexpr const char* kMpiFlags = "--allow-run-as-root --oversubscribe";
// The time between mpirun's SIGTERM and SIGKILL when a rank dies, which lets rank 0 record the
// tasks it got no answer for (the default, 1 s, is often too short on a loaded machine).
constexpr const char* kKillGraceFlags = "--mca odls_base_sigkill_timeout 3";
// The silence after which rank 0 gives up on a stopped rank in these tests (default 60 s), and
// how long the job's ranks may take to end after the stop: the timeout, the rest of
// quick.json on one worker rank and the end of the job, on a loaded machine.
constexpr int kRankTimeoutS = 4;
constexpr auto kEndAfterStop = std::chrono::seconds(40);
// How long a job with a worker rank left stopped may take: quick.json, 2 s of silence, the rest
// on one worker rank and the end of the job, on a loaded machine (7 to 8 s on 2 busy cores).
constexpr auto kStoppedJobLimit = std::chrono::seconds(60);

constexpr const char* kCanonicalRows =
    "SELECT point_id || '|' || status || '|' || quote(err) || '|' || quote(srf) || '|' || "
    "quote(steps) || '|' || quote(n_modes) FROM results ORDER BY point_id";
constexpr const char* kDone =
    "SELECT count(*) FROM points WHERE status NOT IN ('pending', 'running')";
constexpr const char* kSceneRows =
    "SELECT point_id || '|' || status || '|' || quote(err) || '|' || quote(srf) || '|' || "
    "quote(steps) || '|' || quote(coordinates) FROM scene_results ORDER BY point_id";

std::string Source(const std::string& relative) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
}

// Every column of the `results` view but those that differ between runs of the same points
// (times, where and when they were computed), one row per point.
std::vector<std::string> StoredResults(const std::string& db) {
  std::string columns;
  for (const std::string& c : Rows(db,
                                   "SELECT name FROM pragma_table_info('results') WHERE name "
                                   "NOT IN ('wall_s', 'cpu_s', 'ref_wall_s', 'host', 'rank', "
                                   "'updated_utc')")) {
    columns += (columns.empty() ? "quote(" : " || '|' || quote(") + c + ")";
  }
  return Rows(db, "SELECT " + columns + " FROM results ORDER BY point_id");
}

// Count, or -1 while the file is still being created.
std::int64_t CountSoFar(const std::string& db, const std::string& sql) {
  try {
    return std::filesystem::exists(db) ? Count(db, sql) : -1;
  } catch (const std::exception&) {
    return -1;
  }
}

std::string MpiRun(int ranks, const std::string& args, const std::string& flags = "") {
  return std::string(kMpiexec) + " " + kMpiFlags + " " + flags + " -np " + std::to_string(ranks) +
         " " + SHOCKMAP_BIN + " " + args;
}

// The command in a child process with its output in `log`; its pid.
pid_t Start(const std::string& command, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command + " >" + log + " 2>&1").c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// The wait status of the child `pid` once it ends, or nullopt when it runs past `limit` (it
// is then killed).
std::optional<int> WaitAtMost(pid_t pid, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return std::nullopt;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return status;
}

// Whether process `pid` has ended: gone, or a zombie its parent has not reaped.
bool Ended(pid_t pid) {
  const std::string stat = ReadBytes("/proc/" + std::to_string(pid) + "/stat");
  const auto close = stat.rfind(')');
  return close == std::string::npos || stat.compare(close, 3, ") Z") == 0;
}

// Waits until every process in `pids` has ended; false when `limit` passes first.
bool AllEndWithin(const std::vector<pid_t>& pids, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!std::ranges::all_of(pids, Ended)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// The pid of MPI rank `rank` among the children of `launcher`, or -1.
pid_t RankPid(pid_t launcher, int rank) {
  const std::string wanted = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string stat = ReadBytes(entry.path() / "stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos) continue;
    int parent = 0;
    char state = 0;
    if (std::sscanf(stat.c_str() + close + 1, " %c %d", &state, &parent) != 2) continue;
    if (parent != launcher) continue;
    std::string environ = ReadBytes(entry.path() / "environ");
    for (auto& c : environ) c = c == '\0' ? '\n' : c;
    if (("\n" + environ).find("\n" + wanted + "\n") != std::string::npos) return std::stoi(name);
  }
  return -1;
}

class MpiStudy : public testing::TempDirTest {
 protected:
  void SetUp() override {
    if (std::string(kMpiexec).empty()) GTEST_SKIP() << "built without MPI";
    TempDirTest::SetUp();
  }

  // Sends `signal` to MPI rank `rank` of `launcher` once `db` has `stored` points done; the
  // rank's pid, or -1 when the study ended first.
  pid_t SignalRankOnceStored(pid_t launcher, int rank, const std::string& db, std::int64_t stored,
                             int signal);
  // Runs quick.json under mpirun on `ranks` ranks with a short rank timeout and SIGSTOPs rank
  // `rank` once 60 points are stored, then wakes it once rank 0 has named it (so that it sends
  // a late result): every rank ends within kEndAfterStop, mpirun 10 s later at most with exit code
  // 1 (MPI_Abort), rank 0 naming the stopped rank and the point it held in `log`; the database is
  // sound, no point left running, the run row closed.
  void StopRank(int ranks, int rank, const std::string& db, const std::string& log);
  // Runs quick.json `jobs` times under mpirun on 3 ranks with a 2 s rank timeout and leaves
  // rank 2 stopped once 150 points are stored (or at the end of the job): each job ends within
  // kStoppedJobLimit with exit code 1 (MPI_Abort), rank 0 naming the rank, the run row closed.
  // Open MPI 4.1's mpirun, aborting a job some of whose ranks waited in MPI_Finalize, would
  // deadlock or crash in its own PMIx_server_finalize (docs/cluster.md). Prints each job's
  // ending and time.
  void EndJobsWithAStoppedWorkerRank(int jobs);
  // The stored results of a threaded run of quick.json on 2 threads.
  std::vector<std::string> ThreadedResults();

  // Runs quick.json under mpirun on 3 ranks, SIGKILLs `rank` once `stored` points are stored,
  // then reruns the study: every point once, a sound file, the outcomes of a threaded run. The
  // rerun says how the killed job ended (one of `endings`).
  void KillRankAndRerun(int rank, std::int64_t stored, const std::string& flags,
                        const std::vector<std::string>& endings);
};

TEST_F(MpiStudy, ThreeRanksStoreTheThreadedRunsResults) {
  const std::string spec = Source("studies/quick.json");
  const auto local = RunShockmap("study run " + spec + " --db " + Path("t.db") + " --quiet");
  ASSERT_EQ(local.exit_code, 0) << local.output;
  const auto mpi = RunShell(MpiRun(3, "study run " + spec + " --db " + Path("m.db") + " --quiet"));
  ASSERT_EQ(mpi.exit_code, 0) << mpi.output;
  EXPECT_NE(mpi.output.find("2 worker ranks x 1 thread)"), std::string::npos) << mpi.output;
  const auto threaded = Rows(Path("t.db"), kCanonicalRows);
  ASSERT_EQ(threaded.size(), 308u);
  EXPECT_EQ(Rows(Path("m.db"), kCanonicalRows), threaded);
  // Provenance: the workers computed every point, rank 0 none.
  EXPECT_EQ(Count(Path("m.db"), "SELECT count(*) FROM results WHERE rank IN (1, 2)"), 308);
  EXPECT_EQ(Count(Path("t.db"), "SELECT count(*) FROM results WHERE rank = 0"), 308);
  const auto status = RunShockmap("study status --db " + Path("m.db"));
  EXPECT_NE(status.output.find("rank"), std::string::npos) << status.output;
}

TEST_F(MpiStudy, SceneStudyOnThreeRanksStoresTheThreadedRunsResults) {
  const std::string spec = Source("studies/bundle_row_truncation.json");
  const auto local = RunShockmap("study run " + spec + " --db " + Path("t.db") + " --quiet");
  ASSERT_EQ(local.exit_code, 0) << local.output;
  const auto mpi =
      RunShell(MpiRun(3, "study run " + spec + " --db " + Path("m.db") + " --jobs 2 --quiet"));
  ASSERT_EQ(mpi.exit_code, 0) << mpi.output;
  const auto threaded = Rows(Path("t.db"), kSceneRows);
  ASSERT_EQ(threaded.size(), 16u);
  EXPECT_EQ(Rows(Path("m.db"), kSceneRows), threaded);
}

void MpiStudy::KillRankAndRerun(int rank, std::int64_t stored, const std::string& flags,
                                const std::vector<std::string>& endings) {
  const std::string spec = Source("studies/quick.json"), db = Path("k.db");
  const auto whole = RunShockmap("study run " + spec + " --db " + Path("t.db") + " --quiet");
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const pid_t launcher =
      Start(MpiRun(3, "study run " + spec + " --db " + db + " --quiet", flags), Path("killed.log"));
  const bool killed = SignalRankOnceStored(launcher, rank, db, stored, SIGKILL) > 0;
  int status = 0;
  waitpid(launcher, &status, 0);
  const std::string log = ReadBytes(Path("killed.log"));
  ASSERT_TRUE(killed) << log;
  ASSERT_LT(Count(db, kDone), 308) << "the study finished before the kill landed\n" << log;
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << log;
  EXPECT_NE(log.find("rank " + std::to_string(rank)), std::string::npos) << log;
  EXPECT_EQ(Count(db, "SELECT count(*) FROM points"), 308);
  EXPECT_EQ(Rows(db, "PRAGMA integrity_check"), std::vector<std::string>{"ok"});

  const auto rerun = RunShell(MpiRun(3, "study run " + spec + " --db " + db + " --quiet"));
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_TRUE(std::ranges::any_of(endings, [&](const std::string& ending) {
    return rerun.output.find(ending) != std::string::npos;
  })) << rerun.output;
  EXPECT_EQ(Rows(db, "PRAGMA integrity_check"), std::vector<std::string>{"ok"});
  EXPECT_EQ(Count(db, "SELECT count(*) FROM points"), 308);
  EXPECT_EQ(Count(db, "SELECT count(*) FROM scores"), 308);
  EXPECT_EQ(Count(db, kDone), 308);
  EXPECT_EQ(Rows(db, kCanonicalRows), Rows(Path("t.db"), kCanonicalRows));
}

pid_t MpiStudy::SignalRankOnceStored(pid_t launcher, int rank, const std::string& db,
                                     std::int64_t stored, int signal) {
  for (int i = 0; i < 6000; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (CountSoFar(db, kDone) < stored) continue;
    const pid_t target = RankPid(launcher, rank);
    if (target > 0 && kill(target, signal) == 0) return target;
  }
  return -1;
}

void MpiStudy::StopRank(int ranks, int rank, const std::string& db, const std::string& log) {
  const pid_t launcher =
      Start(MpiRun(ranks, "study run " + Source("studies/quick.json") + " --db " + db +
                              " --quiet --rank-timeout-s " + std::to_string(kRankTimeoutS)),
            log);
  const pid_t stopped = SignalRankOnceStored(launcher, rank, db, 60, SIGSTOP);
  std::vector<pid_t> job;
  for (int r = 0; r < ranks; ++r) job.push_back(RankPid(launcher, r));
  const std::string named = "rank " + std::to_string(rank) + " (host ";
  for (int i = 0; i < 3000 && stopped > 0 && ReadBytes(log).find(named) == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (stopped > 0) kill(stopped, SIGCONT);
  const bool ended = AllEndWithin(job, kEndAfterStop);
  const std::optional<int> status = WaitAtMost(launcher, std::chrono::seconds(10));
  const std::string output = ReadBytes(log);
  ASSERT_GT(stopped, 0) << output;
  ASSERT_TRUE(std::ranges::none_of(job, [](pid_t p) { return p <= 0; })) << output;
  ASSERT_TRUE(ended) << "the job still ran " << kEndAfterStop.count() << " s after a rank stopped\n"
                     << output;
  ASSERT_TRUE(status) << "mpirun still ran 10 s after every rank had ended\n" << output;
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 1) << output;
  EXPECT_NE(output.find(named), std::string::npos) << output;
  EXPECT_NE(output.find(" s, holding point "), std::string::npos) << output;
  EXPECT_EQ(Rows(db, "PRAGMA integrity_check"), std::vector<std::string>{"ok"});
  EXPECT_EQ(Count(db, "SELECT count(*) FROM points"), 308);
  EXPECT_EQ(Count(db, "SELECT count(*) FROM points WHERE status = 'running'"), 0);
  EXPECT_EQ(Count(db, "SELECT count(*) FROM runs WHERE ended_utc IS NULL"), 0);
}

std::vector<std::string> MpiStudy::ThreadedResults() {
  const auto threaded = RunShockmap("study run " + Source("studies/quick.json") + " --db " +
                                    Path("t.db") + " --jobs 2 --quiet");
  EXPECT_EQ(threaded.exit_code, 0) << threaded.output;
  return StoredResults(Path("t.db"));
}

TEST_F(MpiStudy, WorkerRankKilledWithSigkillLosesNothingAndARerunCompletes) {
  // mpirun names the dead rank and ends the job with SIGTERM; rank 0 stores which tasks got
  // no answer (its own output is no longer shown by then). On a loaded machine mpirun's
  // SIGKILL may come before rank 0 has stored that: the rerun then takes the points over as
  // from a killed run. Either way nothing is lost.
  KillRankAndRerun(2, 60, kKillGraceFlags,
                   {"interrupted: SIGTERM received; no answer for point ", "was killed"});
}

TEST_F(MpiStudy, RankZeroKilledWithSigkillResumesLikeALocalRun) {
  KillRankAndRerun(0, 60, "", {"was killed"});
}

TEST_F(MpiStudy, StoppedWorkerRankLosesItsTaskToAnotherRankAndItsLateResultIsDropped) {
  const std::string db = Path("s.db"), log = Path("stopped.log");
  StopRank(3, 2, db, log);
  EXPECT_NE(ReadBytes(log).find("it gets no more work, its tasks go to the other ranks"),
            std::string::npos)
      << ReadBytes(log);
  // Rank 1 computed the rest, the stopped rank's point included, each stored once.
  EXPECT_EQ(Count(db, kDone), 308);
  EXPECT_EQ(Count(db, "SELECT count(*) FROM scores"), 308);
  EXPECT_EQ(Rows(db, "SELECT end_reason FROM runs"), std::vector<std::string>{"completed"});
  const auto rerun =
      RunShell(MpiRun(3, "study run " + Source("studies/quick.json") + " --db " + db + " --quiet"));
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_NE(rerun.output.find("nothing to compute"), std::string::npos) << rerun.output;
  EXPECT_EQ(StoredResults(db), ThreadedResults());
}

TEST_F(MpiStudy, StoppedLastWorkerRankEndsTheRunInterruptedAndARerunCompletes) {
  const std::string db = Path("s.db"), log = Path("stopped.log");
  StopRank(2, 1, db, log);
  const std::string output = ReadBytes(log);
  EXPECT_NE(output.find("shockmap: no worker rank answers: rank 1 (host "), std::string::npos)
      << output;
  EXPECT_NE(output.find("the run is interrupted, the points stored are kept"), std::string::npos)
      << output;
  EXPECT_LT(Count(db, kDone), 308);
  EXPECT_EQ(Rows(db, "SELECT end_reason FROM runs"), std::vector<std::string>{"interrupted"});
  const auto rerun =
      RunShell(MpiRun(3, "study run " + Source("studies/quick.json") + " --db " + db + " --quiet"));
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_NE(rerun.output.find("interrupted: no worker rank answers: rank 1 (host "),
            std::string::npos)
      << rerun.output;
  EXPECT_EQ(Count(db, kDone), 308);
  EXPECT_EQ(Count(db, "SELECT count(*) FROM scores"), 308);
  EXPECT_EQ(StoredResults(db), ThreadedResults());
}

void MpiStudy::EndJobsWithAStoppedWorkerRank(int jobs) {
  const std::string spec = Source("studies/quick.json");
  std::vector<std::string> endings;
  for (int job = 1; job <= jobs; ++job) {
    const std::string db = Path("r" + std::to_string(job) + ".db");
    const std::string log = Path("r" + std::to_string(job) + ".log");
    const auto start = std::chrono::steady_clock::now();
    const pid_t launcher =
        Start(MpiRun(3, "study run " + spec + " --db " + db + " --quiet --rank-timeout-s 2"), log);
    const pid_t stopped = SignalRankOnceStored(launcher, 2, db, 150, SIGSTOP);
    const std::optional<int> status = WaitAtMost(launcher, kStoppedJobLimit);
    if (stopped > 0) kill(stopped, SIGKILL);  // Left behind by a launcher killed as hung.
    const double took_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string output = ReadBytes(log);
    ASSERT_GT(stopped, 0) << output;
    const std::string ending = !status ? "hung, killed"
                               : WIFSIGNALED(*status)
                                   ? "signal " + std::to_string(WTERMSIG(*status))
                                   : "exit " + std::to_string(WEXITSTATUS(*status));
    endings.push_back(ending + fmt::format(" ({:.1f} s)", took_s));
    EXPECT_EQ(ending, "exit 1") << "job " << job << "\n" << output;
    EXPECT_NE(output.find("rank 2 (host "), std::string::npos) << output;
    EXPECT_EQ(Count(db, "SELECT count(*) FROM runs WHERE ended_utc IS NULL"), 0);
  }
  for (std::size_t job = 0; job < endings.size(); ++job) {
    std::cerr << "job " << job + 1 << ": " << endings[job] << "\n";
  }
}

#ifdef SHOCKMAP_MPI_LONG
TEST_F(MpiStudy, TwentyJobsWithAStoppedWorkerRankEachEndWithExitCodeOne) {
  EndJobsWithAStoppedWorkerRank(20);
}
#else
TEST_F(MpiStudy, ThreeJobsWithAStoppedWorkerRankEachEndWithExitCodeOne) {
  EndJobsWithAStoppedWorkerRank(3);
}
#endif

// The MPI flags are checked in every build, with or without MPI.
class MpiFlags : public testing::TempDirTest {};

TEST_F(MpiFlags, RankTimeoutUnderTwoSecondsIsRefusedBeforeTheDatabaseIsTouched) {
  const std::string db = Path("r.db");
  for (const char* value : {"1", "nan", "abc"}) {
    const auto r = RunShockmap("study run " + Source("studies/quick.json") + " --db " + db +
                               " --rank-timeout-s " + value);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--rank-timeout-s: value"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(db));
}

TEST_F(MpiStudy, SecondJobOnTheDatabaseIsRefusedNamingTheHolder) {
  // The slow study: the first job must still hold the database when the second one starts.
  const std::string spec = Path("slow.json"), db = Path("l.db");
  WriteText(spec, kSlowStudy);
  const pid_t launcher =
      Start(MpiRun(3, "study run " + spec + " --db " + db + " --quiet"), Path("first.log"));
  pid_t holder = -1;
  for (int i = 0; i < 2000 && holder < 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (CountSoFar(db, "SELECT count(*) FROM runs WHERE ended_utc IS NULL") > 0) {
      holder = RankPid(launcher, 0);
    }
  }
  const auto second = RunShell(MpiRun(2, "study run " + spec + " --db " + db + " --quiet"));
  int status = 0;
  waitpid(launcher, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ReadBytes(Path("first.log"));
  EXPECT_NE(second.exit_code, 0) << second.output;
  EXPECT_NE(second.output.find("is writing this database"), std::string::npos) << second.output;
  EXPECT_NE(second.output.find("pid " + std::to_string(holder) + ")"), std::string::npos)
      << second.output;
}

}  // namespace
}  // namespace shockmap

// Studies on MPI ranks (docs/cluster.md): `mpirun -np 3 shockmap study run` stores what the
// threaded run stores; a worker rank or rank 0 killed with SIGKILL loses nothing, and a rerun
// completes the study; a second job on the database is refused naming the holder. Skipped in a
// build without MPI.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

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

constexpr const char* kCanonicalRows =
    "SELECT point_id || '|' || status || '|' || quote(err) || '|' || quote(srf) || '|' || "
    "quote(steps) || '|' || quote(n_modes) FROM results ORDER BY point_id";
constexpr const char* kSceneRows =
    "SELECT point_id || '|' || status || '|' || quote(err) || '|' || quote(srf) || '|' || "
    "quote(steps) || '|' || quote(coordinates) FROM scene_results ORDER BY point_id";

std::string Source(const std::string& relative) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
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
  const std::string done = "SELECT count(*) FROM points WHERE status NOT IN ('pending', 'running')";
  bool killed = false;
  for (int i = 0; i < 6000 && !killed; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (CountSoFar(db, done) < stored) continue;
    const pid_t target = RankPid(launcher, rank);
    killed = target > 0 && kill(target, SIGKILL) == 0;
  }
  int status = 0;
  waitpid(launcher, &status, 0);
  const std::string log = ReadBytes(Path("killed.log"));
  ASSERT_TRUE(killed) << log;
  ASSERT_LT(Count(db, done), 308) << "the study finished before the kill landed\n" << log;
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
  EXPECT_EQ(Count(db, done), 308);
  EXPECT_EQ(Rows(db, kCanonicalRows), Rows(Path("t.db"), kCanonicalRows));
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

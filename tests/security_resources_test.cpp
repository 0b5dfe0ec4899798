// Hangs, resources and signals: a database whose views another program redefined, a database
// path that is a FIFO or a device, an ensemble window of more steps than any run may take, and
// a signal or a second run while pictures are drawn. Each must end promptly with a clear word,
// exit 2, and leave what was on disk as it was.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <vector>

#include "db/result_views.h"
#include "db/schema.h"
#include "db/sqlite_handle.h"
#include "tests/database_rows.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::Outcome;
using testing::ReadBytes;
using testing::RunShell;
using testing::RunShockmap;
using testing::WriteText;

// Eight explicit points with cheap references: a fraction of a second in all.
constexpr const char* kSmallStudy = R"({
  "name": "small",
  "scoring": {"window_s": 0.02, "reference": {"r_fref_min": 300, "r_fref_per_sqrt_rk": 3}},
  "grids": [{"rk": [10, 100, 1000, 3000], "rftrunc": [10, 30]}]
})";

// `shockmap ARGS`, ended by SIGKILL after `seconds` so that a hang fails the test, not the suite.
Outcome RunBounded(const std::string& args, int seconds = 20) {
  return RunShell("timeout -s KILL " + std::to_string(seconds) + " " + SHOCKMAP_BIN + " " + args);
}

// The hidden temporary files shockmap leaves in `dir` (".shockmap-PID-N.tmp").
std::vector<std::string> Temporaries(const std::filesystem::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(".shockmap-")) found.push_back(entry.path().string());
  }
  return found;
}

class Resources : public testing::TempDirTest {
 protected:
  // A study database of kSmallStudy, computed.
  std::string SmallDatabase() {
    const std::string spec = Path("study.json"), db = Path("s.db");
    WriteText(spec, kSmallStudy);
    const Outcome run = RunShockmap("study run " + spec + " --db " + db + " --quiet");
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return db;
  }
};

// `results` redefined by another program: rows only after an endless recursive query.
constexpr const char* kEndlessResults = R"sql(
DROP VIEW results;
CREATE VIEW results AS
SELECT st.name AS study, p.point_id, p.r_k, p.r_ftrunc, p.scheme, p.dt_rule, p.dt_factor,
       p.dt_asked_s, p.window_s, p.mass_damping_per_s, p.status, p.message,
       sc.err, sc.srf, sc.n_modes, sc.n_elements, sc.n_dofs, sc.dt_requested_s, sc.dt_used_s,
       sc.dt_paper_s, sc.dt_sharp_s, sc.steps, sc.wall_s, sc.cpu_s, sc.max_energy_ratio,
       sc.n_shocks, sc.first_shock_start_s, sc.first_shock_impulse_n_s, sc.first_shock_peak_n,
       sc.first_shock_duration_s, sc.first_shock_rebounds,
       r.r_fref, r.r_fref_check, r.convergence AS ref_convergence,
       r.n_transitions AS ref_transitions, r.wall_s AS ref_wall_s,
       ru.code_version, p.host, p.rank, p.updated_utc, sc.srf_definition
FROM points p
JOIN studies st ON st.study_id = p.study_id
LEFT JOIN scores sc ON sc.point_id = p.point_id
LEFT JOIN reference_runs r ON r.reference_id = sc.reference_id
LEFT JOIN runs ru ON ru.run_id = p.run_id
WHERE EXISTS (WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n)
              SELECT 1 FROM n WHERE i < 0);
)sql";

TEST_F(Resources, RedefinedViewIsRefusedInsteadOfFollowed) {
  const std::string db = SmallDatabase();
  Connection(db, Connection::Mode::kReadWriteCreate).Execute(kEndlessResults);
  const std::string before = ReadBytes(db);
  for (const std::string& command : std::vector<std::string>{
           "criteria derive small", "map small --out " + Path("map.png"), "cost small",
           "report small --out " + Path("report"), "study status"}) {
    const auto start = std::chrono::steady_clock::now();
    const Outcome out = RunBounded(command + " --db " + db);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(out.exit_code, 2) << command << ": " << out.output;
    EXPECT_NE(out.output.find(db + ": view results is not the one shockmap writes"),
              std::string::npos)
        << command << ": " << out.output;
    EXPECT_LT(seconds, 10.0) << command;
  }
  EXPECT_FALSE(std::filesystem::exists(Path("map.png")));
  EXPECT_FALSE(std::filesystem::exists(Path("report/index.html")));
  EXPECT_TRUE(ReadBytes(db) == before) << db << " changed";
}

// A database of the previous schema version: its migrations, and the views as declared now.
std::string PreviousVersionDatabase(const std::string& path) {
  Connection db(path, Connection::Mode::kReadWriteCreate);
  for (int i = 0; i + 1 < kSchemaVersion; ++i) db.Execute(kMigrations[i]);
  CreateDeclaredViews(db);
  db.Execute("PRAGMA application_id = " + std::to_string(kApplicationId) +
             "; PRAGMA user_version = " + std::to_string(kSchemaVersion - 1));
  return path;
}

// A trigger runs inside the writer's statements, the migrations' included: refused at the
// current schema version and before migrating an older file.
TEST_F(Resources, ForeignTriggerIsRefusedBeforeAnyWrite) {
  for (const std::string& db : {SmallDatabase(), PreviousVersionDatabase(Path("older.db"))}) {
    Connection(db, Connection::Mode::kReadWriteCreate)
        .Execute(
            "CREATE TRIGGER erase AFTER UPDATE ON ensemble_members BEGIN DELETE FROM scores; END; "
            "CREATE TRIGGER erase_too AFTER INSERT ON runs BEGIN DELETE FROM scores; END;");
    const std::string before = ReadBytes(db);
    const Outcome out = RunBounded("study run " + Path("study.json") + " --db " + db + " --quiet");
    EXPECT_EQ(out.exit_code, 2) << db << ": " << out.output;
    EXPECT_NE(out.output.find(db + ": trigger erase"), std::string::npos) << out.output;
    EXPECT_NE(out.output.find("is not the one shockmap writes"), std::string::npos) << out.output;
    EXPECT_TRUE(ReadBytes(db) == before) << db << " changed";
  }
}

TEST_F(Resources, FifoDatabaseIsRefusedWithoutOpeningIt) {
  const std::string fifo = Path("fifo.db");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  WriteText(Path("study.json"), kSmallStudy);
  for (const std::string& command : std::vector<std::string>{
           "sizing", "study status", "criteria derive", "map", "report --out " + Path("r"),
           "query 'SELECT 1'", "study run " + Path("study.json") + " --quiet"}) {
    const Outcome out = RunBounded(command + " --db " + fifo, 10);
    EXPECT_EQ(out.exit_code, 2) << command << ": " << out.output;
    EXPECT_NE(out.output.find(fifo + ": not a regular file"), std::string::npos)
        << command << ": " << out.output;
  }
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 2);  // fifo, study
}

// A FIFO where SQLite keeps a journal beside the database: opening it would block as well.
TEST_F(Resources, FifoBesideTheDatabaseIsRefusedWithoutOpeningIt) {
  const std::string db = SmallDatabase();
  for (const char* beside : {"-journal", "-wal"}) {
    const std::string fifo = db + beside;
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const char* command : {"study status", "query 'SELECT 1'"}) {
      const Outcome out = RunBounded(std::string(command) + " --db " + db, 10);
      EXPECT_EQ(out.exit_code, 2) << command << ": " << out.output;
      EXPECT_NE(out.output.find(fifo + " is not a regular file"), std::string::npos)
          << command << ": " << out.output;
    }
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
    std::filesystem::remove(fifo);
  }
}

TEST_F(Resources, DeviceDatabaseIsRefusedBeforeSqliteWritesBesideIt) {
  WriteText(Path("study.json"), kSmallStudy);
  const bool journal_before = std::filesystem::exists("/dev/null-journal");
  const Outcome out = RunBounded("study run " + Path("study.json") + " --db /dev/null --quiet");
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("/dev/null: not a regular file"), std::string::npos) << out.output;
  if (!journal_before && std::filesystem::exists("/dev/null-journal")) {
    std::filesystem::remove("/dev/null-journal");
    ADD_FAILURE() << "the run created /dev/null-journal";
  }
}

TEST_F(Resources, EnsembleWindowOfTooManyStepsIsRefusedBeforeAnythingRuns) {
  const std::string spec = Path("long.json"), db = Path("long.db");
  WriteText(spec, std::string(R"({"kind": "scene_ensemble", "name": "long", "scene": ")") +
                      SHOCKMAP_SOURCE_DIR + R"(/scenes/bundle_row.json", "members": 3,
      "seed": 11, "window_s": 1e4,
      "draws": {"bundle.wire.stiffness_n_per_m": {"lognormal": {"sigma": 0.2}}}})");
  const Outcome out = RunBounded("study run " + spec + " --db " + db + " --quiet");
  EXPECT_EQ(out.exit_code, 2) << out.output;
  for (const std::string& expected : std::vector<std::string>{
           spec + ": window_s: 10000.0 s in state \"scene\"", "steps: must be <= 100000000"}) {
    EXPECT_NE(out.output.find(expected), std::string::npos) << expected << "\n" << out.output;
  }
  EXPECT_FALSE(std::filesystem::exists(db));
}

// A model that cannot be built at a checked scene (here a preload on a beam whose rotation about
// its pin no contact holds, at the draws' centres) refuses the file for that reason, naming the
// state and setting: its window is not to blame.
TEST_F(Resources, EnsembleModelNotBuiltAtACheckedSceneIsNotBlamedOnTheWindow) {
  const std::string scene = Path("pinned.json"), spec = Path("pinned_ensemble.json");
  WriteText(scene, R"({"name": "pinned", "beams": [{"name": "beam", "length_m": 1.0,
      "ei_n_m2": 1.5e5, "rho_a_kg_per_m": 127.0, "elements": 3, "ends": ["pinned", "free"]}],
    "zones": [{"name": "tip", "beam": "beam", "against": "stop", "height_m": 1.0,
      "normal": [-1, 0], "gap_m": -1e-5, "stiffness_n_per_m": 1.35e9}],
    "solver": {"r_ftrunc": 300, "dt": {"rule": "sharp", "factor": 0.1}, "end_time_s": 0.06},
    "outputs": {"max_contact_force": true}})");
  WriteText(spec, R"({"kind": "scene_ensemble", "name": "pinned", "scene": ")" + scene +
                      R"(", "members": 2, "seed": 1, "window_s": 0.001,
      "draws": {"zones.0.stiffness_n_per_m": {"lognormal": {"sigma": 0.1}}}})");
  const Outcome out = RunBounded("study run " + spec + " --db " + Path("p.db") + " --quiet");
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find(spec + ": state \"scene\", setting {}: zones with a negative gap "
                                   "(preloaded contacts): the model has a rigid-body mode"),
            std::string::npos)
      << out.output;
  EXPECT_EQ(out.output.find("window_s"), std::string::npos) << out.output;
}

// The planar bundle over 5 ms, one state: a member takes a few hundredths of a second.
std::string TinyEnsemble(int members) {
  return std::string(R"({"kind": "scene_ensemble", "name": "tiny", "scene": ")") +
         SHOCKMAP_SOURCE_DIR + R"(/scenes/bundle_row.json", "members": )" +
         std::to_string(members) + R"(, "seed": 11, "window_s": 0.005,
      "draws": {"bundle.wire.stiffness_n_per_m": {"lognormal": {"sigma": 0.2}}}})";
}

// Each member row used to repeat its nominal run's key, the whole scene as JSON (2.5 kB for the
// bundle): a million members wrote gigabytes before computing anything.
TEST_F(Resources, EnsembleMembersReferToTheirNominalRunByItsStateOnly) {
  const std::string spec = Path("tiny.json"), db = Path("tiny.db");
  WriteText(spec, TinyEnsemble(2));
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + db + " --quiet").exit_code, 0);
  WriteText(spec, TinyEnsemble(3));
  const Outcome again = RunShockmap("study run " + spec + " --db " + db);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("references   0 computed, 1 reused"), std::string::npos)
      << again.output;
  EXPECT_EQ(testing::Rows(db, "SELECT DISTINCT reference_key FROM ensemble_members"),
            std::vector<std::string>{"scene"});
  EXPECT_EQ(testing::Rows(db,
                          "SELECT count(*), max(length(reference_key)) > 1000 FROM "
                          "ensemble_references"),
            std::vector<std::string>{"1|1"});
  const Outcome sizing = RunShockmap("sizing --db " + db + " --format json");
  ASSERT_EQ(sizing.exit_code, 0) << sizing.output;
  EXPECT_NE(sizing.output.find("\"members\": 3"), std::string::npos) << sizing.output;
  EXPECT_EQ(sizing.output.find("\"nominal_n\": null"), std::string::npos) << sizing.output;
}

// A sweep of the paper's cantilever whose two points share one reference (R_ftrunc 100).
std::string TinySweep(const std::string& r_ftrunc_values) {
  return std::string(R"({"name": "sweep", "scene": ")") + SHOCKMAP_SOURCE_DIR +
         R"(/scenes/cantilever_spring.json", "sweep": {"solver.r_ftrunc": [)" + r_ftrunc_values +
         R"(]}, "reference": {"solver.r_ftrunc": 100}, "scoring": {"displacement": "tip",
      "zone": "tip_spring", "window_s": 0.02, "rest_duration_s": 0.005}})";
}

// Each scene point's row used to repeat its reference's key, the whole scene as JSON: a row
// filled a page of its own, which every stored point wrote twice (docs/cluster.md).
TEST_F(Resources, ScenePointsReferToTheirReferenceByItsParametersOnly) {
  const std::string spec = Path("sweep.json"), db = Path("sweep.db");
  WriteText(spec, TinySweep("10"));
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + db + " --quiet").exit_code, 0);
  WriteText(spec, TinySweep("10, 30"));
  const Outcome again = RunShockmap("study run " + spec + " --db " + db);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("references   0 computed, 1 reused"), std::string::npos)
      << again.output;
  EXPECT_EQ(testing::Rows(db,
                          "SELECT count(*), max(length(p.reference_key)) < 40, "
                          "min(length(r.reference_key)) > 1000 FROM scene_points p "
                          "JOIN scene_references r ON r.parameters_json = p.reference_key "
                          "WHERE p.status = 'ok' AND p.reference_id = r.reference_id"),
            std::vector<std::string>{"2|1|1"});
}

// A stand-in for gnuplot that starts drawing (a few bytes into the file RunGnuplot names by -e,
// when it does) and never finishes; it writes its pid to PID_FILE and then touches STARTED.
constexpr const char* kStuckGnuplot = R"(#!/bin/sh
echo $$ > "$PID_FILE"
case "$2" in shockmap_output*)
  out=$(printf '%s' "$2" | sed "s/^[^']*'\(.*\)'$/\1/")
  printf 'partial' > "$out";;
esac
touch "$STARTED"
exec sleep 60
)";

TEST_F(Resources, SignalWhileDrawingKeepsTheGoodImageAndNoTemporary) {
  const std::string db = SmallDatabase();
  const std::filesystem::path out_dir = dir_ / "maps", image = out_dir / "map.png";
  const Outcome first = RunShockmap("map small --db " + db + " --out " + image.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const std::string good = ReadBytes(image);

  const std::filesystem::path bin = dir_ / "bin";
  std::filesystem::create_directories(bin);
  WriteText((bin / "gnuplot").string(), kStuckGnuplot);
  std::filesystem::permissions(bin / "gnuplot", std::filesystem::perms::owner_all);
  const std::string started = Path("started"), pid_file = Path("gnuplot.pid");
  const pid_t pid = fork();
  if (pid == 0) {
    setenv("PATH", (bin.string() + ":" + std::getenv("PATH")).c_str(), 1);
    setenv("STARTED", started.c_str(), 1);
    setenv("PID_FILE", pid_file.c_str(), 1);
    freopen(Path("log").c_str(), "w", stdout);
    dup2(fileno(stdout), fileno(stderr));
    execl(SHOCKMAP_BIN, SHOCKMAP_BIN, "map", "small", "--db", db.c_str(), "--out", image.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!std::filesystem::exists(started) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(std::filesystem::exists(started)) << ReadBytes(Path("log"));
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;

  const pid_t gnuplot = std::atoi(ReadBytes(pid_file).c_str());
  const bool gnuplot_ended = gnuplot > 0 && ::kill(gnuplot, 0) != 0;
  if (!gnuplot_ended && gnuplot > 0) ::kill(gnuplot, SIGKILL);
  EXPECT_TRUE(gnuplot_ended) << "gnuplot " << gnuplot << " outlived shockmap";
  EXPECT_TRUE(ReadBytes(image.string()) == good) << "the good map was not kept";
  EXPECT_EQ(Temporaries(out_dir), std::vector<std::string>{});
}

// A stand-in for gnuplot that touches STARTED, waits until RELEASE exists, then draws with the
// real gnuplot, REAL_GNUPLOT.
constexpr const char* kHeldGnuplot = R"(#!/bin/sh
touch "$STARTED"
while [ ! -e "$RELEASE" ]; do sleep 0.05; done
exec "$REAL_GNUPLOT" "$@"
)";

// Under nohup (SIGHUP ignored, as the parent asked) a SIGHUP while drawing changes nothing: the
// command finishes and writes its pictures.
TEST_F(Resources, IgnoredHangupWhileDrawingIsStillIgnored) {
  const std::string db = SmallDatabase();
  Outcome real = RunShell("command -v gnuplot");
  ASSERT_EQ(real.exit_code, 0) << real.output;
  real.output.erase(real.output.find_last_not_of('\n') + 1);
  const std::filesystem::path bin = dir_ / "bin";
  std::filesystem::create_directories(bin);
  WriteText((bin / "gnuplot").string(), kHeldGnuplot);
  std::filesystem::permissions(bin / "gnuplot", std::filesystem::perms::owner_all);
  const std::filesystem::path image = dir_ / "map.png", report = dir_ / "report";
  for (const std::string& args : {"map small --db " + db + " --out " + image.string(),
                                  "report small --db " + db + " --out " + report.string()}) {
    const std::string started = Path("started"), release = Path("release");
    std::filesystem::remove(started);
    std::filesystem::remove(release);
    const pid_t pid = fork();
    if (pid == 0) {
      setenv("PATH", (bin.string() + ":" + std::getenv("PATH")).c_str(), 1);
      setenv("STARTED", started.c_str(), 1);
      setenv("RELEASE", release.c_str(), 1);
      setenv("REAL_GNUPLOT", real.output.c_str(), 1);
      freopen(Path("log").c_str(), "w", stdout);
      dup2(fileno(stdout), fileno(stderr));
      const std::string command = "trap '' HUP; exec " + std::string(SHOCKMAP_BIN) + " " + args;
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!std::filesystem::exists(started) && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_TRUE(std::filesystem::exists(started)) << args << "\n" << ReadBytes(Path("log"));
    EXPECT_EQ(::kill(pid, SIGHUP), 0);
    WriteText(release, "");
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << args << ": status " << status << "\n"
        << ReadBytes(Path("log"));
  }
  EXPECT_TRUE(ReadBytes(image.string()).starts_with("\x89PNG")) << "no map was written";
  EXPECT_EQ(Temporaries(dir_), std::vector<std::string>{});
  EXPECT_TRUE(std::filesystem::exists(report / "index.html"));
}

TEST_F(Resources, TwoReportsIntoOneFolderBothSucceed) {
  const std::string db = SmallDatabase();
  const std::string report = Path("report");
  const std::string command =
      std::string(SHOCKMAP_BIN) + " report small --db " + db + " --out " + report;
  // Three rounds: two runs do not always draw the same picture at the same moment.
  for (int round = 0; round < 3; ++round) {
    const Outcome both = RunShell("(" + command + " > " + Path("a.log") + " 2>&1; echo a=$?) & (" +
                                  command + " > " + Path("b.log") + " 2>&1; echo b=$?); wait");
    ASSERT_NE(both.output.find("a=0"), std::string::npos)
        << round << ": " << both.output << ReadBytes(Path("a.log"));
    ASSERT_NE(both.output.find("b=0"), std::string::npos)
        << round << ": " << both.output << ReadBytes(Path("b.log"));
  }
  EXPECT_TRUE(std::filesystem::exists(report + "/index.html"));
  EXPECT_EQ(Temporaries(report), std::vector<std::string>{});
}

// `shockmap ARGS` with its files (and its children's) limited to `bytes` (RLIMIT_FSIZE, as
// `ulimit -f`), ended by SIGKILL after 60 s.
Outcome RunWithFileSizeLimit(std::size_t bytes, const std::string& args) {
  return RunShell("prlimit --fsize=" + std::to_string(bytes) + " timeout -s KILL 60 " +
                  SHOCKMAP_BIN + " " + args);
}

// The entries of `dir`, by name, but for the -wal and -shm files SQLite keeps beside a database
// it reads.
std::vector<std::string> Entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (!name.ends_with("-wal") && !name.ends_with("-shm")) names.push_back(name);
  }
  std::ranges::sort(names);
  return names;
}

TEST_F(Resources, ReportPastTheFileSizeLimitSaysSoAndLeavesNothing) {
  const std::string db = SmallDatabase();
  const auto before = Entries(dir_);
  // 40 kB: a picture is cut short; 120 kB: a history CSV is (the database's own -shm file,
  // 32 kB, must fit).
  for (const std::size_t limit : {40000u, 120000u}) {
    const Outcome r =
        RunWithFileSizeLimit(limit, "report small --db " + db + " --out " + Path("report"));
    EXPECT_EQ(r.exit_code, 2) << limit << "\n" << r.output;
    EXPECT_TRUE(r.output.find("File too large") != std::string::npos ||
                r.output.find("the file-size limit (ulimit -f) of") != std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(Path("report")), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(Path("report"))) << limit;
    EXPECT_EQ(Temporaries(dir_), std::vector<std::string>{});
    EXPECT_EQ(Entries(dir_), before);
    std::printf("[resources] %s\n", r.output.substr(0, r.output.find('\n')).c_str());
  }
}

TEST_F(Resources, ExportPointPastTheFileSizeLimitLeavesNoFolder) {
  const std::string db = SmallDatabase();
  // 4 kB: the database's own -shm file (32 kB) is refused before the point is computed again.
  const Outcome r =
      RunWithFileSizeLimit(4096, "export point --id 1 --db " + db + " --out " + Path("p/q"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(Path("p")));
  EXPECT_EQ(Temporaries(dir_), std::vector<std::string>{});
  std::printf("[resources] %s\n", r.output.c_str());
}

TEST_F(Resources, StudyRunPastTheFileSizeLimitNamesTheDatabase) {
  const std::string spec = Path("study.json");
  WriteText(spec, kSmallStudy);
  const Outcome r =
      RunWithFileSizeLimit(32u << 10, "study run " + spec + " --db " + Path("s.db") + " --quiet");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_LT(r.exit_code, 128) << "ended by a signal: " << r.output;
  EXPECT_NE(r.output.find(Path("s.db")), std::string::npos) << r.output;
  std::printf("[resources] %s\n", r.output.c_str());
}

TEST_F(Resources, PlotNameWithALineBreakLeavesNoFile) {
  const std::string db = SmallDatabase();
  const auto before = Entries(dir_);
  const Outcome r = RunShell(std::string(SHOCKMAP_BIN) + " map small --db " + db +
                             " --out \"$(printf '" + Path("maps/m\\nap.png") + "')\"");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("\"m\\x0aap.png\" holds a line break"), std::string::npos) << r.output;
  EXPECT_EQ(Entries(dir_), before);
}

}  // namespace
}  // namespace shockmap

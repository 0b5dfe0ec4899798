// The study manager as a process: killed with SIGKILL mid-run and resumed, bad study files
// refused without touching the database, read-only queries.

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <thread>

#include "db/migrations.h"
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

class StudyProcess : public testing::TempDirTest {};

// point_key -> the columns that must not depend on interruptions.
std::map<std::string, std::string> Outcomes(const std::string& db) {
  const Table r = RunReadOnlyQuery(
      db,
      "SELECT p.point_key, p.status || ' ' || quote(s.err) || ' ' || quote(s.srf) || ' ' || "
      "quote(s.steps) || ' ' || quote(s.dt_used_s) || ' ' || quote(s.n_dofs) "
      "FROM points p LEFT JOIN scores s USING (point_id)");
  std::map<std::string, std::string> m;
  for (const auto& row : r.rows) m[std::get<std::string>(row[0])] = std::get<std::string>(row[1]);
  return m;
}

// `shockmap study run SPEC --db DB --jobs 2 --quiet` in a child process; its pid, or -1.
pid_t StartStudy(const std::string& spec, const std::string& db) {
  const pid_t pid = fork();
  if (pid == 0) {
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(SHOCKMAP_BIN, SHOCKMAP_BIN, "study", "run", spec.c_str(), "--db", db.c_str(), "--jobs",
          "2", "--quiet", static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

TEST_F(StudyProcess, KilledWithSigkillResumesWithNothingLostOrDuplicated) {
  const std::string spec = Path("slow.json");
  WriteText(spec, kInterruptibleStudy);
  const std::string whole = Path("whole.db"), killed = Path("killed.db");
  const auto uninterrupted = RunShockmap("study run " + spec + " --db " + whole + " --quiet");
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.output;

  const pid_t pid = StartStudy(spec, killed);
  ASSERT_GE(pid, 0);
  // Kill once a few points are stored and before the study is done.
  std::int64_t stored = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    try {
      stored =
          Count(killed, "SELECT count(*) FROM points WHERE status NOT IN ('pending', 'running')");
    } catch (const std::exception&) {
      stored = 0;  // Not created or not migrated yet.
    }
    if (stored >= 3) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the study finished before it could be killed";
  const std::int64_t total = Count(whole, "SELECT count(*) FROM points");
  const std::int64_t unfinished =
      Count(killed, "SELECT count(*) FROM points WHERE status IN ('pending', 'running')");
  EXPECT_GT(unfinished, 0) << "nothing was left to resume";
  EXPECT_EQ(Count(killed, "SELECT count(*) FROM points"), total);

  const auto resumed = RunShockmap("study run " + spec + " --db " + killed + " --quiet");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find(std::to_string(unfinished) + " computed now"), std::string::npos)
      << resumed.output;
  EXPECT_EQ(Count(killed, "SELECT count(*) FROM points"), total);
  EXPECT_EQ(Count(killed, "SELECT count(*) FROM scores"), total);
  EXPECT_EQ(Count(killed, "SELECT count(*) FROM points WHERE status IN ('pending', 'running')"), 0);
  EXPECT_EQ(Outcomes(killed), Outcomes(whole));
}

// Killed five times at random moments (seeded), from the opening of the database to the middle
// of the points: after each kill the file is sound and holds every point once; the final run
// completes the study with the outcomes of an uninterrupted one.
TEST_F(StudyProcess, KilledRepeatedlyAtRandomMomentsLosesAndDuplicatesNothing) {
  const std::string spec = Path("slow.json");
  WriteText(spec, kInterruptibleStudy);
  const std::string whole = Path("whole.db"), killed = Path("killed.db");
  const auto started = std::chrono::steady_clock::now();
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + whole + " --quiet").exit_code, 0);
  const auto whole_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                            std::chrono::steady_clock::now() - started)
                            .count();
  const std::int64_t total = Count(whole, "SELECT count(*) FROM points");
  // Five delays of at most a sixth of an uninterrupted run each: together they cannot let the
  // study finish, whatever the machine's speed.
  std::mt19937 rng(20261123);
  std::uniform_int_distribution<long> delay_ms(0, whole_ms / 6);
  int kills = 0;
  for (int attempt = 0; attempt < 5; ++attempt) {
    const pid_t pid = StartStudy(spec, killed);
    ASSERT_GE(pid, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(rng)));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    kills += WIFSIGNALED(status) ? 1 : 0;
    if (!std::filesystem::exists(killed)) continue;  // Killed before it created the file.
    // Opened as the next run opens it: a writer rolls back a journal the kill left, which a
    // reader cannot (DatabaseCorruption.AJournalLeftByAKilledRunIsNamedByReadersAndRolled...).
    Connection raw(killed, Connection::Mode::kReadWriteCreate);
    Statement integrity = raw.Prepare("PRAGMA integrity_check");
    ASSERT_TRUE(integrity.Step());
    EXPECT_EQ(integrity.GetText(0), "ok");
    Statement version = raw.Prepare("PRAGMA user_version");
    ASSERT_TRUE(version.Step());
    // Killed while it created its schema: the migrations' one transaction leaves the empty file
    // as it was (version 0), which the next run migrates.
    if (version.GetInt(0) < kSchemaVersion) {
      EXPECT_EQ(version.GetInt(0), 0);
      continue;
    }
    const std::int64_t points = Count(killed, "SELECT count(*) FROM points");
    EXPECT_TRUE(points == 0 || points == total) << points << " of " << total;
    EXPECT_EQ(Count(killed,
                    "SELECT count(*) FROM (SELECT point_key FROM points GROUP BY "
                    "point_key HAVING count(*) > 1)"),
              0);
    // A point is finished exactly when it has its score.
    EXPECT_EQ(
        Count(killed,
              "SELECT count(*) FROM points p LEFT JOIN scores s USING (point_id) "
              "WHERE (p.status IN ('ok', 'diverged', 'unstable')) != (s.point_id IS NOT NULL)"),
        0);
  }
  EXPECT_EQ(kills, 5) << "the study finished before a kill";
  const auto resumed = RunShockmap("study run " + spec + " --db " + killed + " --quiet");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(Count(killed, "SELECT count(*) FROM points"), total);
  EXPECT_EQ(Count(killed, "SELECT count(*) FROM scores"), total);
  EXPECT_EQ(Outcomes(killed), Outcomes(whole));
}

TEST_F(StudyProcess, BadStudyFilesLeaveTheDatabaseByteForByteUnchanged) {
  const std::string db = Path("study.db");
  const std::string good = Path("good.json");
  WriteText(
      good,
      R"({"name": "g", "scoring": {"window_s": 0.03}, "grids": [{"rk": 100, "rftrunc": 10}]})");
  ASSERT_EQ(RunShockmap("study run " + good + " --db " + db + " --quiet").exit_code, 0);
  const std::string bytes = ReadBytes(db);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"", "is empty"},
      {"{\"name\": \"g\", \"grids\": [", "not valid JSON"},
      {R"({"name": "g", "grids": [{"rk": -1, "rftrunc": 10}]})", "grids[0].rk"},
      {R"({"name": "g", "grids": [{"rk": 1, "rftrunc": 10, "speed": 3}]})", "grids[0].speed"},
      {R"({"name": "g", "grids": [{"rk": 1e400, "rftrunc": 10}]})",
       "grids[0].rk (line 1): the number 1e400 is beyond a double's range"},
      {R"({"name": "g", "scoring": {"window_s": 0.03, "shocks": {"rest_duration_t1": 0.2}},
           "grids": [{"rk": 100, "rftrunc": 10}]})",
       "scoring.shocks.rest_duration_t1 = 0.1, where this file gives 0.2"},
      // Another window would add points that criteria pool with the stored ones.
      {R"({"name": "g", "scoring": {"window_s": 0.05}, "grids": [{"rk": 100, "rftrunc": 10}]})",
       "study \"g\" already exists in " + db +
           " with scoring.window_s = 0.03, where this file "
           "gives 0.05"},
      {R"({"name": "g", "scoring": {"window_s": 0.03, "reference": {"r_fref_min": 1000}},
           "grids": [{"rk": 100, "rftrunc": 10}]})",
       "scoring.reference.r_fref_min = 3000, where this file gives 1000"},
  };
  const std::string counts =
      "SELECT (SELECT count(*) FROM studies) || ' ' || (SELECT count(*) FROM points) || ' ' || "
      "(SELECT count(*) FROM runs) || ' ' || (SELECT count(*) FROM reference_runs)";
  const auto rows = testing::Rows(db, counts);
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const std::string file = Path("bad" + std::to_string(i) + ".json");
    WriteText(file, bad[i].first);
    const auto o = RunShockmap("study run " + file + " --db " + db + " --quiet");
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find(bad[i].second), std::string::npos) << o.output;
    EXPECT_NE(o.output.find(file), std::string::npos) << o.output;
    EXPECT_TRUE(ReadBytes(db) == bytes) << "case " << i;
    EXPECT_EQ(testing::Rows(db, counts), rows) << "case " << i;
  }
  const auto renamed = RunShockmap("study run " + Path("bad6.json") + " --db " + db + " --quiet");
  EXPECT_NE(renamed.output.find("Give the study a new name"), std::string::npos) << renamed.output;
  // A bad file never creates a database either.
  const std::string fresh = Path("fresh.db");
  EXPECT_EQ(RunShockmap("study run " + Path("bad2.json") + " --db " + fresh).exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(fresh));
  EXPECT_EQ(RunShockmap("study run " + Path("missing.json") + " --db " + fresh).exit_code, 2);
}

// A study file's misspelt key is named with the allowed key it most likely misspells, also
// when it hides a required one; so are a misspelt subcommand and option of `study`.
TEST_F(StudyProcess, MisspeltKeysSubcommandsAndOptionsAreNamedWithTheOneMeant) {
  const std::vector<std::pair<std::string, std::string>> files = {
      {R"({"name": "g", "grids": [{"rk": 100, "rftrunk": 10}]})",
       "grids[0].rftrunk: unknown key; did you mean \"rftrunc\"? (rftrunc: required axis is "
       "missing)"},
      {R"({"name": "g", "scoring": {"windw_s": 0.03}, "grids": [{"rk": 100, "rftrunc": 10}]})",
       "scoring.windw_s: unknown key; did you mean \"window_s\"? (allowed here: "},
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string file = Path("typo" + std::to_string(i) + ".json");
    WriteText(file, files[i].first);
    const auto o = RunShockmap("study run " + file + " --db " + Path("s.db") + " --quiet");
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_EQ(o.output.rfind("shockmap: error: " + file + ": " + files[i].second, 0), 0u)
        << o.output;
  }
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"study runn " + Path("typo0.json"),
       "study: unknown command \"runn\" (did you mean \"run\"?); use one of run, status "
       "(`shockmap study --help` says what each does)\n"},
      {"study",
       "study: a command is required, one of run, status; `shockmap study --help` says "
       "what each does\n"},
      {"study run " + Path("typo0.json") + " --quite",
       "study run: unknown option --quite (did you mean --quiet?); `shockmap study run --help` "
       "lists the options\n"},
  };
  for (const auto& [args, message] : commands) {
    const auto o = RunShockmap(args);
    EXPECT_EQ(o.exit_code, 2) << args << ": " << o.output;
    EXPECT_EQ(o.output, "shockmap: error: " + message) << args;
  }
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

TEST_F(StudyProcess, QueryAnswersInCsvAndJsonAndRefusesWrites) {
  const std::string db = Path("study.db");
  const std::string spec = Path("q.json");
  WriteText(
      spec,
      R"({"name": "q", "scoring": {"window_s": 0.03}, "grids": [{"rk": [100, 3000], "rftrunc": [10, 300]}]})");
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + db + " --quiet").exit_code, 0);

  const auto csv = RunShockmap("query --db " + db +
                               " 'SELECT r_k, r_ftrunc, err, srf FROM results ORDER BY point_id' "
                               "--format csv");
  ASSERT_EQ(csv.exit_code, 0) << csv.output;
  EXPECT_EQ(csv.output.rfind("r_k,r_ftrunc,err,srf\n", 0), 0u) << csv.output;
  EXPECT_EQ(std::count(csv.output.begin(), csv.output.end(), '\n'), 5);

  const auto json = RunShockmap("query --db " + db + " 'SELECT * FROM results' --format json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const auto rows = nlohmann::json::parse(json.output);
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    EXPECT_EQ(row["status"], "ok");
    EXPECT_GE(row["err"].get<double>(), 0.0);
    EXPECT_LE(row["srf"].get<double>(), 1.0);
    EXPECT_FALSE(row["code_version"].get<std::string>().empty());
  }

  const std::string bytes = ReadBytes(db);
  for (const char* sql :
       {"DELETE FROM points", "UPDATE scores SET err = 0", "DROP VIEW results",
        "SELECT 1; DELETE FROM points", "PRAGMA user_version = 7", "ATTACH 'x.db' AS x"}) {
    const auto o = RunShockmap("query --db " + db + " \"" + sql + "\"");
    EXPECT_EQ(o.exit_code, 2) << sql << ": " << o.output;
  }
  EXPECT_TRUE(ReadBytes(db) == bytes);
  const auto missing = RunShockmap("query --db " + Path("none.db") + " 'SELECT 1'");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("none.db"), std::string::npos);
}

TEST_F(StudyProcess, ForeignCorruptAndNewerDatabasesAreRefusedUntouched) {
  const std::string spec = Path("g.json");
  WriteText(
      spec,
      R"({"name": "g", "scoring": {"window_s": 0.03}, "grids": [{"rk": 100, "rftrunc": 10}]})");
  const std::string foreign = Path("foreign.db");
  {
    Connection c(foreign, Connection::Mode::kReadWriteCreate);
    c.Execute("CREATE TABLE accounts (id INTEGER); INSERT INTO accounts VALUES (1)");
  }
  const std::string corrupt = Path("corrupt.db");
  std::string noise(8192, '\0');
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<char>((i * 7919) % 251);
  WriteText(corrupt, noise);
  const std::string newer = Path("newer.db");
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + newer + " --quiet").exit_code, 0);
  {
    Connection c(newer, Connection::Mode::kReadWriteCreate);
    c.Execute("PRAGMA user_version = 99");
  }
  const std::vector<std::pair<std::string, std::string>> cases = {
      {foreign, "not a shockmap database"}, {corrupt, "corrupt.db"}, {newer, "newer shockmap"}};
  for (const auto& [db, expected] : cases) {
    const std::string bytes = ReadBytes(db);
    for (const std::string& command :
         {"study run " + spec + " --quiet", std::string("study status"),
          std::string("query 'SELECT 1'"), std::string("criteria derive")}) {
      const auto o = RunShockmap(command + " --db " + db);
      EXPECT_EQ(o.exit_code, 2) << command << " on " << db << ": " << o.output;
      EXPECT_NE(o.output.find(expected), std::string::npos) << command << ": " << o.output;
    }
    EXPECT_TRUE(ReadBytes(db) == bytes) << db;
  }
}

TEST_F(StudyProcess, LockedDatabaseWaitsThenFailsClearlyAndLosesNothing) {
  const std::string spec = Path("g.json");
  WriteText(
      spec,
      R"({"name": "g", "scoring": {"window_s": 0.03}, "grids": [{"rk": [100, 1000], "rftrunc": 10}]})");
  const std::string db = Path("locked.db");
  ASSERT_EQ(RunShockmap("study run " + spec + " --db " + db + " --quiet").exit_code, 0);
  WriteText(
      spec,
      R"({"name": "g", "scoring": {"window_s": 0.03}, "grids": [{"rk": [100, 1000], "rftrunc": [10, 30]}]})");
  const auto before = Outcomes(db);
  {
    Connection holder(db, Connection::Mode::kReadWriteCreate);
    holder.Execute("BEGIN EXCLUSIVE");
    const auto start = std::chrono::steady_clock::now();
    const auto o = RunShockmap("study run " + spec + " --db " + db + " --quiet");
    const double waited =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find("locked by another writer"), std::string::npos) << o.output;
    EXPECT_GE(waited, 9.0);
    EXPECT_LT(waited, 30.0);
    holder.Execute("ROLLBACK");
  }
  EXPECT_EQ(Outcomes(db), before);
  const auto resumed = RunShockmap("study run " + spec + " --db " + db + " --quiet");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("2 computed now"), std::string::npos) << resumed.output;
}

// `study status` lists every kind of study a database holds, from the registry of the kinds'
// tables (db/point_tables.h): a study of the paper's problem, a scene sweep and an ensemble, each
// with its points by status, and the ensemble's members also by clearance state and setting.
TEST_F(StudyProcess, StatusListsStudiesOfEveryKindAndEnsembleMembersByStateAndSetting) {
  const std::string source = SHOCKMAP_SOURCE_DIR;
  const std::string canonical = Path("canonical.json"), sweep = Path("sweep.json"),
                    ensemble = Path("ensemble.json"), db = Path("kinds.db");
  WriteText(
      canonical,
      nlohmann::json{
          {"name", "tiny_canonical"},
          {"scoring",
           {{"window_s", 0.02}, {"reference", {{"r_fref_min", 300}, {"r_fref_per_sqrt_rk", 3}}}}},
          {"grids",
           {{{"rk", 10}, {"rftrunc", {10, 100}}, {"dt", {{"rule", "sharp"}, {"factor", 0.1}}}}}}}
          .dump());
  WriteText(sweep, nlohmann::json{{"kind", "scene_sweep"},
                                  {"name", "tiny_sweep"},
                                  {"scene", source + "/scenes/cantilever_spring.json"},
                                  {"sweep", {{"solver.r_ftrunc", {10, 30}}}},
                                  {"reference", {{"solver.r_ftrunc", 100}}},
                                  {"scoring",
                                   {{"displacement", "tip"},
                                    {"zone", "tip_spring"},
                                    {"window_s", 0.02},
                                    {"rest_duration_s", 0.005}}}}
                       .dump());
  // Two states, two settings, one member each, of the planar bundle over 0.01 s.
  WriteText(ensemble,
            nlohmann::json{
                {"kind", "scene_ensemble"},
                {"name", "tiny_ensemble"},
                {"scene", source + "/scenes/bundle_row.json"},
                {"members", 1},
                {"seed", 3},
                {"window_s", 0.01},
                // 30 as a computed value would carry it: 0.1 * 300.
                {"settings", {{"solver.r_ftrunc", {30.000000000000004, 100}}}},
                {"refined", {{"solver.r_ftrunc", 100}}},
                {"draws",
                 {{"effects.base_motion.half_sine.amplitude_m_s2", {{"normal", {{"std", 9.81}}}}}}},
                {"clearance_states",
                 {{{"name", "new"}, {"pin_gap_m", {{"mean", 5e-5}, {"std", 5e-6}}}},
                  {{"name", "worn"}, {"pin_gap_m", {{"mean", 1e-5}, {"std", 3e-5}}}}}}}
                .dump());
  for (const std::string& spec : {canonical, sweep, ensemble}) {
    const auto run = RunShockmap("study run " + spec + " --db " + db + " --jobs 2 --quiet");
    ASSERT_EQ(run.exit_code, 0) << spec << ": " << run.output;
  }
  const auto status = RunShockmap("study status --db " + db);
  ASSERT_EQ(status.exit_code, 0) << status.output;
  const std::string& out = status.output;
  for (const char* study : {"tiny_canonical", "tiny_sweep", "tiny_ensemble"}) {
    EXPECT_NE(out.find(study), std::string::npos) << study << " missing from:\n" << out;
  }
  EXPECT_NE(out.find("ensemble_members by state and setting:"), std::string::npos) << out;
  std::vector<std::string> lines;
  for (std::size_t at = 0, end; at < out.size(); at = end + 1) {
    end = std::min(out.find('\n', at), out.size());
    lines.push_back(out.substr(at, end - at));
  }
  // One line per state and setting, with its one member computed, the setting by its number;
  // the numbers' settings beneath, without the JSON nor the last bits of a computed value.
  for (const char* state : {"new", "worn"}) {
    for (const char* setting : {"1", "2"}) {
      const std::regex row("tiny_ensemble +" + std::string(state) + " +" + setting + " +1 +1 .*");
      EXPECT_EQ(std::ranges::count_if(
                    lines, [&](const std::string& l) { return std::regex_match(l, row); }),
                1)
          << state << " " << setting << " missing from:\n"
          << out;
    }
  }
  EXPECT_NE(out.find("\nsettings of tiny_ensemble:\n  1  solver.r_ftrunc = 30\n"
                     "  2  solver.r_ftrunc = 100\n"),
            std::string::npos)
      << out;
  for (const std::string& line : lines) EXPECT_LE(line.size(), 160u) << line;
  // A study named alone shows its own breakdown only.
  const auto one = RunShockmap("study status tiny_canonical --db " + db);
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_EQ(one.output.find("tiny_ensemble"), std::string::npos) << one.output;
  EXPECT_EQ(one.output.find("ensemble_members by"), std::string::npos) << one.output;
}

}  // namespace
}  // namespace shockmap

// Database files edited, damaged or forged, as a user might receive them by
// mail: every command that reads one refuses what it cannot trust with exit
// code 2 and "database corrupt: ..." naming the row and column, never crashes,
// never writes memory it did not read from the file, and leaves the file as it
// was.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "db/schema.h"
#include "db/sqlite_handle.h"
#include "tests/database_rows.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::ReadBytes;
using testing::RunShockmap;
using testing::WriteText;

// Four points at two R_k, each R_k with its own reference: a tenth of a second.
constexpr const char* kCanonicalStudy = R"({
  "name": "small",
  "scoring": {"window_s": 0.02, "reference": {"r_fref_min": 300, "r_fref_per_sqrt_rk": 3}},
  "grids": [{"rk": [10, 100], "rftrunc": [10, 30]}]
})";

// The same study with one more point at R_k = 10: a run reuses the stored
// reference.
constexpr const char* kCanonicalStudyGrown = R"({
  "name": "small",
  "scoring": {"window_s": 0.02, "reference": {"r_fref_min": 300, "r_fref_per_sqrt_rk": 3}},
  "grids": [{"rk": [10, 100], "rftrunc": [10, 20, 30]}]
})";

class DatabaseCorruption : public testing::TempDirTest {
 protected:
  // A study run into db() by one job: references and points get their ids in
  // the study's order.
  void RunStudy(const std::string& json) {
    WriteText(Path("study.json"), json);
    const auto run =
        RunShockmap("study run " + Path("study.json") + " --db " + db() + " --jobs 1 --quiet");
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  void Canonical() { RunStudy(kCanonicalStudy); }
  void Ensemble() {
    RunStudy(R"({"kind": "scene_ensemble", "name": "ens", "scene": ")" +
             std::string(SHOCKMAP_SOURCE_DIR) +
             R"(/scenes/bundle_row.json", "members": 3, "seed": 11, "window_s": 0.01,
        "draws": {"bundle.wire.stiffness_n_per_m": {"lognormal": {"sigma": 0.2}}},
        "clearance_states": [{"name": "new", "pin_gap_m": {"mean": 5e-5, "std": 5e-6}}]})");
  }
  void Scene() {
    RunStudy(R"({"name": "sc", "scene": ")" + std::string(SHOCKMAP_SOURCE_DIR) +
             R"(/scenes/cantilever_spring.json", "sweep": {"solver.r_ftrunc": [10, 300]},
        "reference": {"solver.r_ftrunc": 1000},
        "scoring": {"displacement": "tip", "zone": "tip_spring", "rest_duration_s": 0.0052}})");
  }
  // Edits db() as a hostile sender would, with the sqlite3 shell's powers.
  void Edit(const std::string& sql) {
    Connection c(db(), Connection::Mode::kReadWriteCreate);
    c.Execute(sql);
  }
  std::string db() const { return Path("s.db"); }

  // Runs `args` on db() and expects a refusal: exit code 2, `message` in its
  // output, and the file as it was.
  void ExpectRefused(const std::string& args, const std::string& message) {
    const std::string before = ReadBytes(db());
    const auto r = RunShockmap(args + " --db " + db());
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_TRUE(ReadBytes(db()) == before) << args << " changed the file";
  }
  // Each (edit, message) applied alone to the database as it is now: sizing and report refuse
  // the edited file with the message. The database is left as it was.
  void ExpectEachRefusedBySizingAndReport(
      const std::vector<std::pair<std::string, std::string>>& cases) {
    const std::string pristine = ReadBytes(db());
    for (const auto& [sql, message] : cases) {
      WriteText(db(), pristine);
      Edit(sql);
      ExpectRefused("sizing", message);
      ExpectRefused("report --out " + Path("report"), message);
    }
    WriteText(db(), pristine);
  }
};

// Every command of a canonical study that reads the database.
const std::vector<std::string> kCanonicalReaders = {"query 'SELECT count(*) FROM results'",
                                                    "study status",
                                                    "criteria derive",
                                                    "cost",
                                                    "map --out map.png",
                                                    "report --out report",
                                                    "export reference --rk 10 --out ref.csv",
                                                    "advise --rk 1000"};

// A run killed while it created its database can leave the rollback journal of its schema's
// transaction beside the file (tests/data/killed_while_created.db: `study run` killed by
// SIGKILL 3 ms in). A reader cannot roll it back: it is refused, unchanged, with what to do; a
// run rolls it back and completes its study into the file.
TEST_F(DatabaseCorruption, AJournalLeftByAKilledRunIsNamedByReadersAndRolledBackByARun) {
  const std::string fixture =
      std::string(SHOCKMAP_SOURCE_DIR) + "/tests/data/killed_while_created.db";
  std::filesystem::copy_file(fixture, db());
  std::filesystem::copy_file(fixture + "-journal", db() + "-journal");
  const std::string journal = ReadBytes(db() + "-journal");
  for (const char* reader : {"study status", "criteria derive", "report --out report"}) {
    ExpectRefused(reader,
                  "a run was killed while it wrote this file (as when it created the database) "
                  "and left its rollback journal, which a reader cannot roll back");
    EXPECT_EQ(ReadBytes(db() + "-journal"), journal) << reader;
  }
  Canonical();
  EXPECT_FALSE(std::filesystem::exists(db() + "-journal"));
  EXPECT_EQ(testing::Rows(db(), "SELECT count(*) FROM points WHERE status = 'ok'"),
            std::vector<std::string>{"4"});
}

TEST_F(DatabaseCorruption, NegativeSchemaVersionIsRefusedByTheWriterAndEveryReader) {
  Canonical();
  for (const char* version : {"-1", "-2147483648"}) {
    Edit(std::string("PRAGMA user_version = ") + version);
    const std::string message = std::string("database corrupt: schema version ") + version +
                                " (PRAGMA user_version) is none shockmap writes (0 to " +
                                std::to_string(kSchemaVersion) + ")";
    ExpectRefused("study run " + Path("study.json"), message);
    for (const std::string& reader : kCanonicalReaders) ExpectRefused(reader, message);
  }
}

TEST_F(DatabaseCorruption, SchemaVersionThatDisagreesWithTheTablesIsRefusedNotMigrated) {
  Canonical();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0",
       "schema version 0 disagrees with its tables: table points, added "
       "by version 1, "
       "is already there"},
      {"5",
       "schema version 5 disagrees with its tables: view scene_params, "
       "added by version 6, "
       "is already there"},
      {"7",
       "schema version 7 disagrees with its tables: table "
       "ensemble_member_zones, added by "
       "version 8, is already there"}};
  for (const auto& [version, message] : cases) {
    Edit("PRAGMA user_version = " + version);
    ExpectRefused("study run " + Path("study.json"), message);
    ExpectRefused("query 'SELECT 1'", message);
  }
  Edit("PRAGMA user_version = 8; ALTER TABLE runs DROP COLUMN end_message");
  ExpectRefused("study status",
                "schema version 8 disagrees with its tables: "
                "column runs.end_message of version "
                "8 is missing");
}

TEST_F(DatabaseCorruption, ReferenceSignalsOfUnequalLengthAreRefusedBeforeAnyUse) {
  Canonical();
  Edit(
      "UPDATE reference_runs SET force_n = substr(force_n, 1, 800) WHERE "
      "reference_id = 1");
  const std::string message =
      "database corrupt: reference 1: tip_m holds 781 "
      "samples, force_n 100 (they must be equal)";
  ExpectRefused("export reference --rk 10 --out " + Path("ref.csv"), message);
  EXPECT_FALSE(std::filesystem::exists(Path("ref.csv")));
  ExpectRefused("export point --id 1 --out " + Path("point"), message);
  // A run that would reuse it to score a new point stops before scoring it
  // against it.
  WriteText(Path("study.json"), kCanonicalStudyGrown);
  const auto run = RunShockmap("study run " + Path("study.json") + " --db " + db());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(message), std::string::npos) << run.output;
  // Its run row ends failed and says why.
  const std::vector<std::string> last_run = testing::Rows(
      db(), "SELECT end_reason || ': ' || end_message FROM runs ORDER BY run_id DESC");
  ASSERT_FALSE(last_run.empty());
  EXPECT_EQ(last_run[0].rfind("failed: ", 0), 0u) << last_run[0];
  EXPECT_NE(last_run[0].find(message), std::string::npos) << last_run[0];

  Edit(
      "UPDATE reference_runs SET tip_m = zeroblob(120000000), force_n = "
      "zeroblob(8)");
  ExpectRefused("export reference --rk 100 --out " + Path("ref.csv"),
                "reference 2: tip_m holds 15000000 samples, force_n 1 (they "
                "must be equal)");
}

// A scene point names its reference by the reference's parameters as JSON (schema 13): text
// that is not such an object, or nests deeper than any stored JSON, stops the run that reads it.
TEST_F(DatabaseCorruption, AScenePointsReferenceThatIsNotAnObjectOfParametersIsRefused) {
  Scene();
  for (const std::string& key : {std::string("[1]"), std::string(100000, '[')}) {
    Edit("UPDATE scene_points SET status = 'pending', reference_key = '" + key + "'");
    const auto run = RunShockmap("study run " + Path("study.json") + " --db " + db());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find("database corrupt: a scene point: reference_key: "),
              std::string::npos)
        << run.output;
  }
}

TEST_F(DatabaseCorruption, ReferenceBlobsThatAreNotWholeFiniteSamplesAreRefused) {
  Canonical();
  const std::string pristine = ReadBytes(db());
  Edit(
      "UPDATE reference_runs SET force_n = CAST(x'000000000000F87F' || "
      "substr(force_n, 9) AS "
      "BLOB)");
  ExpectRefused("export point --id 1 --out " + Path("point"),
                "database corrupt: reference 1: force_n value 0 is nan (values "
                "must be finite)");
  WriteText(db(), pristine);
  Edit("UPDATE reference_runs SET force_n = substr(force_n, 1, 801)");
  ExpectRefused("export reference --rk 10 --out " + Path("ref.csv"),
                "database error: " + db() +
                    ": database corrupt: column force_n holds 801 bytes, not a whole number of "
                    "8-byte float64 values");
}

TEST_F(DatabaseCorruption, SamplingStepThatDisagreesWithTheWindowIsRefused) {
  Canonical();
  for (const char* dt : {"1e300", "0", "-1"}) {
    Edit(std::string("UPDATE reference_runs SET output_dt_s = ") + dt + " WHERE reference_id = 1");
    ExpectRefused("export point --id 1 --out " + Path("point"),
                  std::string("database corrupt: reference 1: ") +
                      (std::string(dt) == "1e300"
                           ? "tip_m holds 781 samples, but a window of 0.02 s "
                             "sampled every "
                             "1e+300 s holds 1"
                           : "output_dt_s is " + std::string(dt) + " (it must be finite and > 0)"));
  }
}

TEST_F(DatabaseCorruption, SceneReferenceSignalsOfUnequalLengthAreRefused) {
  Scene();
  Edit("UPDATE scene_references SET force_n = substr(force_n, 1, 800)");
  ExpectRefused("export reference --point 1 --out " + Path("ref.csv"),
                "database corrupt: scene reference 1: displacement_m holds "
                "34917 samples, "
                "force_n 100 (they must be equal)");
  EXPECT_FALSE(std::filesystem::exists(Path("ref.csv")));
}

TEST_F(DatabaseCorruption, CorruptStoredShocksAreADatabaseErrorNotAnInternalOne) {
  Canonical();
  Edit("UPDATE reference_runs SET shocks_json = '{bad' WHERE reference_id = 1");
  ExpectRefused("export point --id 1 --out " + Path("point"),
                "database corrupt: reference 1: shocks_json: parse error");
  Edit("UPDATE reference_runs SET shocks_json = '[1]' WHERE reference_id = 1");
  ExpectRefused("export point --id 1 --out " + Path("point"),
                "database corrupt: reference 1: shocks_json: cannot use at() "
                "with number");
}

TEST_F(DatabaseCorruption, StoredReboundsOutOfRangeAreADatabaseError) {
  Canonical();
  const std::string pristine = ReadBytes(db());
  for (const std::string rebounds : {"2147483647", "1e300", "-1", "2.5"}) {
    WriteText(db(), pristine);
    Edit("UPDATE reference_runs SET shocks_json = json_set(shocks_json, '$[0].rebounds', " +
         rebounds + ") WHERE reference_id = 1");
    ExpectRefused("export point --id 1 --out " + Path("point"),
                  "database corrupt: reference 1: shocks_json: rebounds holds ");
    ExpectRefused("export point --id 1 --out " + Path("point"), " (a count from 0 to 2147483646)");
  }
}

TEST_F(DatabaseCorruption, MembersWithoutTheirZoneRowsOrWithShiftedOnesAreRefused) {
  Ensemble();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"DELETE FROM ensemble_member_zones WHERE point_id = 3",
       "database corrupt: ensemble member 3: 0 zone rows, its nominal run 127 zones"},
      {"UPDATE ensemble_member_zones SET zone = zone + 1000 WHERE point_id = 3; "
       "UPDATE ensemble_member_zones SET zone = zone - 999 WHERE point_id = 3",
       "database corrupt: ensemble member 3: zone rows 1, 2, 3, "},
      {"UPDATE ensemble_member_zones SET zone = 500 WHERE point_id = 3 AND zone = 126",
       ", 124, 125, 500; its nominal run has zones 0 to 126"}};
  ExpectEachRefusedBySizingAndReport(cases);
}

TEST_F(DatabaseCorruption, CorruptEnsembleJsonAndMissingZoneRowsAreRefusedBySizing) {
  Ensemble();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"UPDATE ensemble_references SET zones_json = '{bad'",
       "database corrupt: ensemble reference 1: zones_json: parse error"},
      {"UPDATE ensemble_references SET zones_json = '[1, 2]'",
       "database corrupt: ensemble reference 1: zones_json: cannot use at() "
       "with number"},
      {"UPDATE ensemble_references SET zones_json = '[{\"name\": \"a\"}]'",
       "database corrupt: ensemble reference 1: zones_json: 1 zones, but "
       "max_force_n holds 127 "
       "forces"},
      {"UPDATE ensemble_members SET setting_json = '[1' WHERE point_id = 2",
       "database corrupt: ensemble member 2: setting_json: parse error"},
      {"DELETE FROM ensemble_member_zones WHERE point_id = 3 AND zone > 5",
       "database corrupt: ensemble member 3: 6 zone rows, its nominal run 127 "
       "zones"}};
  ExpectEachRefusedBySizingAndReport(cases);
  Edit("UPDATE studies SET spec_json = json_remove(spec_json, '$.scene_json')");
  ExpectRefused("report --out " + Path("report"),
                "database corrupt: study ens: spec_json: key 'scene_json' not found");
  EXPECT_FALSE(std::filesystem::exists(Path("report")));  // No refusal creates a file.
}

TEST_F(DatabaseCorruption, PendingSettingsAndTheSpecsMemberFieldsAreCheckedBeforeSizing) {
  Ensemble();
  const std::string spec = "UPDATE studies SET spec_json = json_set(spec_json, ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"UPDATE ensemble_members SET status = 'pending', setting_json = '[1' WHERE point_id = 2",
       "database corrupt: ensemble member 2: setting_json: parse error"},
      {spec + "'$.members', '3')",
       "database corrupt: study ens: spec_json: members: \"3\" is not a whole number from 1 "
       "to 100000"},
      {spec + "'$.members', 1e300)", "spec_json: members: 1e+300 is not a whole number"},
      {spec + "'$.members', 0)", "spec_json: members: 0 is not a whole number"},
      {spec + "'$.clearance_states', json('[1]'))",
       "database corrupt: study ens: spec_json: cannot use at() with number"},
      {spec + "'$.clearance_states', json('{\"name\": \"new\"}'))",
       "database corrupt: study ens: spec_json: type must be array, but is object"},
      {spec + "'$.settings', json('[1]'))",
       "database corrupt: study ens: spec_json: settings: neither a JSON object nor a list of "
       "objects"}};
  ExpectEachRefusedBySizingAndReport(cases);
}

TEST_F(DatabaseCorruption, StoredTextThatIsNotTextIsADatabaseErrorNotAnInternalOne) {
  Canonical();
  // The NOT NULL of studies.spec_json edited out of the schema, as a forger can.
  Edit(
      "PRAGMA writable_schema = ON; UPDATE sqlite_schema SET sql = replace(sql, "
      "'spec_json   TEXT NOT NULL', 'spec_json   TEXT') WHERE name = 'studies'");
  Edit("UPDATE studies SET spec_json = NULL");
  ExpectRefused("export reference --rk 10 --out " + Path("ref.csv"),
                "database corrupt: study small: spec_json holds NULL where text belongs");
}

TEST_F(DatabaseCorruption, StoredCountsOutOfRangeAreADatabaseError) {
  Canonical();
  Edit("UPDATE scores SET n_modes = 1e300 WHERE point_id = 2");
  ExpectRefused("criteria derive",
                "database corrupt: point 2: n_modes holds 1e+300 (a count from 0 to 2147483647)");
  Edit("UPDATE scores SET n_modes = 3, steps = -5 WHERE point_id = 2");
  ExpectRefused("cost",
                "database corrupt: point 2: steps holds -5 (a count from 0 to "
                "9223372036854775807)");
}

// A stored number of the wrong type, not finite or out of its column's range (records/
// columns.h) is refused where the row is read, naming the row, the column and the value: text
// in a score judged the point failing, a negative R_k made the criteria print -nan.
TEST_F(DatabaseCorruption, StoredNumbersOfTheWrongTypeOrOutOfRangeAreRefusedNamingTheRow) {
  Canonical();
  const std::string pristine = ReadBytes(db());
  struct Case {
    std::string sql;
    std::vector<std::string> readers;
    std::string message;
  };
  const std::vector<std::string> point_readers = {"criteria derive", "map --out " + Path("m.png"),
                                                  "cost", "report --out " + Path("report")};
  for (const Case& c : std::vector<Case>{
           {"UPDATE scores SET err = 'abc' WHERE point_id = 2", point_readers,
            "database corrupt: point 2: err is the text \"abc\" (it must be a number, in [0, 1] "
            "or NULL)"},
           {"UPDATE points SET r_k = -5 WHERE point_id = 3", point_readers,
            "database corrupt: point 3: r_k is -5 (it must be finite and > 0)"},
           {"UPDATE scores SET srf = 1.5 WHERE point_id = 1", point_readers,
            "database corrupt: point 1: srf is 1.5 (it must be in [0, 1])"},
           {"UPDATE scores SET dt_sharp_s = -9e999 WHERE point_id = 4", point_readers,
            "database corrupt: point 4: dt_sharp_s is -inf (it must be finite and >= 0)"},
           {"UPDATE reference_runs SET output_dt_s = 'abc' WHERE reference_id = 1",
            {"export point --id 1 --out " + Path("point"),
             "export reference --rk 10 --out " + Path("ref.csv")},
            "database corrupt: reference 1: output_dt_s is the text \"abc\" (it must be a "
            "number, finite and > 0)"},
           {"UPDATE reference_runs SET r_fref = 'x' WHERE reference_id = 1",
            {"export point --id 1 --out " + Path("point")},
            "database corrupt: reference 1: r_fref is the text \"x\" (it must be a number, "
            "finite and > 0)"}}) {
    WriteText(db(), pristine);
    Edit(c.sql);
    for (const std::string& reader : c.readers) ExpectRefused(reader, c.message);
  }
  std::filesystem::remove(db());
  Ensemble();
  ExpectEachRefusedBySizingAndReport(
      {{"UPDATE ensemble_member_zones SET max_force_n = 'big' WHERE zone = 0 AND point_id = "
        "(SELECT min(point_id) FROM ensemble_member_zones)",
        ", zone 0: max_force_n is the text \"big\" (it must be a number, finite and >= 0)"},
       {"UPDATE ensemble_member_zones SET contact_time_fraction = 2 WHERE zone = 0 AND point_id = "
        "(SELECT min(point_id) FROM ensemble_member_zones)",
        ", zone 0: contact_time_fraction is 2 (it must be in [0, 1])"}});
}

// SQLite's database in memory keeps nothing once the command ends: every command taking --db
// refuses it, as it does SHOCKMAP_DB set to it, before anything runs.
TEST_F(DatabaseCorruption, TheDatabaseInMemoryIsRefused) {
  WriteText(Path("study.json"), kCanonicalStudy);
  const std::string allowed =
      "\":memory:\" names SQLite's database in memory, which keeps nothing once the command "
      "ends; it must name a database file (./:memory: for a file of that name)";
  for (const std::string& command :
       {"study run " + Path("study.json") + " --quiet", std::string("study status"),
        std::string("query 'SELECT 1'"), std::string("criteria derive"), std::string("sizing")}) {
    const auto r = RunShockmap(command + " --db :memory:");
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("--db: the value " + allowed), std::string::npos) << r.output;
  }
  const auto from_env =
      testing::RunShell("SHOCKMAP_DB=:memory: " + std::string(SHOCKMAP_BIN) + " study status");
  EXPECT_EQ(from_env.exit_code, 2) << from_env.output;
  EXPECT_NE(from_env.output.find("environment variable SHOCKMAP_DB " + allowed), std::string::npos)
      << from_env.output;
}

TEST_F(DatabaseCorruption, ReportSkipsTheFigureOfACorruptReferenceAndWritesTheRest) {
  Canonical();
  Edit("UPDATE reference_runs SET shocks_json = '{bad' WHERE reference_id = 1");
  const auto r = RunShockmap("report --db " + db() + " --out " + Path("report"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: Fig. 3 of point 1 not drawn: " + db() +
                          ": database corrupt: reference 1: shocks_json: parse error"),
            std::string::npos)
      << r.output;
  const std::string index = ReadBytes(Path("report/index.html"));
  EXPECT_NE(index.find("Figures not drawn"), std::string::npos);
  EXPECT_NE(index.find("point 1: " + db() + ": database corrupt: reference 1: shocks_json"),
            std::string::npos);
  // The points of the sound reference keep their figures.
  EXPECT_TRUE(std::filesystem::exists(Path("report/points/point_3/fig3.png")));
}

// The database fuzzer's seeds are real study databases at the schema version of this build:
// readers refuse an older file at the schema check, so seeds left behind by a new migration would
// keep every input from reaching the stored rows.
TEST_F(DatabaseCorruption, FuzzerSeedsAreStudyDatabasesOfTheCurrentSchema) {
  const std::filesystem::path corpus =
      std::filesystem::path(SHOCKMAP_SOURCE_DIR) / "fuzz" / "corpus" / "database";
  int seeds = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    const std::string copy = Path(entry.path().filename().string());
    std::filesystem::copy_file(entry.path(), copy);
    const auto r = RunShockmap("study status --db " + copy);
    EXPECT_EQ(r.exit_code, 0) << entry.path() << ": " << r.output;
    ++seeds;
  }
  EXPECT_GE(seeds, 3);  // One of each study kind.
}

}  // namespace
}  // namespace shockmap

// Database files edited, damaged or forged, as a user might receive them by mail: every command
// that reads one refuses what it cannot trust with exit code 2 and "database corrupt: ..." naming
// the row and column, never crashes, never writes memory it did not read from the file, and
// leaves the file as it was.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "db/sqlite_handle.h"
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

class DatabaseCorruption : public testing::TempDirTest {
 protected:
  // A study run into db() by one job: references and points get their ids in the study's order.
  void RunStudy(const std::string& json) {
    WriteText(Path("study.json"), json);
    const auto run =
        RunShockmap("study run " + Path("study.json") + " --db " + db() + " --jobs 1 --quiet");
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  void Canonical() { RunStudy(kCanonicalStudy); }
  // Edits db() as a hostile sender would, with the sqlite3 shell's powers.
  void Edit(const std::string& sql) {
    Connection c(db(), Connection::Mode::kReadWriteCreate);
    c.Execute(sql);
  }
  std::string db() const { return Path("s.db"); }

  // Runs `args` on db() and expects a refusal: exit code 2, `message` in its output, and the
  // file as it was.
  void ExpectRefused(const std::string& args, const std::string& message) {
    const std::string before = ReadBytes(db());
    const auto r = RunShockmap(args + " --db " + db());
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_TRUE(ReadBytes(db()) == before) << args << " changed the file";
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

TEST_F(DatabaseCorruption, NegativeSchemaVersionIsRefusedByTheWriterAndEveryReader) {
  Canonical();
  for (const char* version : {"-1", "-2147483648"}) {
    Edit(std::string("PRAGMA user_version = ") + version);
    const std::string message = std::string("database corrupt: schema version ") + version +
                                " (PRAGMA user_version) is none shockmap writes (0 to 8)";
    ExpectRefused("study run " + Path("study.json"), message);
    for (const std::string& reader : kCanonicalReaders) ExpectRefused(reader, message);
  }
}

TEST_F(DatabaseCorruption, SchemaVersionThatDisagreesWithTheTablesIsRefusedNotMigrated) {
  Canonical();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0",
       "schema version 0 disagrees with its tables: table points, added by version 1, "
       "is already there"},
      {"5",
       "schema version 5 disagrees with its tables: view scene_params, added by version 6, "
       "is already there"},
      {"7",
       "schema version 7 disagrees with its tables: table ensemble_member_zones, added by "
       "version 8, is already there"}};
  for (const auto& [version, message] : cases) {
    Edit("PRAGMA user_version = " + version);
    ExpectRefused("study run " + Path("study.json"), message);
    ExpectRefused("query 'SELECT 1'", message);
  }
  Edit("PRAGMA user_version = 8; ALTER TABLE runs DROP COLUMN end_message");
  ExpectRefused("study status",
                "schema version 8 disagrees with its tables: column runs.end_message of version "
                "8 is missing");
}

}  // namespace
}  // namespace shockmap

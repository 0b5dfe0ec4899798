// Data that leaves the tool: numbers printed by `query` and written to CSV read back as the
// stored doubles, bit for bit; `export` writes a reference's stored signals and a point's
// histories; scene study parameters are columns of the view scene_params.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "db/read_only_query.h"
#include "db/stored_signals.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::RunShockmap;
using testing::WriteText;

class DataExport : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    WriteText(Path("g.json"),
              R"({"name": "g", "scoring": {"window_s": 0.03},
                  "grids": [{"rk": {"logspace": [2, 3.5, 2]}, "rftrunc": {"logspace": [1, 2.5, 2]}}]})");
    ASSERT_EQ(RunShockmap("study run " + Path("g.json") + Db() + " --quiet").exit_code, 0);
  }
  std::string Db() const { return " --db " + Path("s.db"); }
};

std::vector<std::vector<std::string>> CsvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST_F(DataExport, QueryPrintsValuesThatReadBackBitForBitAndMatchInWhere) {
  const Table stored = RunReadOnlyQuery(
      Path("s.db"), "SELECT point_id, r_k, r_ftrunc, err FROM results ORDER BY point_id");
  ASSERT_EQ(stored.rows.size(), 4u);
  for (const std::string format : {"csv", "table"}) {
    const auto o = RunShockmap("query" + Db() + " --format " + format +
                               " 'SELECT point_id, r_k, r_ftrunc, err FROM results ORDER BY "
                               "point_id'");
    ASSERT_EQ(o.exit_code, 0) << o.output;
    std::istringstream lines(o.output);
    std::string line;
    std::vector<std::vector<std::string>> rows;
    while (std::getline(lines, line)) {
      std::istringstream cells(format == "csv" ? std::regex_replace(line, std::regex(","), " ")
                                               : line);
      std::vector<std::string> row;
      for (std::string c; cells >> c;) row.push_back(c);
      if (!row.empty() && std::isdigit(static_cast<unsigned char>(row[0][0]))) rows.push_back(row);
    }
    ASSERT_EQ(rows.size(), 4u) << o.output;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      for (int c = 1; c <= 3; ++c) {
        const double value = std::get<double>(stored.rows[i][c]);
        EXPECT_TRUE(SameBits(std::strtod(rows[i][c].c_str(), nullptr), value))
            << rows[i][c] << " against " << value;
      }
    }
  }
  // 10^2.5, printed in the 16 digits that read back as it, finds its rows.
  const auto printed =
      CsvRows(RunShockmap("query" + Db() +
                          " --format csv 'SELECT DISTINCT r_ftrunc FROM results WHERE "
                          "r_ftrunc > 300 AND r_ftrunc < 400'")
                  .output);
  ASSERT_EQ(printed.size(), 2u);
  const auto matched =
      RunShockmap("query" + Db() + " --format csv 'SELECT count(*) FROM results WHERE r_ftrunc = " +
                  printed[1][0] + "'");
  EXPECT_EQ(matched.output, "count(*)\n2\n") << printed[1][0];
}

TEST_F(DataExport, AReferenceIsWrittenAsStoredAndAPointIsComputedAgainAsStored) {
  const auto ids = ReferenceIdsAt(Path("s.db"), "g", 3162.2776601683795);
  ASSERT_EQ(ids.size(), 1u);
  const auto stored = ReadReference(Path("s.db"), ids.front());
  ASSERT_TRUE(stored);
  const auto o = RunShockmap("export reference --rk 3162.2776601683795" + Db() + " --out " +
                             Path("out/ref.csv"));
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const auto rows = CsvRows(testing::ReadBytes(Path("out/ref.csv")));
  ASSERT_EQ(rows.size(), stored->tip_m.size() + 1);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"t_s", "tip_displacement_m", "contact_force_n"}));
  for (std::size_t i = 0; i < stored->tip_m.size(); ++i) {
    const auto& r = rows[i + 1];
    ASSERT_TRUE(
        SameBits(std::strtod(r[0].c_str(), nullptr), static_cast<double>(i) * stored->output_dt_s));
    ASSERT_TRUE(SameBits(std::strtod(r[1].c_str(), nullptr), stored->tip_m[i])) << i;
    ASSERT_TRUE(SameBits(std::strtod(r[2].c_str(), nullptr), stored->force_n[i])) << i;
  }
  EXPECT_GT(*std::max_element(stored->force_n.begin(), stored->force_n.end()), 0.0);
  // --rk as a person types it: the nearest studied R_k, said, and the same file.
  const auto typed =
      RunShockmap("export reference --rk 3162" + Db() + " --out " + Path("out/ref_typed.csv"));
  ASSERT_EQ(typed.exit_code, 0) << typed.output;
  EXPECT_NE(typed.output.find("(R_k = 3162.2776601683795, the studied value nearest to --rk 3162)"),
            std::string::npos)
      << typed.output;
  EXPECT_EQ(testing::ReadBytes(Path("out/ref_typed.csv")), testing::ReadBytes(Path("out/ref.csv")));

  const Table point = RunReadOnlyQuery(
      Path("s.db"),
      "SELECT point_id, err, srf FROM results WHERE r_k > 3000 AND r_ftrunc > 300 LIMIT 1");
  ASSERT_EQ(point.rows.size(), 1u);
  const auto id = std::get<std::int64_t>(point.rows[0][0]);
  const auto replay =
      RunShockmap("export point --id " + std::to_string(id) + Db() + " --out " + Path("p"));
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  // The run is deterministic: the scores printed are the stored ones, to the last bit.
  std::smatch err;
  ASSERT_TRUE(std::regex_search(replay.output, err, std::regex("Err ([0-9.e+-]+)")))
      << replay.output;
  EXPECT_TRUE(
      SameBits(std::strtod(err[1].str().c_str(), nullptr), std::get<double>(point.rows[0][1])))
      << replay.output;
  const auto numerical = CsvRows(testing::ReadBytes(Path("p/numerical.csv")));
  const auto reference = CsvRows(testing::ReadBytes(Path("p/reference.csv")));
  EXPECT_EQ(reference.size(), rows.size());
  EXPECT_GT(numerical.size(), 100u);
  EXPECT_EQ(numerical[0].size(), 8u);
}

TEST_F(DataExport, SceneStudyParametersAreColumnsOfSceneParams) {
  const nlohmann::json study = {
      {"name", "truncation"},
      {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json"},
      {"sweep", {{"solver.r_ftrunc", {10, 300}}, {"solver.dt.factor", {0.1}}}},
      {"reference", {{"solver.r_ftrunc", 1000}}},
      {"scoring", {{"displacement", "tip"}, {"zone", "tip_spring"}, {"rest_duration_s", 0.0052}}}};
  WriteText(Path("scene.json"), study.dump());
  ASSERT_EQ(RunShockmap("study run " + Path("scene.json") + Db() + " --quiet").exit_code, 0);
  const Table r = RunReadOnlyQuery(
      Path("s.db"),
      "SELECT \"params_solver.r_ftrunc\", \"params_solver.dt.factor\", err, "
      "json_extract(parameters_json, '$.\"solver.r_ftrunc\"') FROM scene_params ORDER BY 1");
  ASSERT_EQ(r.rows.size(), 2u);
  EXPECT_EQ(std::get<double>(r.rows[0][0]), 10.0);
  EXPECT_EQ(std::get<double>(r.rows[1][0]), 300.0);
  EXPECT_EQ(std::get<double>(r.rows[1][1]), 0.1);
  EXPECT_EQ(r.rows[1][0], r.rows[1][3]);
  // The scored point's reference, from the scene_references table.
  const auto o = RunShockmap("export reference truncation --point 1" + Db() + " --out " +
                             Path("scene_ref.csv"));
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const auto rows = CsvRows(testing::ReadBytes(Path("scene_ref.csv")));
  EXPECT_EQ(rows[0], (std::vector<std::string>{"t_s", "displacement_m", "contact_force_n"}));
  EXPECT_GT(rows.size(), 1000u);
  // A scene point stores no signals: exporting one is refused, naming what to do instead.
  const auto refused = RunShockmap("export point truncation --id 1" + Db() + " --out " + Path("x"));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("export reference --point 1"), std::string::npos);
}

TEST_F(DataExport, AMigratedDatabaseHasItsSceneParametersAsColumnsAtOnce) {
  // A schema 2 file with scene points, opened for writing by a study of the paper's problem
  // only: the migration alone writes scene_params.
  const std::string source = std::string(SHOCKMAP_SOURCE_DIR) + "/tests/data/";
  std::filesystem::copy_file(source + "schema_v2.db", Path("v2.db"));
  ASSERT_EQ(RunShockmap("study run " + source + "schema_v2_canonical.json --db " + Path("v2.db") +
                        " --quiet")
                .exit_code,
            0);
  const Table r =
      RunReadOnlyQuery(Path("v2.db"),
                       "SELECT \"params_solver.r_ftrunc\", json_extract(parameters_json, "
                       "'$.\"solver.r_ftrunc\"') FROM scene_params ORDER BY 1");
  ASSERT_EQ(r.rows.size(), 2u);
  EXPECT_EQ(std::get<double>(r.rows[0][0]), 10.0);
  EXPECT_EQ(r.rows[1][0], r.rows[1][1]);
}

TEST(DatabaseDocs, ThePythonReaderReadsAStoredReferenceBack) {
  // The ```python block of docs/database.md, run as written on a database named as it expects.
  const std::string docs =
      testing::ReadBytes(std::string(SHOCKMAP_SOURCE_DIR) + "/docs/database.md");
  const auto begin = docs.find("```python\n");
  ASSERT_NE(begin, std::string::npos);
  const auto end = docs.find("```", begin + 10);
  const std::string dir = ::testing::TempDir() + "/shockmap_python_reader";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  WriteText(dir + "/read.py", docs.substr(begin + 10, end - begin - 10));
  WriteText(dir + "/quick.json", R"({"name": "quick", "scoring": {"window_s": 0.03},
      "grids": [{"rk": 3162.2776601683795, "rftrunc": 300}]})");
  ASSERT_EQ(RunShockmap("study run " + dir + "/quick.json --db " + dir + "/shockmap.db --quiet")
                .exit_code,
            0);
  const auto o = testing::RunShell("cd " + dir + " && /usr/bin/python3 read.py");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const auto ids = ReferenceIdsAt(dir + "/shockmap.db", "quick", 3162.2776601683795);
  ASSERT_EQ(ids.size(), 1u);
  const auto stored = ReadReference(dir + "/shockmap.db", ids.front());
  const double peak = *std::max_element(stored->force_n.begin(), stored->force_n.end());
  char expected[128];
  std::snprintf(expected, sizeof expected,
                "%zu samples, dt = %.6g s, window 0.03 s, peak force %.6g N", stored->tip_m.size(),
                stored->output_dt_s, peak);
  EXPECT_EQ(o.output.rfind(expected, 0), 0u) << o.output << " against " << expected;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace shockmap

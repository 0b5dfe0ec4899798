// Ensembles of the rubbing bundle (scenes/bundle_hex_7_friction.json; docs/ensembles.md): each
// member zone's stored wear volume is Archard's law of its stored wear work rate over the
// scene's life, friction's power stays inside the Coulomb cone, the listed impacts are the
// zone's impacts one by one (their impulses sum to the zone's impulse), the wear sizing is the
// statistics of the stored volumes, the impacts export as CSV (an ensemble's only), and a bad
// counting is refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "db/sqlite_handle.h"
#include "statistics/quantile_interval.h"
#include "tests/database_rows.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using nlohmann::json;
using testing::RunShockmap;
using testing::WriteText;

const std::string kScene = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_hex_7_friction.json";

// The rubbing bundle through its shock (the half-sine lasts 0.01 s), every contact an impact
// (rest_duration_s 0), the shock's amplitude drawn.
json RubbingEnsemble(int members) {
  return {{"kind", "scene_ensemble"},
          {"name", "rubbing"},
          {"scene", kScene},
          {"members", members},
          {"seed", 5},
          {"window_s", 0.02},
          {"impact_statistics", {{"rest_duration_s", 0.0}}},
          {"draws",
           {{"effects.base_motion.half_sine.amplitude_m_s2", {{"normal", {{"std", 19.62}}}}}}}};
}

class EnsembleWearTest : public testing::TempDirTest {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::filesystem::temp_directory_path() /
           ("shockmap_ensemble_wear_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    WriteText((dir_ / "rubbing.json").string(), RubbingEnsemble(kMembers).dump(2));
    run_ = RunShockmap("study run " + (dir_ / "rubbing.json").string() + " --db " + Db() +
                       " --jobs 2 --quiet");
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  static std::string Db() { return (dir_ / "rubbing.db").string(); }

  static constexpr int kMembers = 60;  // Enough to bound a P95 from above at 95 %.
  static inline std::filesystem::path dir_;
  static inline testing::Outcome run_;
};

json SceneJson() {
  std::ifstream in(kScene);
  return json::parse(in);
}

TEST_F(EnsembleWearTest, StoredWearVolumeIsArchardsOfTheStoredWearWorkRate) {
  ASSERT_EQ(run_.exit_code, 0) << run_.output;
  const json wear = SceneJson()["wear"];
  const double k = wear["coefficient_m2_per_n"], life = wear["life_s"];
  Connection c(Db(), Connection::Mode::kReadOnly);
  Statement s = c.Prepare(
      "SELECT wear_work_rate_w, wear_volume_m3, friction_power_w FROM ensemble_member_zones");
  int rows = 0, worn = 0, rubbing = 0;
  while (s.Step()) {
    ++rows;
    // The scene bends in both planes: every zone's sliding is carried.
    ASSERT_FALSE(s.IsNull(0));
    ASSERT_FALSE(s.IsNull(1));
    const double rate = s.GetDouble(0), volume = s.GetDouble(1);
    EXPECT_EQ(volume, k * rate * life);
    worn += volume > 0.0;
    if (s.IsNull(2)) continue;
    // |F_t| <= mu_s F_n at every sample that slides (mu_s = 0.35 at every zone of the scene).
    EXPECT_LE(s.GetDouble(2), 0.35 * rate * (1.0 + 1e-12));
    rubbing += s.GetDouble(2) > 0.0;
  }
  EXPECT_EQ(rows, kMembers * testing::Count(Db(),
                                            "SELECT json_array_length(zones_json) FROM "
                                            "ensemble_references LIMIT 1"));
  EXPECT_GT(worn, 0);
  EXPECT_GT(rubbing, 0);
}

// Every contact is an impact (rest_duration_s 0) and the force threshold is 0: every impulse is
// in an impact, so a listed zone's impacts, one row each, sum to its impulse and number its
// impacts; their rebounds are none.
TEST_F(EnsembleWearTest, ListedImpactsSumToTheZonesImpulse) {
  ASSERT_EQ(run_.exit_code, 0) << run_.output;
  Connection c(Db(), Connection::Mode::kReadOnly);
  Statement s = c.Prepare(
      "SELECT z.point_id, z.zone, z.impacts, z.impulse_n_s, count(i.impact), "
      "total(i.impulse_n_s), total(i.rebounds), max(i.impact) FROM ensemble_member_zones z JOIN "
      "ensemble_member_impacts i ON i.point_id = z.point_id AND i.zone = z.zone GROUP BY "
      "z.point_id, z.zone");
  int zones = 0;
  std::int64_t impacts = 0;
  while (s.Step()) {
    ++zones;
    SCOPED_TRACE("member " + s.GetText(0) + " zone " + s.GetText(1));
    EXPECT_EQ(s.GetInt(4), s.GetInt(2));
    EXPECT_EQ(s.GetInt(7), s.GetInt(2));  // Numbered 1 to impacts.
    EXPECT_NEAR(s.GetDouble(5), s.GetDouble(3), 1e-12 * s.GetDouble(3));
    EXPECT_EQ(s.GetDouble(6), 0.0);
    impacts += s.GetInt(4);
  }
  // The scene lists two zones; each member's duct pad is struck by the shock.
  EXPECT_GE(zones, kMembers);
  EXPECT_LE(zones, 2 * kMembers);
  EXPECT_GT(impacts, zones);
  // No zone the scene does not list has impacts stored.
  EXPECT_EQ(testing::Count(Db(), "SELECT count(DISTINCT zone) FROM ensemble_member_impacts"),
            zones > kMembers ? 2 : 1);
}

TEST_F(EnsembleWearTest, ExportedImpactsAreTheStoredRows) {
  ASSERT_EQ(run_.exit_code, 0) << run_.output;
  const std::string csv = (dir_ / "impacts.csv").string();
  const auto out = RunShockmap("export impacts --db " + Db() + " --out " + csv);
  ASSERT_EQ(out.exit_code, 0) << out.output;
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header,
            "point_id,state,setting_json,member,zone_name,zone,impact,start_s,duration_s,"
            "peak_force_n,peak_time_s,impulse_n_s,impact_speed_m_s,rebounds,truncated");
  std::int64_t lines = 0;
  std::map<std::string, int> by_zone;
  while (std::getline(in, line)) {
    ++lines;
    // point_id, state, setting ({}: no comma), member, zone_name, ...
    std::vector<std::string> fields;
    std::stringstream split(line);
    for (std::string f; std::getline(split, f, ',');) fields.push_back(f);
    ASSERT_EQ(fields.size(), 15u) << line;
    ++by_zone[fields[4]];
  }
  EXPECT_EQ(lines, testing::Count(Db(), "SELECT count(*) FROM ensemble_member_impacts"));
  // The zones by name, as the scene lists them.
  for (const auto& [zone, count] : by_zone) {
    EXPECT_TRUE(zone == "duct-pad" || zone == "pin_0-pin_3@0.9144") << zone;
  }
  EXPECT_NE(out.output.find(std::to_string(lines) + " impacts of study rubbing"), std::string::npos)
      << out.output;
}

TEST_F(EnsembleWearTest, ExportingImpactsOfAnotherKindIsRefusedWithExitCode2) {
  const std::string db = (dir_ / "canonical.db").string(), csv = (dir_ / "none.csv").string();
  std::filesystem::copy_file(
      std::string(SHOCKMAP_SOURCE_DIR) + "/fuzz/corpus/database/canonical.db", db);
  const auto out = RunShockmap("export impacts --db " + db + " --out " + csv);
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("study canonical is not an ensemble study"), std::string::npos)
      << out.output;
  EXPECT_FALSE(std::filesystem::exists(csv));
}

TEST_F(EnsembleWearTest, WearSizingIsTheStatisticsOfTheStoredVolumes) {
  ASSERT_EQ(run_.exit_code, 0) << run_.output;
  const auto out = RunShockmap("sizing --wear --db " + Db() + " --format json");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  const json rows = json::parse(out.output);
  ASSERT_EQ(static_cast<std::int64_t>(rows.size()),
            testing::Count(Db(), "SELECT count(DISTINCT zone) FROM ensemble_member_zones"));
  // One state and setting: the rows are the zones in the scene's order.
  std::vector<std::vector<double>> volumes(rows.size());
  Connection c(Db(), Connection::Mode::kReadOnly);
  Statement stored =
      c.Prepare("SELECT zone, wear_volume_m3 FROM ensemble_member_zones ORDER BY point_id, zone");
  while (stored.Step()) volumes.at(stored.GetInt(0)).push_back(stored.GetDouble(1));
  int checked = 0;
  for (std::size_t z = 0; z < rows.size(); ++z) {
    const json& row = rows[z];
    ASSERT_EQ(volumes[z].size(), static_cast<std::size_t>(kMembers));
    const QuantileInterval p95 = EstimateQuantile(volumes[z], 0.95, 0.95);
    EXPECT_EQ(row["wear_p95_m3"].get<double>(), p95.estimate);
    EXPECT_EQ(row["wear_p95_lower_m3"], p95.lower_bounded ? json(p95.lower) : json("-inf"));
    EXPECT_EQ(row["wear_p95_upper_m3"], p95.upper_bounded ? json(p95.upper) : json("inf"));
    // 60 members allow Wilks' first order at 95/95: the largest volume.
    EXPECT_EQ(row["wilks_order"].get<int>(), 1);
    EXPECT_EQ(row["wilks_limit_m3"].get<double>(),
              *std::max_element(volumes[z].begin(), volumes[z].end()));
    checked += p95.estimate > 0.0;
  }
  EXPECT_GT(checked, 0);
}

TEST_F(EnsembleWearTest, ABadCountingIsRefusedWithExitCode2) {
  struct Case {
    json counting;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {{{"rest_duration_s", -1.0}}, {"impact_statistics.rest_duration_s", "-1", "[0, 100]"}},
      {{{"rest_duration_s", 0.0}, {"convention", "aster"}},
       {"impact_statistics.convention", "aster", "\"shockmap\" or \"code_aster\""}},
      {{{"rest_duration_s", 0.0}, {"window_s", {0.0, 0.5}}},
       {"impact_statistics.window_s", "0.5", "window_s = 0.02"}},
  };
  for (const Case& c : cases) {
    json spec = RubbingEnsemble(2);
    spec["impact_statistics"] = c.counting;
    const std::string file = (dir_ / "bad.json").string(), db = (dir_ / "bad.db").string();
    WriteText(file, spec.dump(2));
    const auto out = RunShockmap("study run " + file + " --db " + db + " --quiet");
    EXPECT_EQ(out.exit_code, 2) << out.output;
    for (const std::string& e : c.expected) {
      EXPECT_NE(out.output.find(e), std::string::npos) << "no \"" << e << "\" in " << out.output;
    }
    EXPECT_FALSE(std::filesystem::exists(db));
  }
}

}  // namespace
}  // namespace shockmap

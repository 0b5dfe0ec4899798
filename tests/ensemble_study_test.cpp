// Ensemble studies (docs/ensembles.md) as a user runs them: members reproducible bit for bit,
// a study killed mid-ensemble resuming to the same table, added members computed alone, bad
// study files refused with exit code 2, and the sizing table as the statistics of the stored
// maxima.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "db/migrations.h"
#include "db/sqlite_handle.h"
#include "engine/ensemble_study.h"
#include "specs/study_file.h"
#include "specs/zone_family.h"
#include "statistics/quantile_interval.h"
#include "statistics/wilks.h"
#include "tests/database_rows.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using nlohmann::json;
using testing::Count;
using testing::RunShockmap;
using testing::WriteText;

// The planar bundle over 0.03 s (about 0.02 s of CPU per member), two clearance states, the
// second with preloaded wires, and three scattered parameters.
json SmallEnsemble(int members) {
  return {{"kind", "scene_ensemble"},
          {"name", "small"},
          {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json"},
          {"members", members},
          {"seed", 11},
          {"window_s", 0.03},
          {"draws",
           {{"effects.base_motion.half_sine.amplitude_m_s2", {{"normal", {{"std", 9.81}}}}},
            {"effects.base_motion.half_sine.duration_s",
             {{"uniform", {{"min", 0.008}, {"max", 0.012}}}}},
            {"bundle.wire.stiffness_n_per_m", {{"lognormal", {{"sigma", 0.2}}}}}}},
          {"clearance_states",
           {{{"name", "new"}, {"pin_gap_m", {{"mean", 5e-5}, {"std", 5e-6}}}},
            {{"name", "worn"},
             {"pin_gap_m", {{"mean", 1e-5}, {"std", 3e-5}, {"min", -4e-5}}},
             {"wrapper_gap_m", {{"mean", 1e-4}, {"std", 5e-5}}}}}}};
}

// Long enough for the shock to reach every family of the hexagonal bundle.
constexpr double kHexWindowS = 0.05;

class EnsembleStudyTest : public testing::TempDirTest {
 protected:
  std::string Write(const json& spec, const std::string& name = "ensemble.json") {
    const std::string file = Path(name);
    WriteText(file, spec.dump(2));
    return file;
  }
  testing::Outcome Run(const std::string& spec, const std::string& db) {
    return RunShockmap("study run " + spec + " --db " + db + " --jobs 2 --quiet");
  }
};

// point_key -> every zone's largest force, as text that keeps all 17 digits.
std::map<std::string, std::string> ZoneMaxima(const std::string& db) {
  std::map<std::string, std::string> m;
  for (const std::string& row :
       testing::Rows(db,
                     "SELECT p.point_key, group_concat(printf('%.17g', z.max_force_n), ' ') FROM "
                     "ensemble_members p JOIN ensemble_member_zones z USING (point_id) GROUP BY "
                     "p.point_id ORDER BY p.point_id")) {
    const auto bar = row.rfind('|');
    m[row.substr(0, bar)] = row.substr(bar + 1);
  }
  return m;
}

TEST_F(EnsembleStudyTest, RerunningOneMemberGivesTheSameMaximaBitForBit) {
  const std::string spec = Write(SmallEnsemble(3));
  const std::string db = Path("e.db");
  ASSERT_EQ(Run(spec, db).exit_code, 0);
  const EnsembleStudy kind(std::get<EnsembleStudySpec>(ReadStudyFile(spec)));
  for (const EnsembleMember& m : {kind.Points()[1], kind.Points().back()}) {
    const auto out = kind.Score(m, {}, 0);
    ASSERT_EQ(out.status, RunStatus::kOk) << out.message;
    const std::string key = MemberKey(kind.Spec(), m);
    Connection c(db, Connection::Mode::kReadOnly);
    Statement s = c.Prepare(
        "SELECT z.max_force_n, p.member_seed FROM ensemble_members p JOIN ensemble_member_zones "
        "z USING (point_id) WHERE p.point_key = ? ORDER BY z.zone");
    s.Bind(1, key);
    std::size_t zone = 0;
    while (s.Step()) {
      ASSERT_LT(zone, out.score->zones.size());
      EXPECT_EQ(s.GetDouble(0), out.score->zones[zone].max_force_n) << key << " zone " << zone;
      EXPECT_EQ(s.GetText(1), out.score->member_seed);
      ++zone;
    }
    EXPECT_EQ(zone, out.score->zones.size());
  }
  // The members differ: the draws reach the runs.
  const auto maxima = ZoneMaxima(db);
  ASSERT_EQ(maxima.size(), 6u);
  EXPECT_NE(maxima.begin()->second, std::next(maxima.begin())->second);
}

// Two clearance states may share their gap laws: each keeps its name, its own nominal run
// stored under that name, and its members, in one run and when the study is run again.
TEST_F(EnsembleStudyTest, TwoStatesWithTheSameGapsKeepTheirNames) {
  json spec = SmallEnsemble(2);
  spec["clearance_states"][1] = spec["clearance_states"][0];
  spec["clearance_states"][1]["name"] = "also_new";
  const std::string file = Write(spec), db = Path("e.db");
  const auto run = Run(file, db);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::vector<std::string> nominal = {"also_new|ok", "new|ok"};
  EXPECT_EQ(testing::Rows(db, "SELECT state, status FROM ensemble_references ORDER BY state"),
            nominal);
  const char* members_by_nominal =
      "SELECT count(*) FROM ensemble_members p JOIN ensemble_references r USING (reference_id) "
      "WHERE p.state = r.state AND p.status = 'ok'";
  EXPECT_EQ(Count(db, members_by_nominal), 4);
  const auto again = RunShockmap("study run " + file + " --db " + db + " --retry-failed --quiet");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(testing::Rows(db, "SELECT state, status FROM ensemble_references ORDER BY state"),
            nominal);
}

TEST_F(EnsembleStudyTest, AddedMembersAreTheOnlyOnesComputed) {
  const std::string db = Path("e.db");
  ASSERT_EQ(Run(Write(SmallEnsemble(3)), db).exit_code, 0);
  const auto before =
      testing::Rows(db, "SELECT point_key, run_id, updated_utc FROM ensemble_members");
  const auto grown = Run(Write(SmallEnsemble(5)), db);
  ASSERT_EQ(grown.exit_code, 0) << grown.output;
  EXPECT_NE(grown.output.find("10 points in the study, 4 computed now"), std::string::npos)
      << grown.output;
  const auto after =
      testing::Rows(db, "SELECT point_key, run_id, updated_utc FROM ensemble_members");
  ASSERT_EQ(after.size(), 10u);
  for (const std::string& row : before) {
    EXPECT_NE(std::find(after.begin(), after.end(), row), after.end()) << row << " was recomputed";
  }
  // A member does not depend on how many there are.
  const std::string alone = Path("alone.db");
  ASSERT_EQ(Run(Write(SmallEnsemble(5), "alone.json"), alone).exit_code, 0);
  EXPECT_EQ(ZoneMaxima(db), ZoneMaxima(alone));
}

// The sizing table without what depends on the machine (wall and CPU time).
json SizingOf(const std::string& db) {
  const auto out = RunShockmap("sizing --db " + db + " --format json");
  EXPECT_EQ(out.exit_code, 0) << out.output;
  json rows = json::parse(out.output);
  for (json& row : rows) row.erase("wall_s_per_member"), row.erase("cpu_s_per_member");
  return rows;
}

TEST_F(EnsembleStudyTest, AStudyKilledMidEnsembleResumesToTheSameTable) {
  const std::string spec = Write(SmallEnsemble(40));
  const std::string whole = Path("whole.db"), killed = Path("killed.db");
  ASSERT_EQ(Run(spec, whole).exit_code, 0);
  const pid_t pid = fork();
  if (pid == 0) {
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(SHOCKMAP_BIN, SHOCKMAP_BIN, "study", "run", spec.c_str(), "--db", killed.c_str(),
          "--jobs", "2", "--quiet", static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    try {
      if (Count(killed, "SELECT count(*) FROM ensemble_members WHERE status = 'ok'") >= 5) break;
    } catch (const std::exception&) {
      // Not created or not migrated yet.
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the study finished before it could be killed";
  EXPECT_GT(Count(killed, "SELECT count(*) FROM ensemble_members WHERE status <> 'ok'"), 0);
  ASSERT_EQ(Run(spec, killed).exit_code, 0);
  EXPECT_EQ(ZoneMaxima(killed), ZoneMaxima(whole));
  EXPECT_EQ(SizingOf(killed), SizingOf(whole));
}

TEST_F(EnsembleStudyTest, SizingIsTheStatisticsOfTheStoredMaxima) {
  json spec = SmallEnsemble(64);
  spec["clearance_states"].erase(1);
  spec["window_s"] = 0.01;
  const std::string db = Path("e.db");
  ASSERT_EQ(Run(Write(spec), db).exit_code, 0);
  const json rows = SizingOf(db);
  ASSERT_GT(rows.size(), 1u);
  int checked = 0;
  for (const json& row : rows) {
    if (row["zone"] != "pin_7-pin_8@1.2192" && row["hottest"] != 1) continue;
    std::vector<double> forces;
    Connection c(db, Connection::Mode::kReadOnly);
    Statement zone = c.Prepare(
        "SELECT z.max_force_n FROM ensemble_members p JOIN ensemble_member_zones z USING "
        "(point_id) JOIN ensemble_references r ON r.reference_id = p.reference_id, "
        "json_each(r.zones_json) j WHERE j.key = z.zone AND json_extract(j.value, '$.name') = ? "
        "ORDER BY p.point_id");
    zone.Bind(1, row["zone"].get<std::string>());
    while (zone.Step()) forces.push_back(zone.GetDouble(0));
    ASSERT_EQ(forces.size(), 64u);
    const QuantileInterval p95 = EstimateQuantile(forces, 0.95, 0.95);
    EXPECT_EQ(row["p95_n"].get<double>(), p95.estimate);
    // An unbounded side (too few members for it) is an infinite bound.
    EXPECT_EQ(row["p95_lower_n"], p95.lower_bounded ? json(p95.lower) : json("-inf"));
    EXPECT_EQ(row["p95_upper_n"], p95.upper_bounded ? json(p95.upper) : json("inf"));
    // 64 members allow Wilks' first order only at 95/95 (the second needs 93): the largest.
    EXPECT_EQ(row["wilks_order"].get<int>(), 1);
    EXPECT_EQ(row["wilks_limit_n"].get<double>(), *std::max_element(forces.begin(), forces.end()));
    EXPECT_LE(row["bootstrap_lower_n"].get<double>(), row["bootstrap_upper_n"].get<double>());
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(ZoneFamilyTest, FamiliesComeFromTheBeamsTheBundleGeneratorNames) {
  EXPECT_EQ(FamilyOfZone("pin_0", "pin_12"), ZoneFamily::kPinPinWire);
  EXPECT_EQ(FamilyOfZone("pin_3", "wrapper"), ZoneFamily::kPinWrapper);
  EXPECT_EQ(FamilyOfZone("wrapper", "pin_3"), ZoneFamily::kPinWrapper);
  EXPECT_EQ(FamilyOfZone("wrapper", "stop"), ZoneFamily::kDuctPad);
  // Listed beams of other names, a pin against a stop, a name that is no generated pin's.
  EXPECT_EQ(FamilyOfZone("pin_3", "stop"), ZoneFamily::kOther);
  EXPECT_EQ(FamilyOfZone("pin_a", "pin_1"), ZoneFamily::kOther);
  EXPECT_EQ(FamilyOfZone("pin_", "wrapper"), ZoneFamily::kOther);
  EXPECT_EQ(FamilyOfZone("beam", "stop"), ZoneFamily::kOther);
  EXPECT_EQ(FamilyName(ZoneFamily::kDuctPad), "duct pad");
}

// The shipped hexagonal ensemble over a shorter window: every family of the bundle is sized,
// and each family's hottest zone is the highest sizing estimate among that family's zones.
TEST_F(EnsembleStudyTest, EachFamilysHottestZoneIsTheHighestOfItsZones) {
  json spec = json::parse(
      std::ifstream(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/bundle_hex_ensemble.json"));
  spec["scene"] = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_hex_7.json";
  spec["window_s"] = kHexWindowS;
  const std::string db = Path("hex.db");
  ASSERT_EQ(Run(Write(spec), db).exit_code, 0);
  // (state, family) -> the highest p95 of the family's zones, and the row marked its hottest.
  std::map<std::pair<std::string, std::string>, double> highest;
  std::map<std::pair<std::string, std::string>, std::vector<json>> marked;
  for (const json& row : SizingOf(db)) {
    const std::pair key{row["state"].get<std::string>(), row["family"].get<std::string>()};
    const double p95 = row["p95_n"];
    highest[key] = std::max(highest.contains(key) ? highest[key] : p95, p95);
    if (row["family_hottest"] == 1) marked[key].push_back(row);
  }
  std::set<std::string> families;
  for (const auto& [key, value] : highest) {
    families.insert(key.second);
    ASSERT_EQ(marked[key].size(), 1u) << key.first << " " << key.second;
    EXPECT_EQ(marked[key].front()["p95_n"].get<double>(), value) << key.first << " " << key.second;
  }
  EXPECT_EQ(families, (std::set<std::string>{"pin-pin wire", "duct pad", "pin-wrapper"}));
  EXPECT_EQ(highest.size(), 6u);  // Two states by three families.
  // The terminal's table: one row per state and family, within 120 characters.
  const auto table = RunShockmap("sizing --db " + db);
  ASSERT_EQ(table.exit_code, 0) << table.output;
  std::istringstream lines(table.output);
  int family_rows = 0;
  for (std::string line; std::getline(lines, line);) {
    EXPECT_LE(line.size(), 120u) << line;
    for (const std::string& family : families)
      family_rows += line.find("  " + family + " ") != std::string::npos;
  }
  EXPECT_EQ(family_rows, 6) << table.output;
  // One setting, said once by name above the table, never as its stored JSON.
  EXPECT_NE(table.output.find("setting: the scene's own: R_ftrunc = 300, dt = 0.1 dt_sharp\n"),
            std::string::npos)
      << table.output;
  EXPECT_EQ(table.output.find("{}"), std::string::npos) << table.output;
}

// The shipped 7-pin hexagonal ensemble, two members per state over a short window.
json SmallHexEnsemble() {
  json spec = json::parse(
      std::ifstream(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/bundle_hex_ensemble.json"));
  spec["scene"] = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_hex_7.json";
  spec["window_s"] = 0.01;
  spec["members"] = 2;
  return spec;
}

// reference_id -> the nominal run's zones_json.
std::map<std::string, std::string> ZonesJson(const std::string& db) {
  std::map<std::string, std::string> zones;
  for (const std::string& row :
       testing::Rows(db, "SELECT reference_id, zones_json FROM ensemble_references")) {
    const auto bar = row.find('|');
    zones[row.substr(0, bar)] = row.substr(bar + 1);
  }
  return zones;
}

// The sizing table's rows name each zone once per clearance state and setting.
TEST_F(EnsembleStudyTest, SizingRowsNameEachZoneOfAHexagonalBundleOnce) {
  const std::string db = Path("hex.db");
  ASSERT_EQ(Run(Write(SmallHexEnsemble()), db).exit_code, 0);
  std::map<std::string, int> rows;  // state and zone -> rows
  for (const json& row : SizingOf(db))
    ++rows[row["state"].get<std::string>() + " " + row["zone"].get<std::string>()];
  EXPECT_EQ(rows.size(), 2u * 211u);  // Two states by the 211 zones of the 7-pin bundle.
  for (const auto& [zone, count] : rows) EXPECT_EQ(count, 1) << zone;
}

// A database written before the wrapper faces of a hexagonal bundle were named by direction
// gave three faces of a pin one name ("pin_0-wrapper@0.3048"): the migration names each face as
// the scene reader now does, so that the file reads as one written now, and every zone row is
// kept.
TEST_F(EnsembleStudyTest, AnOlderDatabasesWrapperFacesAreNamedByTheMigration) {
  const std::string spec = Write(SmallHexEnsemble());
  const std::string db = Path("hex.db"), older = Path("older.db");
  ASSERT_EQ(Run(spec, db).exit_code, 0);
  const auto now = ZonesJson(db);
  ASSERT_EQ(now.size(), 2u);
  std::filesystem::copy_file(db, older);
  {
    Connection c(older, Connection::Mode::kReadWriteCreate);
    Statement set =
        c.Prepare("UPDATE ensemble_references SET zones_json = ? WHERE reference_id = ?");
    const std::regex face("_[0-9]+deg@");
    for (const auto& [id, zones] : now) {
      const std::string as_before = std::regex_replace(zones, face, "@");
      ASSERT_NE(as_before, zones);
      set.Bind(1, as_before).Bind(2, static_cast<std::int64_t>(std::stoll(id))).Run();
    }
    // Back to schema 13, before the faces were named: what later versions added goes (the
    // scores' reference_undecided of 15, which the results view reads; 15 rewrites the view).
    c.Execute(
        "DROP VIEW results; ALTER TABLE scores DROP COLUMN reference_undecided; "
        "CREATE VIEW results AS SELECT * FROM points; PRAGMA user_version = 13");
  }
  ASSERT_EQ(testing::Rows(older,
                          "SELECT count(DISTINCT json_extract(j.value, '$.name')) FROM "
                          "ensemble_references r, json_each(r.zones_json) j "
                          "WHERE r.reference_id = 1"),
            std::vector<std::string>{"127"});  // 84 wires, 42 names of 126 faces, the duct pad.
  const auto rerun = Run(spec, older);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_EQ(ZonesJson(older), now);
  EXPECT_EQ(ZoneMaxima(older), ZoneMaxima(db));
  EXPECT_EQ(SizingOf(older), SizingOf(db));
}

// A stored nominal run that names two zones alike (a file edited by hand, or one the migration
// could not name) is refused by the readers, which label rows by zone name.
TEST_F(EnsembleStudyTest, ZoneNamesGivenTwiceInADatabaseAreRefusedByItsReaders) {
  const std::string db = Path("hex.db");
  ASSERT_EQ(Run(Write(SmallHexEnsemble()), db).exit_code, 0);
  Connection(db, Connection::Mode::kReadWriteCreate)
      .Execute(
          "UPDATE ensemble_references SET zones_json = json_set(zones_json, '$[1].name', "
          "json_extract(zones_json, '$[0].name'))");
  const std::string name = testing::Rows(
      db, "SELECT json_extract(zones_json, '$[0].name') FROM ensemble_references LIMIT 1")[0];
  for (const std::string& command :
       {"sizing --db " + db, "report --db " + db + " --out " + Path("report")}) {
    const auto out = RunShockmap(command);
    EXPECT_EQ(out.exit_code, 2) << command << ": " << out.output;
    EXPECT_NE(out.output.find("zones_json: zones 0, 1 are all named \"" + name +
                              "\"; zone names must be unique"),
              std::string::npos)
        << command << ": " << out.output;
  }
}

TEST_F(EnsembleStudyTest, BadStudyFilesAreRefusedWithExitCode2) {
  struct Case {
    std::string what;
    std::function<void(json&)> edit;
    std::vector<std::string> expected;  // In the message.
  };
  const std::vector<Case> cases = {
      {"members", [](json& s) { s["members"] = 0; }, {"members", "0", "[1, 100000]"}},
      {"seed", [](json& s) { s["seed"] = -3; }, {"seed", "-3", "non-negative integer"}},
      {"law",
       [](json& s) {
         s["draws"]["bundle.wire.stiffness_n_per_m"] = {{"weibull", {{"k", 2}}}};
       },
       {"draws.bundle.wire.stiffness_n_per_m", "weibull", "normal", "lognormal", "uniform"}},
      {"path",
       [](json& s) {
         s["draws"]["solver.nothing"] = {{"normal", {{"std", 1}}}};
       },
       {"draws.solver.nothing", "no number"}},
      {"std",
       [](json& s) { s["clearance_states"][0]["pin_gap_m"]["std"] = -1e-5; },
       {"clearance_states[0].pin_gap_m", "std", "[0, 1]"}},
      {"bound",
       [](json& s) {
         s["draws"]["bundle.wire.stiffness_n_per_m"] = {{"uniform", {{"min", -1}, {"max", 1e6}}}};
       },
       {"bundle.wire.stiffness_n_per_m at its bound -1", "stiffness_n_per_m"}},
      {"refined",
       [](json& s) {
         s["settings"] = {{"solver.r_ftrunc", {30, 300}}};
         s["refined"] = {{"solver.r_ftrunc", 1000}};
       },
       {"refined", "1000", "not one of the settings", "{\"solver.r_ftrunc\":30}"}},
      {"state twice",
       [](json& s) { s["clearance_states"][1]["name"] = "new"; },
       {"clearance_states[1].name", "new", "twice"}},
      {"kind",
       [](json& s) { s["kind"] = "scene_ensembles"; },
       {"kind", "scene_ensembles", "canonical, scene_sweep, scene_ensemble"}},
  };
  for (const Case& c : cases) {
    json spec = SmallEnsemble(3);
    c.edit(spec);
    const std::string file = Write(spec, "bad.json");
    const auto out = Run(file, Path("bad.db"));
    EXPECT_EQ(out.exit_code, 2) << c.what << ": " << out.output;
    EXPECT_NE(out.output.find(file), std::string::npos) << c.what << ": " << out.output;
    for (const std::string& e : c.expected) {
      EXPECT_NE(out.output.find(e), std::string::npos)
          << c.what << ": no \"" << e << "\" in " << out.output;
    }
    EXPECT_FALSE(std::filesystem::exists(Path("bad.db"))) << c.what;
  }
}

}  // namespace
}  // namespace shockmap

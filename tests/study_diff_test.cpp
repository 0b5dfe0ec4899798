// `shockmap diff`: two studies compared point by point and R_k by R_k. Synthetic studies with a
// known change, then the command on stored studies.

#include "views/study_diff_text.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "db/sqlite_handle.h"
#include "tests/run_command.h"

namespace shockmap {
namespace {

using testing::RunShockmap;

// A study of R_k 1, 100, 1e4 by R_ftrunc 10, 30, 100, 300 at dt = 0.1 dt_sharp whose points
// pass (Err 0.05) from R_ftrunc = 3 sqrt(R_k) up and fail (Err 0.3) below: its boundary is 10,
// 30 and 300.
DiffedStudy SyntheticStudy(const std::string& name) {
  DiffedStudy s;
  s.name = name;
  s.database_path = "synthetic";
  s.settings = {{"window_s", 0.03}, {"psd.window", "hann"}, {"thresholds.err", 0.1}};
  for (double r_k : {1.0, 100.0, 1e4}) {
    for (double r_ftrunc : {10.0, 30.0, 100.0, 300.0}) {
      DiffPoint p;
      p.scheme = "explicit-modal";
      p.dt_rule = "sharp";
      p.dt_asked = 0.1;
      p.window_s = 0.03;
      p.scored.point_id = static_cast<std::int64_t>(s.points.size()) + 1;
      p.scored.r_k = r_k;
      p.scored.r_ftrunc = r_ftrunc;
      p.scored.status = RunStatus::kOk;
      p.scored.dt_s = 1e-6;
      p.scored.dt_sharp_s = 1e-5;
      p.scored.scores.Set("err", r_ftrunc >= 3.0 * std::sqrt(r_k) ? 0.05 : 0.3);
      p.scored.scores.Set("srf", 0.95);
      s.points.push_back(p);
    }
  }
  return s;
}

void Derive(DiffedStudy& s) {
  std::vector<ScoredPoint> points;
  for (const DiffPoint& p : s.points) points.push_back(p.scored);
  s.criteria = DeriveCriteria(points, CriteriaOptions{});
}

DiffPoint& PointAt(DiffedStudy& s, double r_k, double r_ftrunc) {
  for (DiffPoint& p : s.points) {
    if (p.scored.r_k == r_k && p.scored.r_ftrunc == r_ftrunc) return p;
  }
  throw std::out_of_range("no such point");
}

TEST(StudyDiff, AStudyAgainstItselfHasNoDifference) {
  DiffedStudy a = SyntheticStudy("a");
  Derive(a);
  const StudyDiff d = DiffStudies(a, a, 1e-6);
  EXPECT_TRUE(d.settings.empty());
  EXPECT_EQ(d.matched.size(), a.points.size());
  EXPECT_TRUE(d.changed.empty());
  EXPECT_TRUE(d.only_a.empty());
  EXPECT_TRUE(d.only_b.empty());
  ASSERT_EQ(d.criteria.size(), 3u);
  for (const CriteriaRow& r : d.criteria) {
    EXPECT_FALSE(r.TruncationDiffers() || r.DtDiffers()) << r.r_k;
  }
  EXPECT_NE(DiffText(a, a, d).find("0 changed outcome, 0 in A only, 0 in B only"),
            std::string::npos);
}

// One point made to fail in B: it alone changes outcome, and the boundary moves at its R_k only,
// from 30 to the next truncation, 100.
TEST(StudyDiff, AKnownChangedPointIsReportedAloneWithTheBoundaryMoveAtItsRk) {
  DiffedStudy a = SyntheticStudy("a"), b = SyntheticStudy("b");
  PointAt(b, 100.0, 30.0).scored.scores.Set("err", 0.2);
  Derive(a);
  Derive(b);
  const StudyDiff d = DiffStudies(a, b, 1e-6);
  ASSERT_EQ(d.changed.size(), 1u);
  EXPECT_EQ(d.changed[0].a.scored.r_k, 100.0);
  EXPECT_EQ(d.changed[0].a.scored.r_ftrunc, 30.0);
  EXPECT_EQ(OutcomeOf(d.changed[0].a, a.criteria.options), "passes");
  EXPECT_EQ(OutcomeOf(d.changed[0].b, b.criteria.options), "fails thresholds");
  EXPECT_EQ(d.matched.size(), a.points.size());
  ASSERT_EQ(d.criteria.size(), 3u);
  for (const CriteriaRow& r : d.criteria) {
    EXPECT_EQ(r.TruncationDiffers(), r.r_k == 100.0) << r.r_k;
    EXPECT_FALSE(r.DtDiffers()) << r.r_k;
  }
  EXPECT_EQ(d.criteria[1].a->r_ftrunc_min, 30.0);
  EXPECT_EQ(d.criteria[1].b->r_ftrunc_min, 100.0);
  const Table points = DiffPointTable(a, b, d);
  const auto changed = *points.ColumnIndex("outcome_changed");
  int n_changed = 0;
  for (const auto& row : points.rows) n_changed += std::get<std::int64_t>(row[changed]) != 0;
  EXPECT_EQ(n_changed, 1);
}

// B studied at R_ftrunc 10, 50, 100, 300 where A studied 10, 30, 100, 300: at R_k = 100 A's
// boundary is 30 (10 fails) and B's 50 (10 fails), each decided by a point the other did not
// study, so they are not comparable there; no point changed outcome. Once B's point at 100
// fails too, its boundary (300, above a failing 100) is one A's passing 100 contradicts.
TEST(StudyDiff, BoundariesOnDifferentGridsDifferOnlyWhereTheirDecidingPointsSaySo) {
  DiffedStudy a = SyntheticStudy("a"), b = SyntheticStudy("b");
  for (DiffPoint& p : b.points) {
    if (p.scored.r_ftrunc == 30.0) {
      p.scored.r_ftrunc = 50.0;
      p.scored.scores.Set("err", 50.0 >= 3.0 * std::sqrt(p.scored.r_k) ? 0.05 : 0.3);
    }
  }
  Derive(a);
  Derive(b);
  const StudyDiff d = DiffStudies(a, b, 1e-6);
  EXPECT_TRUE(d.changed.empty());
  ASSERT_EQ(d.criteria.size(), 3u);
  for (const CriteriaRow& r : d.criteria) {
    EXPECT_FALSE(r.TruncationDiffers() || r.DtDiffers()) << r.r_k;
    EXPECT_EQ(r.Comparable(), r.r_k != 100.0) << r.r_k;
  }
  EXPECT_EQ(d.criteria[1].a->r_ftrunc_min, 30.0);
  EXPECT_EQ(d.criteria[1].b->r_ftrunc_min, 50.0);
  EXPECT_EQ(d.criteria[1].grids_differ, "R_ftrunc 30 in A only, 50 in B only");
  const std::string text = DiffText(a, b, d);
  EXPECT_NE(text.find("boundary     differs at 0 of 3 R_k; not comparable at 1"), std::string::npos)
      << text;
  EXPECT_NE(text.find("not comparable: grids differ at R_ftrunc 30 in A only, 50 in B only"),
            std::string::npos)
      << text;
  EXPECT_EQ(DiffToJson(a, b, d)["criteria"]["by_r_k"][1]["comparable"], false);

  PointAt(b, 100.0, 100.0).scored.scores.Set("err", 0.2);
  Derive(b);
  const StudyDiff moved = DiffStudies(a, b, 1e-6);
  EXPECT_EQ(moved.criteria[1].b->r_ftrunc_min, 300.0);
  EXPECT_TRUE(moved.criteria[1].TruncationDiffers());
  EXPECT_TRUE(moved.criteria[1].Comparable());
  EXPECT_NE(DiffText(a, b, moved).find("boundary     differs at 1 of 3 R_k\n"), std::string::npos);
}

// Points match when their numbers agree within the tolerance, and only then; a point of one
// study only is counted on its side.
TEST(StudyDiff, PointsMatchWithinTheToleranceAndThoseOfOneStudyAreCounted) {
  DiffedStudy a = SyntheticStudy("a"), b = SyntheticStudy("b");
  for (DiffPoint& p : b.points) p.scored.r_k *= 1.0 + 1e-9;
  DiffPoint extra = b.points.back();
  extra.scored.r_ftrunc = 1000.0;
  b.points.push_back(extra);
  Derive(a);
  Derive(b);
  const StudyDiff loose = DiffStudies(a, b, 1e-6);
  EXPECT_EQ(loose.matched.size(), a.points.size());
  EXPECT_TRUE(loose.only_a.empty());
  ASSERT_EQ(loose.only_b.size(), 1u);
  EXPECT_EQ(loose.only_b[0].scored.r_ftrunc, 1000.0);
  const StudyDiff strict = DiffStudies(a, b, 1e-12);
  EXPECT_TRUE(strict.matched.empty());
  EXPECT_EQ(strict.only_a.size(), a.points.size());
  EXPECT_EQ(strict.only_b.size(), b.points.size());
}

TEST(StudyDiff, ADifferentWindowIsRefusedAndADifferentTaperReported) {
  DiffedStudy a = SyntheticStudy("a"), b = SyntheticStudy("b");
  Derive(a);
  Derive(b);
  b.settings["psd.window"] = "rectangular";
  const StudyDiff d = DiffStudies(a, b, 1e-6);
  ASSERT_EQ(d.settings.size(), 1u);
  EXPECT_EQ(d.settings[0].setting, "psd.window");
  b.settings["window_s"] = 0.3;
  try {
    DiffStudies(a, b, 1e-6);
    ADD_FAILURE() << "a different window was compared";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("window_s (0.03 in A, 0.3 in B)"), std::string::npos)
        << e.what();
  }
}

// The command on stored studies: `quick`, a copy of it with one score changed in the database,
// a study scored over another window and a scene sweep.
class DiffCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::filesystem::temp_directory_path() / ("shockmap_diff_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
    db_ = (dir_ / "diff.db").string();
    const std::string source = SHOCKMAP_SOURCE_DIR;
    nlohmann::json copy = nlohmann::json::parse(std::ifstream(source + "/studies/quick.json"));
    copy["name"] = "quick_copy";
    nlohmann::json other_grid = copy;
    other_grid["name"] = "quick_other_grid";
    other_grid["grids"][0]["rk"] = {{"logspace", {3, 5, 5}}};
    other_grid["grids"][0]["rftrunc"] = {{"logspace", {1.5, 3, 4}}};
    other_grid["grids"][0]["dt"]["factor"] = {0.1, 0.5};
    nlohmann::json window = copy;
    window["name"] = "quick_window";
    window["scoring"]["window_s"] = 0.02;
    window["grids"][0]["rk"] = 10;
    const nlohmann::json sweep{{"kind", "scene_sweep"},
                               {"name", "sweep"},
                               {"scene", source + "/scenes/cantilever_spring.json"},
                               {"sweep", {{"solver.r_ftrunc", {10, 30}}}},
                               {"reference", {{"solver.r_ftrunc", 100}}},
                               {"scoring",
                                {{"displacement", "tip"},
                                 {"zone", "tip_spring"},
                                 {"window_s", 0.02},
                                 {"rest_duration_s", 0.005}}}};
    for (const auto& [name, json] : {std::pair{"copy", copy},
                                     {"other_grid", other_grid},
                                     {"window", window},
                                     {"sweep", sweep}}) {
      std::ofstream(dir_ / (std::string(name) + ".json")) << json.dump();
    }
    for (const std::string& file :
         {source + "/studies/quick.json", (dir_ / "copy.json").string(),
          (dir_ / "other_grid.json").string(), (dir_ / "window.json").string(),
          (dir_ / "sweep.json").string()}) {
      const auto run = RunShockmap("study run " + file + " --db " + db_ + " --quiet");
      ASSERT_EQ(run.exit_code, 0) << run.output;
    }
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }

  static inline std::filesystem::path dir_;
  static inline std::string db_;
};

TEST_F(DiffCommand, AStoredStudyAgainstItselfHasNoDifference) {
  const auto run = RunShockmap("diff quick quick --db " + db_);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("settings     alike"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("boundary     differs at 0 of 11 R_k"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("308 at the same parameters; 0 changed outcome, 0 in A only, 0 in "
                            "B only"),
            std::string::npos)
      << run.output;
}

// The copy's point at R_k = 1, R_ftrunc = 1000 (the largest), dt = 0.1 dt_sharp is made to fail
// Err in the database: the CSV flags that point alone, and at R_k = 1 no truncation passes any
// more.
TEST_F(DiffCommand, AScoreChangedInTheDatabaseIsThatPointAloneAndMovesItsRk) {
  {
    Connection db(db_, Connection::Mode::kReadWriteCreate);
    db.Execute(
        "UPDATE scores SET err = 0.9 WHERE point_id = (SELECT point_id FROM results WHERE "
        "study = 'quick_copy' AND r_k = 1 AND r_ftrunc = 1000 AND dt_factor = 0.1)");
  }
  const auto csv = RunShockmap("diff quick quick_copy --db " + db_ + " --format csv");
  ASSERT_EQ(csv.exit_code, 0) << csv.output;
  std::istringstream lines(csv.output);
  std::vector<std::vector<std::string>> rows;  // No value of this table holds a comma.
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  ASSERT_EQ(rows.size(), 309u) << csv.output;
  const auto changed_column = std::ranges::find(rows[0], "outcome_changed") - rows[0].begin();
  std::vector<std::vector<std::string>> changed;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].at(changed_column) == "1") changed.push_back(rows[i]);
  }
  ASSERT_EQ(changed.size(), 1u) << csv.output;
  EXPECT_EQ(std::vector<std::string>(changed[0].begin(), changed[0].begin() + 11),
            (std::vector<std::string>{"explicit-modal", "1", "1000", "sharp", "0.1", "0.03", "0",
                                      "both", "passes", "fails thresholds", "1"}));
  const auto json = RunShockmap("diff quick quick_copy --db " + db_ + " --format json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const auto report = nlohmann::json::parse(json.output);
  ASSERT_EQ(report["points"]["changed"].size(), 1u);
  for (const auto& row : report["criteria"]["by_r_k"]) {
    EXPECT_EQ(row["r_ftrunc_differs"].get<bool>(), row["r_k"].get<double>() == 1.0) << row;
  }
}

// quick against a study of R_k 1e3 to 1e5 on R_ftrunc 31.6, 100, 316, 1000 at dt 0.1 and 0.5
// dt_sharp: the points studied in both keep their outcome, so no boundary may be said to differ;
// where the grids decide it apart the table says so. `criteria check` of the other study
// against quick's criteria agrees (exit 0) and names what it cannot compare.
TEST_F(DiffCommand, AnotherGridIsNotComparableRatherThanADifferentBoundary) {
  const auto json = RunShockmap("diff quick quick_other_grid --db " + db_ + " --format json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const auto report = nlohmann::json::parse(json.output);
  std::set<double> changed_r_k;
  for (const auto& p : report["points"]["changed"]) changed_r_k.insert(p["r_k"].get<double>());
  int not_comparable = 0;
  for (const auto& row : report["criteria"]["by_r_k"]) {
    const bool changed = changed_r_k.contains(row["r_k"].get<double>());
    EXPECT_TRUE(!row["r_ftrunc_differs"].get<bool>() || changed) << row;
    EXPECT_TRUE(!row["dt_differs"].get<bool>() || changed) << row;
    not_comparable += !row["comparable"].get<bool>();
  }
  EXPECT_GT(not_comparable, 0) << report["criteria"]["by_r_k"];
  const auto text = RunShockmap("diff quick quick_other_grid --db " + db_);
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("; not comparable at " + std::to_string(not_comparable) + ":"),
            std::string::npos)
      << text.output;
  EXPECT_NE(text.output.find("not comparable: grids differ at R_ftrunc "), std::string::npos)
      << text.output;

  const std::string baseline = (dir_ / "quick_criteria.json").string();
  const auto derive = RunShockmap("criteria derive quick --db " + db_ + " --out " + baseline);
  ASSERT_EQ(derive.exit_code, 0) << derive.output;
  const auto check =
      RunShockmap("criteria check quick_other_grid --db " + db_ + " --baseline " + baseline);
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("agrees with " + baseline), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("not comparable: grids differ at R_k"), std::string::npos)
      << check.output;
}

TEST_F(DiffCommand, RefusesAnUnknownStudyAnotherWindowAndASceneSweep) {
  const auto unknown = RunShockmap("diff quick nosuch --db " + db_);
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("no study named \"nosuch\""), std::string::npos) << unknown.output;
  const auto window = RunShockmap("diff quick quick_window --db " + db_);
  EXPECT_EQ(window.exit_code, 2) << window.output;
  EXPECT_NE(window.output.find("window_s (0.03 in A, 0.02 in B)"), std::string::npos)
      << window.output;
  const auto sweep = RunShockmap("diff quick sweep --db " + db_);
  EXPECT_EQ(sweep.exit_code, 2) << sweep.output;
  EXPECT_NE(sweep.output.find("STUDY B: study sweep"), std::string::npos) << sweep.output;
  EXPECT_NE(sweep.output.find("scene_sweep"), std::string::npos) << sweep.output;
}

TEST_F(DiffCommand, DrawsBothBoundariesOnOneMap) {
  const std::string image = (dir_ / "maps" / "diff.png").string();
  const auto run = RunShockmap("diff quick quick --db " + db_ + " --out " + image);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ASSERT_TRUE(std::filesystem::exists(image)) << run.output;
  const std::string script = testing::ReadBytes((dir_ / "maps" / "diff.gp").string());
  EXPECT_NE(script.find("boundary of A, quick"), std::string::npos) << script;
  EXPECT_NE(script.find("boundary of B, quick"), std::string::npos) << script;
}

}  // namespace
}  // namespace shockmap

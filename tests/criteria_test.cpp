// Validity criteria end to end: derived from a study, checked against the shipped baseline, and
// a corrupted score caught by the regression check.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "analysis/scored_points.h"
#include "compare/score_spread.h"
#include "core/input_error.h"
#include "db/read_only_query.h"
#include "db/sqlite_handle.h"
#include "formats/criteria_json.h"
#include "tests/run_command.h"
#include "validation/advice.h"
#include "validation/validity_criteria.h"
#include "views/criteria_report.h"
#include "views/map_grid.h"

namespace shockmap {
namespace {

using testing::RunShockmap;

class QuickStudyCriteria : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    db_ = (std::filesystem::temp_directory_path() /
           ("shockmap_criteria_" + std::to_string(getpid()) + ".db"))
              .string();
    std::filesystem::remove(db_);
    const auto run =
        RunShockmap("study run " + Source("studies/quick.json") + " --db " + db_ + " --quiet");
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  static void TearDownTestSuite() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db_ + suffix);
  }
  static std::string Source(const std::string& relative) {
    return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
  }
  static inline std::string db_;
};

TEST_F(QuickStudyCriteria, AgreeWithTheShippedBaseline) {
  const auto check = RunShockmap("criteria check --db " + db_ + " --baseline " +
                                 Source("studies/baselines/quick.json"));
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("agrees"), std::string::npos) << check.output;
}

// From scoring.spread.from_rk (1e4 by default) every point that ended ok stores its scores'
// spread over the perturbed runs, its own scores inside it; below, none.
TEST_F(QuickStudyCriteria, PointsFromTheSpreadsRkStoreTheirScoresSpread) {
  const std::vector<ScoredPoint> points = LoadCriteriaPoints(db_, "quick");
  int with_spread = 0;
  for (const ScoredPoint& p : points) {
    const bool expected = p.status == RunStatus::kOk && p.r_k >= 1e4;
    ASSERT_EQ(p.spread_runs > 0, expected) << "point " << p.point_id;
    if (!expected) continue;
    ++with_spread;
    EXPECT_LE(p.spread_runs, static_cast<int>(kScorePerturbations.size()))
        << "point " << p.point_id;
    for (const char* score : {"err", "srf"}) {
      if (!p.scores[score]) continue;
      EXPECT_LE(*p.spread_low[score], *p.scores[score]) << score << ", point " << p.point_id;
      EXPECT_GE(*p.spread_high[score], *p.scores[score]) << score << ", point " << p.point_id;
    }
  }
  EXPECT_GT(with_spread, 0);
  // The criteria set aside exactly the points whose spread straddles a threshold.
  const ValidityCriteria c = DeriveCriteria(points, CriteriaOptions{});
  long long undecided = 0, listed = 0;
  for (const ScoredPoint& p : points) undecided += c.options.Undecided(p);
  for (const PointsSetAside& u : c.undecided) listed += u.n_points;
  EXPECT_EQ(listed, undecided);
  const auto derive = RunShockmap("criteria derive --db " + db_);
  EXPECT_EQ(derive.output.find("undecided") != std::string::npos, undecided > 0) << derive.output;
  std::printf("quick: %d points with a spread, %lld undecided\n", with_spread, undecided);
}

TEST_F(QuickStudyCriteria, DeriveReportsTheFitAndThePaperRules) {
  const auto derive = RunShockmap("criteria derive --db " + db_);
  ASSERT_EQ(derive.exit_code, 0) << derive.output;
  for (const char* text : {"interval", "paper eq. 10", "paper eq. 11", "dt_sharp"}) {
    EXPECT_NE(derive.output.find(text), std::string::npos) << text << "\n" << derive.output;
  }
}

std::int64_t CountOf(const std::string& db, const std::string& sql) {
  return std::get<std::int64_t>(RunReadOnlyQuery(db, sql).rows.at(0).at(0));
}

// Paper eq. 11's step is counted once per (R_k, R_ftrunc) cell, and the stability line never
// says "stable up to" a ratio it also says stability was lost at; the counts come from SQL.
TEST_F(QuickStudyCriteria, StabilityAndPaperStepLinesAreConsistentAndCountCells) {
  const auto derive = RunShockmap("criteria derive --db " + db_);
  ASSERT_EQ(derive.exit_code, 0) << derive.output;
  const std::int64_t cells =
      CountOf(db_,
              "SELECT count(*) FROM (SELECT DISTINCT r_k, r_ftrunc FROM results "
              "WHERE scheme = 'explicit-modal')");
  const std::int64_t beyond =
      CountOf(db_,
              "SELECT count(*) FROM (SELECT DISTINCT r_k, r_ftrunc FROM results "
              "WHERE scheme = 'explicit-modal' AND dt_paper_s > dt_sharp_s)");
  EXPECT_NE(derive.output.find("in " + std::to_string(beyond) + " of " + std::to_string(cells) +
                               " (R_k, R_ftrunc) cells"),
            std::string::npos)
      << derive.output;
  const std::int64_t unstable = CountOf(db_,
                                        "SELECT count(*) FROM results WHERE status = "
                                        "'unstable'");
  EXPECT_GT(unstable, 0);
  EXPECT_NE(derive.output.find("stayed stable up to 0.9 dt_sharp; at 1.5 dt_sharp"),
            std::string::npos)
      << derive.output;
  EXPECT_NE(derive.output.find("and " + std::to_string(unstable) + " ended unstable"),
            std::string::npos)
      << derive.output;
}

TEST_F(QuickStudyCriteria, CorruptedScoreIsCaughtAndNamed) {
  const std::string copy = db_ + ".corrupt.db";
  std::filesystem::copy_file(db_, copy, std::filesystem::copy_options::overwrite_existing);
  // The most truncated, finest-step point at the stiffest R_k meets every criterion.
  const Table target = RunReadOnlyQuery(
      copy,
      "SELECT point_id FROM results WHERE status = 'ok' ORDER BY r_k DESC, r_ftrunc DESC, "
      "dt_requested_s / dt_sharp_s ASC LIMIT 1");
  const auto point_id = std::get<std::int64_t>(target.rows.at(0).at(0));
  {
    Connection c(copy, Connection::Mode::kReadWriteCreate);
    c.Execute("UPDATE scores SET err = 0.9 WHERE point_id = " + std::to_string(point_id));
  }
  const auto check = RunShockmap("criteria check --db " + copy + " --baseline " +
                                 Source("studies/baselines/quick.json"));
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find("point " + std::to_string(point_id) + " "), std::string::npos)
      << check.output;
  EXPECT_NE(check.output.find("Err = 0.9"), std::string::npos) << check.output;
  std::filesystem::remove(copy);
}

// The points the derived criteria count as passing, summed over the studied R_k.
int Passing(const nlohmann::json& criteria) {
  int passing = 0;
  for (const auto& b : criteria.at("boundary")) passing += b.at("n_passing").get<int>();
  return passing;
}

// A study file's thresholds judge its criteria (a score without a default threshold, PFr, among
// them), and a flag replaces the study's threshold of its score.
TEST_F(QuickStudyCriteria, TheStudyFilesThresholdsJudgeUnlessAFlagIsGiven) {
  const std::string copy = db_ + ".thresholds.db", spec = db_ + ".strict.json";
  std::filesystem::copy_file(db_, copy, std::filesystem::copy_options::overwrite_existing);
  std::ifstream quick(Source("studies/quick.json"));
  nlohmann::json strict = nlohmann::json::parse(quick);
  strict["name"] = "quick_strict";
  strict["scoring"]["thresholds"] = {{"err_max", 0.05}, {"pfr_min", 0.9}};
  std::ofstream(spec) << strict.dump();
  const auto run = RunShockmap("study run " + spec + " --db " + copy + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto derive = [&](const std::string& args, const std::string& out) {
    const auto o = RunShockmap("criteria derive " + args + " --db " + copy + " --out " + out);
    EXPECT_EQ(o.exit_code, 0) << o.output;
    std::ifstream in(out);
    return std::make_pair(o.output, nlohmann::json::parse(in));
  };
  const auto [own, own_json] = derive("quick_strict", copy + ".own.json");
  EXPECT_NE(own.find("Err <= 0.05, SRf >= 0.8, PFr >= 0.9"), std::string::npos) << own;
  EXPECT_EQ(own_json.at("thresholds"),
            nlohmann::json({{"err_max", 0.05}, {"srf_min", 0.8}, {"pfr_min", 0.9}}));
  const auto [flagged, flagged_json] =
      derive("quick_strict --err-max 0.2 --pfr-min 0.5", copy + ".flagged.json");
  EXPECT_NE(flagged.find("Err <= 0.2, SRf >= 0.8, PFr >= 0.5"), std::string::npos) << flagged;
  const auto [plain, plain_json] = derive("quick", copy + ".plain.json");
  EXPECT_NE(plain.find("Err <= 0.1, SRf >= 0.8;"), std::string::npos) << plain;
  // The same scores judged more strictly pass fewer points.
  EXPECT_LT(Passing(own_json), Passing(plain_json));
  for (const std::string& f : {copy, spec, copy + ".own.json", copy + ".flagged.json",
                               copy + ".plain.json", copy + "-wal", copy + "-shm"}) {
    std::filesystem::remove(f);
  }
}

TEST(DeriveCriteria, RecoversAKnownPowerLaw) {
  // Synthetic study: a point passes exactly when R_ftrunc >= 2 R_k^0.5; truncations on a fine
  // logarithmic grid, so the fitted exponent must come back close to 0.5.
  std::vector<ScoredPoint> points;
  std::int64_t id = 0;
  for (int i = 0; i <= 12; ++i) {
    const double r_k = std::pow(10.0, 0.5 * i);
    for (int j = 0; j <= 40; ++j) {
      const double r_ftrunc = std::pow(10.0, 0.1 * j);
      const bool pass = r_ftrunc >= 2.0 * std::sqrt(r_k);
      ScoredPoint p;
      p.point_id = ++id;
      p.r_k = r_k;
      p.r_ftrunc = r_ftrunc;
      p.status = RunStatus::kOk;
      p.scores.Set("err", pass ? 0.01 : 0.5);
      p.scores.Set("srf", pass ? 0.99 : 0.5);
      p.dt_s = 1e-5;
      p.dt_sharp_s = p.dt_paper_s = 1e-4;
      p.wall_s = 1e-3;
      p.cpu_s = 10;
      p.n_modes = 1000;
      points.push_back(p);
    }
  }
  const ValidityCriteria c = DeriveCriteria(points, {});
  ASSERT_TRUE(c.fit.has_value());
  EXPECT_NEAR(c.fit->p, 0.5, 0.02);
  EXPECT_LE(c.fit->p_low, 0.5);
  EXPECT_GE(c.fit->p_high, 0.5);
  EXPECT_NEAR(c.fit->c, 2.0, 0.4);
  EXPECT_TRUE(FindContradictions(c, points).empty());
  ASSERT_TRUE(c.dt_ratio_max.has_value());
  EXPECT_DOUBLE_EQ(*c.dt_ratio_max, 0.1);
}

// Points whose reference did not converge carry no score: the boundary ignores them, and the
// criteria name their R_k, count and reason in the summary, the baseline and the advice.
TEST(DeriveCriteria, NamesThePointsItCouldNotScore) {
  std::vector<ScoredPoint> points;
  auto point = [&](double r_k, double r_ftrunc, RunStatus status, const std::string& message) {
    ScoredPoint p;
    p.point_id = static_cast<std::int64_t>(points.size()) + 1;
    p.r_k = r_k;
    p.r_ftrunc = r_ftrunc;
    p.status = status;
    if (status == RunStatus::kOk) {
      p.scores.Set("err", r_ftrunc >= std::sqrt(r_k) ? 0.01 : 0.5);
      p.scores.Set("srf", 0.99);
    }
    p.dt_s = 1e-5;
    p.dt_sharp_s = p.dt_paper_s = 1e-4;
    p.message = message;
    points.push_back(p);
  };
  // Listed out of R_k order, as a second grid or listed points store them.
  const std::vector<double> truncations = {10.0, 30.0, 100.0, 300.0};
  for (double r_ftrunc : truncations) point(10.0, r_ftrunc, RunStatus::kOk, "");
  point(1e6, 10.0, RunStatus::kReferenceUnconverged, "estimated error 0.05 above 0.02");
  for (double r_k : {100.0, 1e3, 1e4}) {
    for (double r_ftrunc : truncations) point(r_k, r_ftrunc, RunStatus::kOk, "");
  }
  point(1e5, 30.0, RunStatus::kReferenceUnconverged, "estimated error 0.03 above 0.02");
  point(1e6, 30.0, RunStatus::kReferenceUnconverged, "estimated error 0.05 above 0.02");

  const ValidityCriteria c = DeriveCriteria(points, {});
  ASSERT_EQ(c.boundary.size(), 4u);  // R_k = 10 to 1e4 only.
  ASSERT_EQ(c.unscored.size(), 2u);
  EXPECT_EQ(c.unscored[0].r_k, 1e5);
  EXPECT_EQ(c.unscored[0].n_points, 1);
  EXPECT_EQ(c.unscored[1].r_k, 1e6);
  EXPECT_EQ(c.unscored[1].n_points, 2);
  const auto warning = UnscoredWarning(c);
  ASSERT_TRUE(warning);
  EXPECT_NE(warning->find("3 points unscored, at R_k = 1e+05 (1), 1e+06 (2)"), std::string::npos)
      << *warning;
  EXPECT_NE(warning->find("estimated error 0.03 above 0.02"), std::string::npos) << *warning;
  EXPECT_NE(CriteriaSummary("s", c, points).find("not scored  " + *warning), std::string::npos);

  // The baseline keeps them, so `advise` can name them from the file alone. (Its fit runs
  // through two R_k, 1e3 and 1e4: no spread, written null and read back as such.)
  ASSERT_TRUE(c.fit);
  EXPECT_EQ(c.fit->n, 2);
  const ValidityCriteria read =
      CriteriaFromJson(nlohmann::json::parse(CriteriaToJson("s", c).dump()), "b.json", nullptr);
  ASSERT_EQ(read.unscored.size(), 2u);
  EXPECT_EQ(UnscoredWarning(read), warning);
  nlohmann::json forged = CriteriaToJson("s", c);
  forged["unscored"][1]["n_points"] = 0;
  try {
    CriteriaFromJson(forged, "b.json", nullptr);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.json: unscored[1].n_points"), std::string::npos)
        << e.what();
  }

  // The advice says it too, wherever it advises.
  const Advice advice = Advise(CantileverImpact{}, 0.03, c, points, 500.0);
  EXPECT_NE(std::ranges::find(advice.warnings, *warning), advice.warnings.end());

  point(1e6, 100.0, RunStatus::kOk, "");  // Scored at last: no longer listed as unscored.
  EXPECT_FALSE(UnscoredWarning(DeriveCriteria({points.back()}, {})));
}

// A point whose scores' spread over its perturbed runs straddles a threshold is
// undecided: it passes nowhere, so the boundary rises past it, and the criteria name it in the
// summary, the baseline, the advice and the maps' outcome.
TEST(DeriveCriteria, AnUndecidedPointPassesNowhereAndIsNamed) {
  std::vector<ScoredPoint> points;
  for (double r_ftrunc : {10.0, 30.0, 100.0, 300.0}) {
    ScoredPoint p;
    p.point_id = static_cast<std::int64_t>(points.size()) + 1;
    p.r_k = 1e4;
    p.r_ftrunc = r_ftrunc;
    p.status = RunStatus::kOk;
    p.scores.Set("err", r_ftrunc >= 30.0 ? 0.05 : 0.5);
    p.scores.Set("srf", 0.99);
    p.dt_s = 1e-5;
    p.dt_sharp_s = p.dt_paper_s = 1e-4;
    p.spread_runs = 5;
    p.spread_low = p.spread_high = p.scores;
    points.push_back(p);
  }
  const CriteriaOptions options;
  ASSERT_EQ(DeriveCriteria(points, options).boundary.at(0).r_ftrunc_min, 30.0);
  EXPECT_FALSE(UndecidedWarning(DeriveCriteria(points, options).undecided));

  // R_ftrunc 30 passes by its nominal run, but one perturbed run gives Err 0.13 (max 0.1).
  points[1].spread_high.Set("err", 0.13);
  EXPECT_TRUE(options.Undecided(points[1]));
  EXPECT_FALSE(options.Passes(points[1]));
  EXPECT_EQ(options.Straddling(points[1]), "Err from 0.05 to 0.13 (max 0.1) over 5 runs");
  const ValidityCriteria c = DeriveCriteria(points, options);
  EXPECT_EQ(c.boundary.at(0).r_ftrunc_min, 100.0);
  EXPECT_EQ(c.boundary.at(0).n_passing, 2);
  ASSERT_EQ(c.undecided.size(), 1u);
  EXPECT_EQ(c.undecided[0].n_points, 1);
  const auto warning = UndecidedWarning(c.undecided);
  ASSERT_TRUE(warning);
  EXPECT_NE(warning->find("left 1 point undecided, at R_k = 1e+04 (1)"), std::string::npos)
      << *warning;
  EXPECT_NE(warning->find("point 2 (R_ftrunc 30, dt 0.1 dt_sharp): Err from 0.05 to 0.13"),
            std::string::npos)
      << *warning;
  EXPECT_NE(CriteriaSummary("s", c, points).find("undecided   " + *warning), std::string::npos);
  EXPECT_EQ(OutcomeCategories()[OutcomeCategoryOf(points[1], options)].label, "undecided");
  EXPECT_EQ(OutcomeCategories()[OutcomeCategoryOf(points[2], options)].label, "passes");

  const ValidityCriteria read =
      CriteriaFromJson(nlohmann::json::parse(CriteriaToJson("s", c).dump()), "b.json", nullptr);
  EXPECT_EQ(UndecidedWarning(read.undecided), warning);
  const Advice advice = Advise(CantileverImpact{}, 0.03, c, points, 1e4);
  EXPECT_NE(std::ranges::find(advice.warnings, *warning), advice.warnings.end());

  // A spread wholly on one side decides, however wide: Err from 0.11 to 0.4 fails.
  points[1].scores.Set("err", 0.2);
  points[1].spread_low.Set("err", 0.11);
  points[1].spread_high.Set("err", 0.4);
  EXPECT_FALSE(options.Undecided(points[1]));
  EXPECT_EQ(OutcomeCategories()[OutcomeCategoryOf(points[1], options)].label, "fails thresholds");
  // SRf straddling its threshold decides nothing when Err fails in every run.
  points[1].spread_low.Set("srf", 0.79);
  points[1].spread_high.Set("srf", 0.9);
  EXPECT_FALSE(options.Undecided(points[1]));
  points[1].spread_low.Set("err", 0.05);  // Now Err straddles too: undecided.
  EXPECT_TRUE(options.Undecided(points[1]));
  EXPECT_EQ(options.Straddling(points[1]),
            "Err from 0.05 to 0.4 (max 0.1), SRf from 0.79 to 0.9 (min 0.8) over 5 runs");
}

// A point whose reference does not decide a thresholded score (its Err, at R_k 1e6 over 0.06 s,
// where the first shock is converged and the chatter after it is not) is undecided unless a
// decided score fails: it passes nowhere, is named with the reference's message, and a point
// whose reference decides every thresholded score is judged as before.
TEST(DeriveCriteria, AScoreTheReferenceDoesNotDecideLeavesThePointUndecided) {
  ScoredPoint p;
  p.point_id = 7;
  p.r_k = 1e6;
  p.r_ftrunc = 300.0;
  p.status = RunStatus::kOk;
  p.scores.Set("srf", 0.95);
  p.scores.Set("pfr", 0.9);
  p.reference_undecided = {"err"};
  p.message = "Err undecided: the reference's estimate on the window's tip is 0.16";
  p.dt_s = 1e-6;
  p.dt_sharp_s = p.dt_paper_s = 1e-5;
  const CriteriaOptions options;
  EXPECT_TRUE(options.Undecided(p));
  EXPECT_FALSE(options.Passes(p));
  EXPECT_EQ(options.Straddling(p), "Err undecided by the reference (" + p.message + ")");
  EXPECT_EQ(OutcomeCategories()[OutcomeCategoryOf(p, options)].label, "undecided");
  const ValidityCriteria c = DeriveCriteria({p}, options);
  EXPECT_TRUE(c.unscored.empty());
  ASSERT_EQ(c.undecided.size(), 1u);
  EXPECT_NE(c.undecided[0].reason.find("point 7 (R_ftrunc 300, dt 0.1 dt_sharp): Err undecided "
                                       "by the reference"),
            std::string::npos)
      << c.undecided[0].reason;

  // A decided SRf below its threshold fails the point, whatever Err would be.
  p.scores.Set("srf", 0.5);
  EXPECT_FALSE(options.Undecided(p));
  EXPECT_EQ(OutcomeCategories()[OutcomeCategoryOf(p, options)].label, "fails thresholds");
  // A score the reference leaves undecided and no threshold judges decides nothing.
  p.scores.Set("srf", 0.95);
  p.scores.Set("err", 0.05);
  p.reference_undecided = {"pfr"};
  EXPECT_FALSE(options.Undecided(p));
  EXPECT_TRUE(options.Passes(p));
  // With a threshold on it, it does.
  CriteriaOptions with_pfr;
  with_pfr.thresholds["pfr"] = 0.8;
  EXPECT_TRUE(with_pfr.Undecided(p));
  EXPECT_FALSE(with_pfr.Passes(p));
}

}  // namespace
}  // namespace shockmap

// The advice keeps its promise: for every R_k the quick study stores and every geometric
// midpoint between two of them, the advised truncation and time step pass the study's own
// thresholds when the comparison is computed (docs/physics.md §4.3). Unit checks of the
// choice: the studied boundary at a studied R_k, the safer side between two, the envelope
// beyond the range, and the warnings.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "analysis/scored_points.h"
#include "compare/comparison.h"
#include "engine/study_run.h"
#include "specs/study_file.h"
#include "views/advice_summary.h"

namespace shockmap {
namespace {

class QuickStudyAdvice : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    db_ = (std::filesystem::temp_directory_path() /
           ("shockmap_advice_" + std::to_string(getpid()) + ".db"))
              .string();
    std::filesystem::remove(db_);
    StudyRunOptions options;
    options.database_path = db_;
    options.jobs = 2;
    options.progress = false;
    spec_ = LoadStudySpec(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/quick.json");
    RunStudy(StudyFile(spec_), options);
    points_ = LoadScoredPoints(db_, "quick", "explicit-modal");
    criteria_ = DeriveCriteria(points_, CriteriaOptions{});
  }
  static void TearDownTestSuite() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db_ + suffix);
  }

  // The comparison the advice describes, computed with the study's problem and scoring. Where
  // the study's reference does not converge at that R_k it cannot judge the advice: the
  // reference is computed again at three times its truncation (the numerical run unchanged).
  static ScoredPoint Compute(const Advice& a) {
    StudyPoint point;
    point.r_k = a.r_k;
    point.r_ftrunc = a.r_ftrunc;
    point.dt.rule = DtRule::kSharp;
    point.dt.factor = a.dt_ratio;
    point.window_s = spec_.scoring.window_s;
    StudySpec spec = spec_;
    ComparisonResult r = RunComparison(ProblemOf(spec, point), OptionsOf(spec, point));
    if (r.status == RunStatus::kReferenceUnconverged) {
      spec.scoring.reference.r_fref_min = 3 * spec.scoring.reference.RFref(a.r_k);
      r = RunComparison(ProblemOf(spec, point), OptionsOf(spec, point));
    }
    ScoredPoint p;
    p.r_k = a.r_k;
    p.r_ftrunc = a.r_ftrunc;
    p.status = r.status;
    p.scores = r.scores;
    return p;
  }

  static inline std::string db_;
  static inline StudySpec spec_;
  static inline std::vector<ScoredPoint> points_;
  static inline ValidityCriteria criteria_;
};

TEST_F(QuickStudyAdvice, PassesTheThresholdsAtEveryStudiedRkAndEveryMidpoint) {
  std::vector<double> asked;
  for (std::size_t i = 0; i < criteria_.boundary.size(); ++i) {
    asked.push_back(criteria_.boundary[i].r_k);
    if (i + 1 < criteria_.boundary.size()) {
      asked.push_back(std::sqrt(criteria_.boundary[i].r_k * criteria_.boundary[i + 1].r_k));
    }
  }
  ASSERT_EQ(asked.size(), 21u);  // 11 studied R_k and the 10 midpoints.
  const CriteriaOptions thresholds;
  for (double r_k : asked) {
    const Advice a = Advise(spec_.problem, spec_.scoring.window_s, criteria_, points_, r_k);
    const ScoredPoint computed = Compute(a);
    EXPECT_TRUE(thresholds.Passes(computed))
        << "R_k " << r_k << ": R_ftrunc " << a.r_ftrunc << ", dt/dt_sharp " << a.dt_ratio
        << " gives " << ToString(computed.status) << ", Err "
        << computed.scores["err"].value_or(NAN) << ", SRf " << computed.scores["srf"].value_or(NAN)
        << "\n"
        << AdviceSummary(a);
  }
}

TEST_F(QuickStudyAdvice, AtAStudiedRkIsItsBoundaryAndBetweenTwoTheSaferSide) {
  for (const RkBoundary& b : criteria_.boundary) {
    const Advice a = Advise(spec_.problem, spec_.scoring.window_s, criteria_, points_, b.r_k);
    EXPECT_DOUBLE_EQ(a.r_ftrunc, *b.r_ftrunc_min) << b.r_k;
    EXPECT_DOUBLE_EQ(a.dt_ratio, *b.dt_ratio_max) << b.r_k;
    // The only warning at a studied R_k names the points there whose verdict is undecided.
    const bool undecided = std::ranges::any_of(
        criteria_.undecided, [&b](const PointsSetAside& u) { return u.r_k == b.r_k; });
    EXPECT_EQ(a.warnings.size(), undecided ? 1u : 0u) << b.r_k;
    if (undecided) {
      EXPECT_NE(a.warnings[0].find("undecided"), std::string::npos) << a.warnings[0];
    }
  }
  // Below the knee R_k = 100 needs 21.5 where 31.6 needs 10: R_k = 90 takes 100's truncation
  // (the old advice, 10, gave Err 0.135) and the finer of the two steps, with a warning.
  const Advice a = Advise(spec_.problem, spec_.scoring.window_s, criteria_, points_, 90.0);
  const auto& below = criteria_.boundary[3];
  const auto& above = criteria_.boundary[4];
  ASSERT_NEAR(below.r_k, 31.6227766, 1e-6);
  ASSERT_DOUBLE_EQ(above.r_k, 100.0);
  EXPECT_DOUBLE_EQ(a.r_ftrunc, std::max(*below.r_ftrunc_min, *above.r_ftrunc_min));
  // 0.1 is the finest studied step: nothing finer to step down to.
  EXPECT_DOUBLE_EQ(a.dt_ratio, std::min(*below.dt_ratio_max, *above.dt_ratio_max));
  // Between two studied R_k the advice takes the studied step one finer than the smaller of
  // their largest passing ones. Between 3.16e4 and 1e5 those are both 0.5: at 3.16e4, R_ftrunc
  // 464 at 0.9 dt_sharp grows its energy 1.9-fold and scores Err 0.106 (docs/fidelity.md, "The
  // quick study under the new reference"); at 1e5, R_ftrunc 215 at 0.9 dt_sharp is undecided
  // (Err 0.027 to 0.100 over its perturbed runs, docs/fidelity.md, "Spreads stored with the
  // points"), so 0.9 passes nowhere there. The advice steps down to 0.1.
  const auto& lower = criteria_.boundary[9];
  const auto& upper = criteria_.boundary[10];
  ASSERT_NEAR(lower.r_k, 31622.7766, 1e-3);
  ASSERT_DOUBLE_EQ(upper.r_k, 1e5);
  EXPECT_DOUBLE_EQ(*lower.dt_ratio_max, 0.5);
  EXPECT_DOUBLE_EQ(*upper.dt_ratio_max, 0.5);
  ASSERT_TRUE(std::ranges::any_of(
      criteria_.undecided, [&upper](const PointsSetAside& u) { return u.r_k == upper.r_k; }));
  const Advice high = Advise(spec_.problem, spec_.scoring.window_s, criteria_, points_,
                             std::sqrt(lower.r_k * upper.r_k));
  EXPECT_NEAR(high.dt_ratio, 0.1, 1e-9);
  EXPECT_GT(a.r_ftrunc, 10.0);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(a.warnings[0].find("between sparse studied values"), std::string::npos);
  // The stored points on both sides of the advised truncation at both studied R_k.
  EXPECT_EQ(a.nearest.size(), 4u);
  const auto json = AdviceToJson(a);
  EXPECT_EQ(json["nearest"].size(), 4u);
  EXPECT_EQ(json["studied_r_k"].size(), 2u);
}

TEST_F(QuickStudyAdvice, OutsideTheStudiedRangeWarns) {
  const Advice beyond = Advise(spec_.problem, spec_.scoring.window_s, criteria_, points_, 1e7);
  // Beyond 1e5 the advice rests on 1e5, whose undecided points it names too.
  ASSERT_EQ(beyond.warnings.size(), 2u);
  EXPECT_NE(beyond.warnings[0].find("outside the studied range"), std::string::npos);
  EXPECT_NE(beyond.warnings[1].find("undecided, at R_k = 1e+05"), std::string::npos)
      << beyond.warnings[1];
  // Never less than the largest studied R_k needed.
  EXPECT_GE(beyond.r_ftrunc, *criteria_.boundary.back().r_ftrunc_min);
  const Advice below = Advise(spec_.problem, spec_.scoring.window_s, criteria_, points_, 0.1);
  ASSERT_EQ(below.warnings.size(), 1u);
  EXPECT_DOUBLE_EQ(below.r_ftrunc, *criteria_.boundary.front().r_ftrunc_min);
  // Where the criteria know least the time step is no larger than between the two studied R_k
  // at that edge, and one of quick's studied steps (0.1, 0.5, 0.9 dt_sharp) below the smaller
  // of the edge's two largest passing ones: below R_k = 1 both pass 0.9, so 0.5; above 1e5,
  // 3.16e4 and 1e5 pass 0.5, so 0.1. The advice was 0.9 beyond.
  const auto& all = criteria_.boundary;
  const std::pair<const Advice*, std::pair<std::size_t, std::size_t>> outside[] = {
      {&beyond, {all.size() - 2, all.size() - 1}}, {&below, {0, 1}}};
  for (const auto& [advice, edge] : outside) {
    const auto& [first, second] = edge;
    const Advice inside = Advise(spec_.problem, spec_.scoring.window_s, criteria_, points_,
                                 std::sqrt(all[first].r_k * all[second].r_k));
    EXPECT_LE(advice->dt_ratio, inside.dt_ratio) << advice->r_k;
    const double edge_max = std::min(*all[first].dt_ratio_max, *all[second].dt_ratio_max);
    const double one_step_below = edge_max > 0.9 - 1e-9 ? 0.5 : 0.1;
    ASSERT_GE(edge_max, 0.5 - 1e-9) << advice->r_k;
    EXPECT_NEAR(advice->dt_ratio, one_step_below, 1e-9) << advice->r_k;
    EXPECT_NE(advice->warnings[0].find("dt/dt_sharp is one studied step finer"), std::string::npos);
  }
}

}  // namespace
}  // namespace shockmap

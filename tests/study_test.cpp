// The study manager in-process: strict spec parsing, and a database that computes only what is
// missing and shares references.

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "db/canonical_points.h"
#include "db/read_only_query.h"
#include "db/sqlite_handle.h"
#include "engine/progress_reporter.h"
#include "engine/study_run.h"
#include "engine/task_queue.h"
#include "engine/worker_pool.h"
#include "specs/setting_change.h"
#include "tests/run_command.h"
#include "validation/psd.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

struct BadSpec {
  const char* name;
  const char* json;
  const char* path;  // The key path the message must name.
};

void PrintTo(const BadSpec& b, std::ostream* os) { *os << b.name; }

class StudySpecRejects : public ::testing::TestWithParam<BadSpec> {};

TEST_P(StudySpecRejects, NamingTheKeyPath) {
  const Json json = Json::parse(GetParam().json);
  try {
    ParseStudySpec(json, "bad.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad.json: "), std::string::npos) << message;
    EXPECT_NE(message.find(GetParam().path), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, StudySpecRejects,
    ::testing::Values(
        BadSpec{"MissingName", R"({"grids": [{"rk": 1, "rftrunc": 10}]})", "name"},
        BadSpec{"UnknownTopKey",
                R"({"name": "x", "grid": [], "grids": [{"rk": 1, "rftrunc": 10}]})", "grid"},
        BadSpec{"UnknownAxis", R"({"name": "x", "grids": [{"rk": 1, "rftrunc": 10, "rks": 2}]})",
                "grids[0].rks"},
        BadSpec{"WrongType", R"({"name": "x", "grids": [{"rk": "abc", "rftrunc": 10}]})",
                "grids[0].rk"},
        BadSpec{"EmptyAxis", R"({"name": "x", "grids": [{"rk": [], "rftrunc": 10}]})",
                "grids[0].rk"},
        BadSpec{"NegativeStiffness", R"({"name": "x", "grids": [{"rk": [1, -3], "rftrunc": 10}]})",
                "grids[0].rk"},
        BadSpec{"TruncationBelowOne", R"({"name": "x", "grids": [{"rk": 1, "rftrunc": 0.5}]})",
                "grids[0].rftrunc"},
        BadSpec{"LogspaceArity",
                R"({"name": "x", "grids": [{"rk": {"logspace": [0, 6]}, "rftrunc": 10}]})",
                "grids[0].rk.logspace"},
        BadSpec{"LogspaceCount",
                R"({"name": "x", "grids": [{"rk": {"logspace": [0, 6, 0]}, "rftrunc": 10}]})",
                "grids[0].rk.logspace[2]"},
        BadSpec{"UnknownRule",
                R"({"name": "x", "grids": [{"rk": 1, "rftrunc": 10, "dt": {"rule": "loose"}}]})",
                "grids[0].dt.rule"},
        BadSpec{"NegativeFactor",
                R"({"name": "x", "grids": [{"rk": 1, "rftrunc": 10, "dt": {"factor": -1}}]})",
                "grids[0].dt.factor"},
        BadSpec{"UnknownScheme",
                R"({"name": "x", "grids": [{"rk": 1, "rftrunc": 10, "scheme": "rk4"}]})",
                "grids[0].scheme"},
        BadSpec{"ZeroWindow",
                R"({"name": "x", "scoring": {"window_s": 0}, "grids": [{"rk": 1, "rftrunc": 10}]})",
                "scoring.window_s"},
        BadSpec{
            "WindowTwice",
            R"({"name": "x", "scoring": {"window_s": 0.03, "window_periods": 0.5}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "scoring.window_periods"},
        BadSpec{
            "WindowPeriodsBeyondTheLimit",
            R"({"name": "x", "scoring": {"window_periods": 5000}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "scoring.window_periods"},
        BadSpec{
            "UnknownPsdWindow",
            R"({"name": "x", "scoring": {"psd": {"window": "blackman"}}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "scoring.psd.window"},
        BadSpec{"FractionalElements",
                R"({"name": "x", "grids": [{"rk": 1, "rftrunc": 10, "n_elements": 2.5}]})",
                "grids[0].n_elements"},
        BadSpec{
            "HugeGrid",
            R"({"name": "x", "grids": [{"rk": {"logspace": [0, 6, 100000]}, "rftrunc": {"linspace": [1, 300, 100000]}}]})",
            "grids[0]"},
        BadSpec{"ListForListedPoint", R"({"name": "x", "points": [{"rk": [1, 2], "rftrunc": 10}]})",
                "points[0].rk"},
        BadSpec{
            "BadProblem",
            R"({"name": "x", "problem": {"gap_m": "wide"}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "problem.gap_m"},
        BadSpec{
            "UnknownSrfDefinition",
            R"({"name": "x", "scoring": {"shocks": {"srf_definition": "first"}}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "scoring.shocks.srf_definition"},
        BadSpec{
            "UnknownReferenceCheck",
            R"({"name": "x", "scoring": {"reference": {"check": "both"}}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "scoring.reference.check"},
        BadSpec{"ModesAxisReversed",
                R"({"name": "x", "grids": [{"rk": 1, "rftrunc": {"modes": [5, 2]}}]})",
                "grids[0].rftrunc.modes"},
        BadSpec{"ModesAxisZero",
                R"({"name": "x", "grids": [{"rk": 1, "rftrunc": {"modes": [0, 3]}}]})",
                "grids[0].rftrunc.modes"},
        BadSpec{
            "NegativeTimingBudget",
            R"({"name": "x", "scoring": {"timing": {"repeat_until_s": -1e-4}}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "scoring.timing.repeat_until_s"},
        BadSpec{
            "UnknownTimingKey",
            R"({"name": "x", "scoring": {"timing": {"repeats": 3}}, "grids": [{"rk": 1, "rftrunc": 10}]})",
            "scoring.timing.repeats"},
        BadSpec{"NoGridNoPoints", R"({"name": "x"})", "(top level)"}),
    [](const auto& info) { return std::string(info.param.name); });

// The window in first-mode periods: f1 = b1^2 sqrt(EI / (rho A L^4)) / (2 pi) of the problem's
// beam, so four times EI doubles f1 and halves the window in seconds.
TEST(StudySpec, WindowInFirstModePeriodsIsThatManyPeriodsOfTheProblemsBeam) {
  const auto spec = [](const std::string& beam, const std::string& window) {
    return ParseStudySpec(
        Json::parse(R"({"name": "x", "problem": {"beam": )" + beam + R"(}, "scoring": )" + window +
                    R"(, "grids": [{"rk": 1, "rftrunc": 10}]})"),
        "w.json");
  };
  const double b1 = 1.8751040687119611;
  const double paper_f1 = b1 * b1 * std::sqrt(1.5e5 / 127.0) / (2.0 * M_PI);
  const StudySpec paper = spec("{}", R"({"window_periods": 0.5})");
  EXPECT_NEAR(paper.scoring.window_s, 0.5 / paper_f1, 1e-15);
  EXPECT_NEAR(paper.points.front().window_s, 0.5 / paper_f1, 1e-15);
  EXPECT_NEAR(kFig4WindowS * paper_f1, 0.577, 5e-4);  // The paper's Fig. 4 window in periods.
  EXPECT_FALSE(WindowWarning(paper));

  const StudySpec stiff = spec(R"({"ei_n_m2": 6e5})", R"({"window_periods": 0.5})");
  EXPECT_NEAR(stiff.scoring.window_s, 0.25 / paper_f1, 1e-15);
  EXPECT_FALSE(WindowWarning(stiff));  // Given in periods: meant as such.

  // The same beam with the window in seconds: 0.03 s is 2 x 0.577 periods of it.
  const auto warning = WindowWarning(spec(R"({"ei_n_m2": 6e5})", R"({"window_s": 0.03})"));
  ASSERT_TRUE(warning);
  EXPECT_NE(warning->find("w.json: window_s: 0.03 s covers 1.15 first-mode periods"),
            std::string::npos)
      << *warning;
  EXPECT_NE(warning->find("window_periods"), std::string::npos) << *warning;
  // Within 1.5 times the paper's f1 the seconds keep their meaning closely enough.
  EXPECT_FALSE(WindowWarning(spec(R"({"ei_n_m2": 3e5})", R"({"window_s": 0.03})")));
}

TEST(StudySpec, ExpandsGridsAndPointsWithoutRepeats) {
  const StudySpec s = ParseStudySpec(Json::parse(R"({
    "name": "x",
    "grids": [{"rk": {"logspace": [0, 2, 3]}, "rftrunc": [10, 30], "dt": {"factor": [0.1, 0.2]}}],
    "points": [{"rk": 10, "rftrunc": 10, "dt": {"factor": 0.1}}, {"rk": 5, "rftrunc": 10}]
  })"),
                                     "x.json");
  // 3 x 2 x 2 from the grid; the first listed point repeats a grid point.
  EXPECT_EQ(s.points.size(), 13u);
  EXPECT_DOUBLE_EQ(s.points[0].r_k, 1.0);
  EXPECT_DOUBLE_EQ(s.points.back().r_k, 5.0);
}

TEST(StudySpec, ModesAxisPlacesOneTruncationJustAboveEachModeFrequency) {
  const StudySpec s = ParseStudySpec(
      Json::parse(R"({"name": "x", "grids": [{"rk": 1, "rftrunc": {"modes": [1, 4]}}]})"),
      "x.json");
  // f_n / f1 of the clamped-free beam: (b_n / b_1)^2 with b = 1.8751, 4.6941, 7.8548, 10.9955.
  const double expected[] = {1.0, 6.2669, 17.5475, 34.3861};
  ASSERT_EQ(s.points.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(s.points[i].r_ftrunc / (1.0 + kModeEntryMargin), expected[i], 1e-3 * expected[i]);
  }
}

TEST(StudySpec, ScoringSettingsEnterTheSettingsKeyByTheirValue) {
  auto spec = [](const std::string& shocks) {
    return ParseStudySpec(Json::parse(R"({"name": "x", "scoring": {"shocks": {)" + shocks +
                                      R"(}}, "grids": [{"rk": 1, "rftrunc": 10}]})"),
                          "x.json");
  };
  const StudySpec plain = spec("");
  const StudySpec shock = spec(R"("srf_definition": "first_shock")");
  const StudySpec contact = spec(R"("srf_definition": "first_contact")");
  const StudySpec window = spec(R"("srf_definition": "reference_window")");
  EXPECT_EQ(SettingsKey(plain), SettingsKey(shock));
  EXPECT_NE(SettingsKey(plain), SettingsKey(contact));
  EXPECT_NE(SettingsKey(contact), SettingsKey(window));
  EXPECT_EQ(OptionsOf(window, window.points[0]).srf_definition, SrfDefinition::kReferenceWindow);
  EXPECT_NE(SettingsKey(plain), SettingsKey(ParseStudySpec(Json::parse(R"({"name": "x",
                "scoring": {"psd": {"scaling": "two_sided"}}, "grids": [{"rk": 1, "rftrunc": 10}]})"),
                                                           "x.json")));
  EXPECT_EQ(SettingsKey(plain), SettingsKey(ParseStudySpec(Json::parse(R"({"name": "x",
                "scoring": {"psd": {"scaling": "one_sided"}}, "grids": [{"rk": 1, "rftrunc": 10}]})"),
                                                           "x.json")));
  // The reference does not depend on how SRf reads it.
  EXPECT_EQ(ReferenceKey(plain, plain.points[0]), ReferenceKey(window, window.points[0]));
}

// A study file's "scoring.psd" takes what the library's PsdOptions takes, at either end of
// each range: the one range of validation/psd.h.
TEST(StudySpec, PsdOptionsTakeTheLibrarysRangeAtBothEnds) {
  auto study_takes = [](const char* key, int value) {
    const Json json =
        Json::parse(R"({"name": "x", "scoring": {"psd": {")" + std::string(key) +
                    "\": " + std::to_string(value) + R"(}}, "grids": [{"rk": 1, "rftrunc": 10}]})");
    try {
      ParseStudySpec(json, "x.json");
      return true;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("scoring.psd.") + key), std::string::npos)
          << e.what();
      return false;
    }
  };
  for (const int n : {kMinPsdSamples - 1, kMinPsdSamples, kMaxPsdSamples, kMaxPsdSamples + 1}) {
    PsdOptions options;
    options.n_samples = n;
    EXPECT_EQ(study_takes("n_samples", n), options.IsValid(nullptr)) << n;
  }
  for (const int factor : {0, 1, kMaxZeroPaddingFactor, kMaxZeroPaddingFactor + 1}) {
    PsdOptions options;
    options.zero_padding_factor = factor;
    EXPECT_EQ(study_takes("zero_padding_factor", factor), options.IsValid(nullptr)) << factor;
  }
  EXPECT_FALSE(study_takes("n_samples", kMinPsdSamples - 1));
  EXPECT_TRUE(study_takes("n_samples", kMaxPsdSamples));
}

// The check enters a reference's key only when it is not the default, so that references
// stored before the setting keep their keys; a coarser-checked reference is never taken for a
// finer-checked one.
TEST(StudySpec, ACoarserCheckedReferenceHasItsOwnKey) {
  auto spec = [](const std::string& reference) {
    return ParseStudySpec(Json::parse(R"({"name": "x", "scoring": {"reference": {)" + reference +
                                      R"(}}, "grids": [{"rk": 1, "rftrunc": 10}]})"),
                          "x.json");
  };
  const StudySpec plain = spec("");
  const StudySpec finer = spec(R"("check": "finer")");
  const StudySpec coarser = spec(R"("check": "coarser")");
  EXPECT_EQ(ReferenceKey(plain, plain.points[0]), ReferenceKey(finer, finer.points[0]));
  EXPECT_EQ(ReferenceKey(plain, plain.points[0]).find("check"), std::string::npos);
  EXPECT_NE(ReferenceKey(plain, plain.points[0]), ReferenceKey(coarser, coarser.points[0]));
  EXPECT_EQ(OptionsOf(coarser, coarser.points[0]).reference.check, ReferenceCheck::kCoarser);
  EXPECT_EQ(OptionsOf(plain, plain.points[0]).reference.check, ReferenceCheck::kFiner);
}

// Each scoring and reference setting is lifelong and named by its key in the study file, with
// the stored and the given value; thresholds and grid axes are not.
TEST(StudySpec, AChangedLifelongSettingIsNamedByItsFileKey) {
  auto key = [](const std::string& scoring) {
    return Json::parse(
        SettingsKey(ParseStudySpec(Json::parse(R"({"name": "x", "scoring": {)" + scoring +
                                               R"(}, "grids": [{"rk": [1, 10], "rftrunc": 10}]})"),
                                   "x.json")));
  };
  const Json plain = key(R"("window_s": 0.03)");
  const std::pair<const char*, const char*> changes[] = {
      {R"("window_s": 0.05)", "scoring.window_s"},
      {R"("window_s": 0.03, "psd": {"n_samples": 2048})", "scoring.psd.n_samples"},
      {R"("window_s": 0.03, "psd": {"window": "rectangular"})", "scoring.psd.window"},
      {R"("window_s": 0.03, "psd": {"zero_padding_factor": 2})", "scoring.psd.zero_padding_factor"},
      {R"("window_s": 0.03, "shocks": {"rest_duration_t1": 1})", "scoring.shocks.rest_duration_t1"},
      {R"("window_s": 0.03, "reference": {"r_fref_min": 1000})", "scoring.reference.r_fref_min"},
      {R"("window_s": 0.03, "reference": {"tolerance": 0.05})", "scoring.reference.tolerance"},
      {R"("window_s": 0.03, "reference": {"check": "coarser"})", "scoring.reference.check"},
  };
  for (const auto& [scoring, setting] : changes) {
    const auto change = FirstChangedSetting(plain, key(scoring));
    ASSERT_TRUE(change.has_value()) << scoring;
    EXPECT_EQ(change->key, setting);
  }
  const auto window = FirstChangedSetting(plain, key(R"("window_s": 0.05)"));
  EXPECT_EQ(window->stored, "0.03");
  EXPECT_EQ(window->given, "0.05");
  EXPECT_FALSE(
      FirstChangedSetting(plain, key(R"("window_s": 0.03, "thresholds": {"err_max": 0.2})")));
  EXPECT_FALSE(
      FirstChangedSetting(plain, key(R"("window_s": 0.03, "timing": {"repeat_until_s": 0})")));
}

// A run shorter than the budget is timed again until two runs total it; 0 times it once.
TEST(StudySpec, TimingBudgetSetsHowShortRunsAreTimed) {
  auto timing = [](const std::string& scoring) {
    return ShortRunTiming(ParseStudySpec(Json::parse(R"({"name": "x", "scoring": {)" + scoring +
                                                     R"(}, "grids": [{"rk": 1, "rftrunc": 10}]})"),
                                         "x.json")
                              .scoring);
  };
  const auto by_default = timing("");
  ASSERT_TRUE(by_default.has_value());
  EXPECT_EQ(by_default->min_total_s, 5e-4);
  EXPECT_EQ(by_default->min_repeats, 2);
  EXPECT_EQ(by_default->max_repeats, 101);
  EXPECT_EQ(timing(R"("timing": {"repeat_until_s": 2e-3})")->min_total_s, 2e-3);
  EXPECT_FALSE(timing(R"("timing": {"repeat_until_s": 0})").has_value());
}

class StudyDatabaseRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("shockmap_study_test_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    options_.database_path = (dir_ / "study.db").string();
    options_.jobs = 2;
    options_.progress = false;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static StudySpec Spec(const std::string& name, const std::string& rftrunc) {
    return ParseStudySpec(Json::parse(R"({"name": ")" + name + R"(", "scoring": {"window_s": 0.03},
        "grids": [{"rk": [100, 3000], "rftrunc": )" +
                                      rftrunc + "}]}"),
                          name + ".json");
  }
  Table Rows() const {
    return RunReadOnlyQuery(options_.database_path,
                            "SELECT point_id, status, err, srf, steps, updated_utc FROM results "
                            "ORDER BY point_id");
  }

  std::filesystem::path dir_;
  StudyRunOptions options_;
};

TEST_F(StudyDatabaseRuns, SecondRunComputesNothing) {
  const StudyRunSummary first = RunStudy(Spec("s", "[10, 300]"), options_);
  EXPECT_EQ(first.points_computed, 4u);
  EXPECT_EQ(first.references_computed, 2);
  const Table before = Rows();
  const StudyRunSummary second = RunStudy(Spec("s", "[10, 300]"), options_);
  EXPECT_EQ(second.points_computed, 0u);
  EXPECT_EQ(second.references_computed, 0);
  EXPECT_EQ(Rows().rows, before.rows);
}

TEST_F(StudyDatabaseRuns, AddedAxisValueComputesOnlyTheNewPoints) {
  RunStudy(Spec("s", "[10, 300]"), options_);
  const Table before = Rows();
  const StudyRunSummary more = RunStudy(Spec("s", "[10, 100, 300]"), options_);
  EXPECT_EQ(more.points_in_study, 6u);
  EXPECT_EQ(more.points_computed, 2u);  // R_ftrunc = 100 at both R_k
  EXPECT_EQ(more.references_computed, 0);
  EXPECT_EQ(more.references_reused, 2);
  const Table after = Rows();
  ASSERT_EQ(after.rows.size(), 6u);
  for (const auto& row : before.rows) {
    EXPECT_NE(std::find(after.rows.begin(), after.rows.end(), row), after.rows.end());
  }
}

TEST_F(StudyDatabaseRuns, ReferencesAreSharedAcrossStudies) {
  RunStudy(Spec("a", "[10]"), options_);
  const StudyRunSummary b = RunStudy(Spec("b", "[300]"), options_);
  EXPECT_EQ(b.points_computed, 2u);
  EXPECT_EQ(b.references_computed, 0);
  EXPECT_EQ(b.references_reused, 2);
}

TEST_F(StudyDatabaseRuns, EveryScoreRecordsItsSrfDefinition) {
  RunStudy(Spec("shock", "[10]"), options_);
  RunStudy(ParseStudySpec(Json::parse(R"({"name": "contact", "scoring": {"window_s": 0.03,
               "shocks": {"srf_definition": "first_contact"}},
               "grids": [{"rk": [100, 3000], "rftrunc": [10]}]})"),
                          "contact.json"),
           options_);
  const Table rows = RunReadOnlyQuery(
      options_.database_path,
      "SELECT study, srf_definition, count(*) FROM results GROUP BY study ORDER BY study");
  ASSERT_EQ(rows.rows.size(), 2u);
  EXPECT_EQ(std::get<std::string>(rows.rows[0][1]), "first_contact");
  EXPECT_EQ(std::get<std::string>(rows.rows[1][1]), "first_shock");
  // At R_k = 3000, R_ftrunc = 10 the first contact's impulse is far from the first shock's
  // (0.62 against 0.84 on the Fig. 4 grid): the definition reaches the score.
  const Table srf =
      RunReadOnlyQuery(options_.database_path,
                       "SELECT srf FROM results WHERE r_k = 3000 AND r_ftrunc = 10 ORDER BY study");
  ASSERT_EQ(srf.rows.size(), 2u);
  EXPECT_GT(std::abs(std::get<double>(srf.rows[1][0]) - std::get<double>(srf.rows[0][0])), 0.1);
}

// Timing each run once changes the stored cost only: the scores and step counts of a study
// timed once equal those of the same points timed again, to the bit.
TEST_F(StudyDatabaseRuns, TimingEachRunOnceLeavesEveryScoreAsItWas) {
  RunStudy(Spec("repeated", "[10, 300]"), options_);
  RunStudy(ParseStudySpec(Json::parse(R"({"name": "once", "scoring": {"window_s": 0.03,
               "timing": {"repeat_until_s": 0}}, "grids": [{"rk": [100, 3000], "rftrunc": [10, 300]}]})"),
                          "once.json"),
           options_);
  const Table rows = RunReadOnlyQuery(
      options_.database_path,
      "SELECT a.err, b.err, a.srf, b.srf, a.steps, b.steps, b.cpu_s FROM results a "
      "JOIN results b USING (r_k, r_ftrunc) WHERE a.study = 'repeated' AND b.study = 'once'");
  ASSERT_EQ(rows.rows.size(), 4u);
  for (const auto& row : rows.rows) {
    EXPECT_EQ(row[0], row[1]);
    EXPECT_EQ(row[2], row[3]);
    EXPECT_EQ(row[4], row[5]);
    EXPECT_GT(std::get<double>(row[6]), 0.0);
  }
}

TEST_F(StudyDatabaseRuns, ChangedSettingsAreRefusedAndNothingIsWritten) {
  RunStudy(Spec("s", "[10]"), options_);
  const std::string bytes = testing::ReadBytes(options_.database_path);
  // The PSD settings change every stored Err; the window, an axis, would only add points.
  const StudySpec changed = ParseStudySpec(
      Json::parse(R"({"name": "s", "scoring": {"window_s": 0.03, "psd": {"n_samples": 2048}},
                      "grids": [{"rk": [100], "rftrunc": [10]}]})"),
      "s.json");
  EXPECT_THROW(RunStudy(changed, options_), InputError);
  EXPECT_TRUE(testing::ReadBytes(options_.database_path) == bytes);
}

// Every status is stored as its text and read back as the same status.
TEST_F(StudyDatabaseRuns, EveryStatusRoundTripsThroughTheDatabase) {
  StudyDatabase db(options_.database_path);
  std::vector<NewPoint> points;
  for (RunStatus status : kAllRunStatuses) points.push_back({ToString(status), "ref", {}});
  for (auto& p : points) p.parameters = CellsOf(PointParameters{}, kPointParameterColumns);
  const RegisteredRun registered = db.RegisterRun(
      {"statuses", "{}", kCanonicalPoints, points, Provenance{"v", "c", "b", "host", 1, 1}});
  const std::int64_t study = registered.study_id, run = registered.run_id;
  const auto pending = db.PointsToCompute(kCanonicalPoints, study, false);
  ASSERT_EQ(pending.size(), kAllRunStatuses.size());
  StorePointOutcomes(db, kCanonicalPoints, run, pending.size(), [&](Connection&, std::size_t i) {
    return PointStatus{pending[i].point_id, PointOrigin{"host", 0}, pending[i].point_key, ""};
  });
  const Table r = RunReadOnlyQuery(options_.database_path,
                                   "SELECT point_key, status FROM points ORDER BY point_id");
  ASSERT_EQ(r.rows.size(), kAllRunStatuses.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const auto read = RunStatusFromString(std::get<std::string>(r.rows[i][1]));
    ASSERT_TRUE(read.has_value()) << std::get<std::string>(r.rows[i][1]);
    EXPECT_EQ(*read, kAllRunStatuses[i]);
  }
}

// A group of finished points is one transaction: when writing one of them fails, none of the
// group is stored and the run counts none of them done; the next group stores as usual.
TEST_F(StudyDatabaseRuns, AGroupOfOutcomesIsStoredWhollyOrNotAtAll) {
  StudyDatabase db(options_.database_path);
  std::vector<NewPoint> points(4);
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = {"p" + std::to_string(i), "ref",
                 CellsOf(PointParameters{}, kPointParameterColumns)};
  }
  const RegisteredRun registered = db.RegisterRun(
      {"group", "{}", kCanonicalPoints, points, Provenance{"v", "c", "b", "host", 1, 1}});
  const std::int64_t study = registered.study_id, run = registered.run_id;
  const auto pending = db.PointsToCompute(kCanonicalPoints, study, false);
  ASSERT_EQ(pending.size(), 4u);
  auto store = [&](std::size_t first, std::size_t count, std::optional<std::size_t> failing) {
    StorePointOutcomes(db, kCanonicalPoints, run, count, [&](Connection&, std::size_t i) {
      if (failing == i) throw DbError("disk full");
      return PointStatus{pending[first + i].point_id, PointOrigin{"host", 0}, "ok", ""};
    });
  };
  EXPECT_THROW(store(0, 3, 2), DbError);
  auto stored = [&] {
    return RunReadOnlyQuery(options_.database_path,
                            "SELECT (SELECT count(*) FROM points WHERE status = 'ok'), "
                            "(SELECT points_done FROM runs WHERE run_id = " +
                                std::to_string(run) + ")")
        .rows.at(0);
  };
  EXPECT_EQ(std::get<std::int64_t>(stored()[0]), 0);
  EXPECT_EQ(std::get<std::int64_t>(stored()[1]), 0);
  store(0, 4, std::nullopt);
  EXPECT_EQ(std::get<std::int64_t>(stored()[0]), 4);
  EXPECT_EQ(std::get<std::int64_t>(stored()[1]), 4);
}

// A cached statement is prepared once and comes back reset, its bindings cleared, even when its
// previous use stopped before its last row.
TEST(Connection, ACachedStatementComesBackResetAndUnbound) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("shockmap_cached_" + std::to_string(getpid()) + ".db");
  std::filesystem::remove(path);
  {
    Connection c(path.string(), Connection::Mode::kReadWriteCreate);
    c.Execute("CREATE TABLE t(x); INSERT INTO t VALUES (1), (2)");
    Statement& first = c.Cached("SELECT x, ? FROM t ORDER BY x");
    first.Bind(1, std::int64_t{7});
    ASSERT_TRUE(first.Step());  // Left on its first row.
    Statement& again = c.Cached("SELECT x, ? FROM t ORDER BY x");
    EXPECT_EQ(&again, &first);
    ASSERT_TRUE(again.Step());
    EXPECT_EQ(again.GetInt(0), 1);  // From the first row again.
    EXPECT_TRUE(again.IsNull(1));   // The 7 is no longer bound.
  }
  std::filesystem::remove(path);
}

// A task starts only once the task it waits for has been consumed, and no sooner than needed:
// the tasks waiting for a fast task run while a slow one is still computing (no phase barrier).
TEST(RunOnWorkers, ATaskStartsOnceItsOwnPrerequisiteIsConsumed) {
  const std::size_t kNoWait = TaskQueue::kNoWait;
  // Task 0 is slow, task 1 fast; 2 and 3 wait for 1, 4 and 5 for 0.
  const std::vector<std::size_t> after = {kNoWait, kNoWait, 1, 1, 0, 0};
  std::array<std::atomic<bool>, 6> consumed{};
  std::array<std::atomic<bool>, 6> started_early{};
  std::vector<std::size_t> order;
  const std::size_t n = RunOnWorkers(
      after, 2,
      [&](std::size_t i) {
        if (after[i] != kNoWait && !consumed[after[i]]) started_early[i] = true;
        if (i == 0) std::this_thread::sleep_for(std::chrono::milliseconds(300));
        return i;
      },
      [&](std::size_t i) {
        order.push_back(i);
        consumed[i] = true;
      },
      [] { return false; });
  EXPECT_EQ(n, 6u);
  ASSERT_EQ(order.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_FALSE(started_early[i]) << "task " << i;
  auto position = [&](std::size_t i) { return std::ranges::find(order, i) - order.begin(); };
  EXPECT_LT(position(2), position(0));  // Waited for the fast task only.
  EXPECT_LT(position(3), position(0));
  EXPECT_GT(position(4), position(0));
  EXPECT_GT(position(5), position(0));
}

// A taker holding a result is given the tasks waiting for it first, while the tasks that wait
// for nothing keep their place at the front; every task is taken once, and none before it is
// ready.
TEST(TaskQueue, GivesATakerTheTasksWaitingForAResultItHolds) {
  const std::size_t kNoWait = TaskQueue::kNoWait;
  // Tasks 0 and 1 wait for nothing; 2 and 3 wait for 0, 4 and 5 for 1; 6 waits for nothing.
  TaskQueue queue({kNoWait, kNoWait, 0, 0, 1, 1, kNoWait});
  EXPECT_EQ(queue.Take(std::set<std::size_t>{1}), 0u);  // 1 is not consumed: in order.
  EXPECT_EQ(queue.Take(std::set<std::size_t>{}), 1u);
  queue.Consumed(0);
  queue.Consumed(1);
  EXPECT_EQ(queue.Take(std::set<std::size_t>{1}), 6u);  // Waits for nothing: keeps its place.
  EXPECT_EQ(queue.Take(std::set<std::size_t>{1}), 4u);  // Before 2 and 3, which wait for 0.
  EXPECT_EQ(queue.Take(std::set<std::size_t>{0, 1}), 2u);
  EXPECT_EQ(queue.Take(std::set<std::size_t>{1}), 5u);
  EXPECT_EQ(queue.Take(std::set<std::size_t>{1}), 3u);  // Nothing of 1 left: the front.
  EXPECT_FALSE(queue.HasReady());
  EXPECT_TRUE(queue.IsWaitedFor(0));
  EXPECT_FALSE(queue.IsWaitedFor(2));
}

// Tasks that wait for nothing may still need what a taker holds (a reference read from the
// database, sent along with the first task that needs it): a taker is given those of its groups
// first, the others in order.
TEST(TaskQueue, GivesATakerTheReadyTasksOfTheGroupsItHolds) {
  const std::size_t kNoWait = TaskQueue::kNoWait;
  TaskQueue queue({kNoWait, kNoWait, kNoWait, kNoWait}, {10, 11, 10, 11});
  EXPECT_EQ(queue.Take(std::set<std::size_t>{11}), 1u);
  EXPECT_EQ(queue.Take(std::set<std::size_t>{}), 0u);
  EXPECT_EQ(queue.Take(std::set<std::size_t>{10}), 2u);
  EXPECT_EQ(queue.Take(std::set<std::size_t>{10}), 3u);  // None of group 10 left: in order.
  EXPECT_FALSE(queue.HasReady());
}

// A taker holding no ready group takes up one that no taker holds, in the order the groups
// became ready, rather than the front task of a group another taker holds.
TEST(TaskQueue, GivesATakerHoldingNoneAGroupNobodyHolds) {
  const std::size_t kNoWait = TaskQueue::kNoWait;
  TaskQueue queue({kNoWait, kNoWait, kNoWait, kNoWait, kNoWait}, {10, 10, 11, 11, 12});
  EXPECT_EQ(queue.Take({}, {}), 0u);
  EXPECT_EQ(queue.Take({}, {10}), 2u);  // Not 1: group 10 is held elsewhere.
  EXPECT_EQ(queue.Take({}, {10, 11}), 4u);
  EXPECT_EQ(queue.Take({10}, {10, 11, 12}), 1u);
  EXPECT_EQ(queue.Take({12}, {10, 11, 12}), 3u);  // Every group held, none of 12 left: in order.
  EXPECT_FALSE(queue.HasReady());
}

// Off a terminal a phase prints plain lines: none before 5 s, and its last line always, with
// done / total, the rate, the time it took and the phase's own counts.
TEST(ProgressReporter, PrintsAPlainFinalLineOffATerminal) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  ProgressReporter progress("references", "done", 3, out, true);
  progress.Update(1, "unconverged 0");
  progress.Finish(3, "unconverged 1, failed 0");
  std::rewind(out);
  char line[512] = {};
  ASSERT_NE(std::fgets(line, sizeof line, out), nullptr);
  const std::string text = line;
  EXPECT_EQ(text.rfind("progress: references 3/3 done, ", 0), 0u) << text;
  EXPECT_NE(text.find("/s, took 0 s, unconverged 1, failed 0\n"), std::string::npos) << text;
  EXPECT_EQ(std::fgets(line, sizeof line, out), nullptr) << "one line only: " << line;
  std::fclose(out);
  EXPECT_EQ(FormatDuration(59.4), "59 s");
  EXPECT_EQ(FormatDuration(200), "3 min 20 s");
  EXPECT_EQ(FormatDuration(3900), "1 h 05 min");
}

// Every line printed to `out`.
std::vector<std::string> LinesOf(std::FILE* out) {
  std::rewind(out);
  std::vector<std::string> lines;
  char line[512] = {};
  while (std::fgets(line, sizeof line, out) != nullptr) lines.emplace_back(line);
  return lines;
}

// No ETA before one can be estimated: the wait for the first item done is no rate (a first
// point done after 0.2 s of references would otherwise foretell total / done times 0.2 s), nor
// is a phase held while it waits on another; the rate counts from the start of the estimate.
// A listener makes the reporter print every 0.1 s off a terminal too.
TEST(ProgressReporter, SaysEstimatingUntilARateCanBeMeasured) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  ProgressReporter progress("points", "done", 1000, out, true, [](auto, auto, auto) {});
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  progress.Update(1);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  progress.Update(101);
  ASSERT_EQ(LinesOf(out).size(), 2u);
  EXPECT_NE(LinesOf(out)[0].find("progress: points 1/1000 done, "), std::string::npos);
  EXPECT_NE(LinesOf(out)[0].find(", ETA estimating"), std::string::npos) << LinesOf(out)[0];
  // 100 points in at least 1.1 s since the first: 899 more in at least 9.9 s.
  const std::string second = LinesOf(out)[1];
  const auto eta = second.find(", ETA ");
  ASSERT_NE(eta, std::string::npos) << second;
  EXPECT_GE(std::atoi(second.c_str() + eta + 6), 9) << second;
  std::fclose(out);

  std::FILE* held = std::tmpfile();
  ASSERT_NE(held, nullptr);
  ProgressReporter waiting("points", "done", 1000, held, true, [](auto, auto, auto) {});
  waiting.HoldEstimate();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  waiting.Update(5);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  waiting.Update(10);
  waiting.StartEstimate(10);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  waiting.Update(20);
  const auto lines = LinesOf(held);
  ASSERT_EQ(lines.size(), 3u);
  for (const std::string& line : lines) {
    EXPECT_NE(line.find("ETA estimating"), std::string::npos) << line;
  }
  std::fclose(held);
}

// The CLI reports both phases of a study (stderr is a pipe here: plain lines), and a rerun
// with nothing to do says so instead of printing zero outcomes.
TEST(StudyRunCli, ReportsEveryPhaseAndARerunThatFindsEveryPointStored) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("shockmap_progress_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string spec = (dir / "s.json").string();
  {
    std::ofstream(spec) << R"({"name": "s", "scoring": {"window_s": 0.03},
        "grids": [{"rk": [100, 3000], "rftrunc": [10, 300]}]})";
  }
  const std::string run = "study run " + spec + " --db " + (dir / "s.db").string();
  const auto first = testing::RunShockmap(run + " --jobs 1");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("progress: references 2/2 done"), std::string::npos) << first.output;
  EXPECT_NE(first.output.find("unconverged 0, failed 0"), std::string::npos) << first.output;
  EXPECT_NE(first.output.find("progress: points 4/4 done"), std::string::npos) << first.output;
  EXPECT_NE(first.output.find("4 points in the study, 4 computed now (1 job"), std::string::npos)
      << first.output;
  const auto again = testing::RunShockmap(run + " --jobs 1");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("all 4 points already stored"), std::string::npos) << again.output;
  EXPECT_EQ(again.output.find("progress:"), std::string::npos) << again.output;
  EXPECT_EQ(again.output.find("ok 0"), std::string::npos) << again.output;
  std::filesystem::remove_all(dir);
}

// `simulate` reports the simulated time of its transient loop; the summary counts in words.
TEST(SimulateCli, ReportsSimulatedTimeAndCountsInTheSingular) {
  const auto run = testing::RunShockmap("simulate " + std::string(SHOCKMAP_SOURCE_DIR) +
                                        "/scenes/cantilever_spring.json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("progress: simulate cantilever_spring 0.06/0.06 s simulated"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("1 beam, 1 zone, 10 modal coordinates (10 modes per plane,"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("1 distinct modal basis"), std::string::npos) << run.output;
  const auto quiet = testing::RunShockmap("simulate --quiet " + std::string(SHOCKMAP_SOURCE_DIR) +
                                          "/scenes/cantilever_spring.json");
  EXPECT_EQ(quiet.output.find("progress:"), std::string::npos) << quiet.output;
}

}  // namespace
}  // namespace shockmap

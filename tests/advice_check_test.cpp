// Advice checked on an ensemble (docs/ensembles.md, "Advice checked on the bundle"): the
// ladder stops where the statistics stop moving, each rung sets every beam's truncation with a
// mesh that resolves it, listed settings and scene_set are read and refused as files are, and
// a deliberately bad advice is reported as failing.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "core/cantilever_impact.h"
#include "core/input_error.h"
#include "formats/criteria_json.h"
#include "formats/scene_file.h"
#include "specs/advice_check_study.h"
#include "specs/ensemble_study_spec.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"
#include "validation/scene_advice.h"
#include "views/advice_check_text.h"

namespace shockmap {
namespace {

using nlohmann::json;
using testing::RunShockmap;
using testing::WriteText;

// n members of the exponential law of unit mean at their plotting positions, times `scale`:
// their P95 is close to scale ln 20, the law's.
ZoneSizing ExponentialZone(int n, double scale) {
  std::vector<double> forces;
  for (int i = 0; i < n; ++i) forces.push_back(-scale * std::log(1.0 - (i + 0.5) / n));
  return SizeZone(forces, SizingOptions{});
}

// A ladder whose rung k is off the limit by 2 x 10^-k: 200 % and 20 % lie beyond the P95's
// 95 % interval of 2000 members (about -6 % to +7 %), 2 % and less within it. The ladder stops
// at the first rung within: its interval holds the limit, the rung before's does not.
TEST(AdviceLadder, ConvergesWhereTheStatisticsStopMoving) {
  std::vector<ZoneSizing> rungs;
  for (int k = 0; k < 5; ++k)
    rungs.push_back(ExponentialZone(2000, 1.0 + 2.0 * std::pow(10.0, -k)));
  const LadderConvergence c = ConvergedRung(rungs, 0.0);
  ASSERT_FALSE(c.undecided);
  ASSERT_TRUE(c.rung.has_value());
  EXPECT_EQ(*c.rung, 2);
  const double limit = std::log(20.0);
  EXPECT_LE(rungs[2].sizing.lower, limit);
  EXPECT_GE(rungs[2].sizing.upper, limit);
  EXPECT_GT(rungs[1].sizing.lower, limit);
  // Cut before the statistics stop moving, the ladder has not converged.
  EXPECT_FALSE(ConvergedRung({rungs[0], rungs[1]}, 0.0).rung.has_value());
  // A tolerance as wide as the last move lets the ladder stop one rung earlier.
  EXPECT_EQ(ConvergedRung(rungs, 0.2).rung, 1);
  // Twenty members cannot bound a P95 from above: undecided, never converged.
  const LadderConvergence few =
      ConvergedRung({ExponentialZone(20, 1.0), ExponentialZone(20, 1.0)}, 0.05);
  EXPECT_TRUE(few.undecided);
  EXPECT_FALSE(few.rung.has_value());
}

// Where the advised rung is the converged one, the verdict says so and names the family a third
// of the advice is not enough for; where a coarser rung converged, it says how much cheaper.
TEST(AdviceLadder, TheVerdictSaysWhetherTheAdviceIsTheConvergedSetting) {
  AdviceCheck check;
  check.factors = {1.0 / 3.0, 1.0, 3.0};
  check.cpu_s_per_member = {0.1, 0.4, 2.0};
  const auto family = [](ZoneFamily f, double off_at_third) {
    FamilyLadder ladder{"new", f, "zone", {}, {}};
    for (double off : {off_at_third, 0.0, 0.0})
      ladder.rungs.push_back(ExponentialZone(2000, 1.0 + off));
    ladder.convergence = ConvergedRung(ladder.rungs, 0.05);
    return ladder;
  };
  check.families = {family(ZoneFamily::kPinPinWire, 0.0), family(ZoneFamily::kDuctPad, 1.0)};
  check.converged = 1;
  const std::string at_advice = AdviceVerdict(check, 0.95);
  EXPECT_NE(at_advice.find("Advice held at 2 of 2"), std::string::npos) << at_advice;
  EXPECT_NE(at_advice.find("it is the converged setting"), std::string::npos) << at_advice;
  EXPECT_NE(at_advice.find("x 1/3 of it is not enough for the duct pad."), std::string::npos)
      << at_advice;
  // The table shows every rung's quantile with its interval, so that the converged rung is on
  // the page beside the advised one, each named in its column's header.
  const Table table = AdviceCheckTable(check);
  ASSERT_EQ(table.columns.size(), 9u);
  EXPECT_EQ(table.columns[3], "x 1/3 (N)");
  EXPECT_EQ(table.columns[4], "x 1, advised, converged (N)");
  EXPECT_EQ(table.columns[5], "x 3 (N)");
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const QuantileInterval& q = check.families[i].rungs[k].sizing;
      EXPECT_EQ(std::get<std::string>(table.rows[i][3 + k]),
                fmt::format("{:.4g} [{:.4g}, {:.4g}]", q.estimate, q.lower, q.upper));
    }
  }
  check.families = {family(ZoneFamily::kPinPinWire, 0.0), family(ZoneFamily::kDuctPad, 0.0)};
  check.converged = 0;
  const std::string below = AdviceVerdict(check, 0.95);
  EXPECT_NE(below.find("x 1/3 of the advised truncations"), std::string::npos) << below;
  EXPECT_NE(below.find("costs 0.1 s, 4 times less"), std::string::npos) << below;
}

json ReadJson(const std::string& path) { return json::parse(std::ifstream(path)); }

const std::string kRowScene = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json";

SceneAdvice RowAdvice() {
  CriteriaTolerances tolerances;
  const std::string criteria =
      std::string(SHOCKMAP_SOURCE_DIR) + "/studies/baselines/paper_fig4.json";
  return AdviseScene(LoadScene(kRowScene),
                     CriteriaFromJson(ReadJson(criteria), criteria, &tolerances));
}

// The shipped scene criteria (docs/physics.md §5.1) size on the peak force: their boundary
// grows as R_k^(2/3), the contact frequency of a spring on a beam, not as the paper's sqrt(R_k);
// they give the row's pins at least the truncation from which the wires' P95 stopped moving
// under the Err and SRf criteria's advice (9 x 1254, docs/ensembles.md), and the duct more than
// the third of the Err and SRf advice at which its pad had not settled.
TEST(AdviceLadder, TheSceneCriteriaGiveTheWiresWhatTheirStatisticsNeeded) {
  CriteriaTolerances tolerances;
  const std::string file =
      std::string(SHOCKMAP_SOURCE_DIR) + "/studies/baselines/modes_fig4_peak_force.json";
  const ValidityCriteria criteria = CriteriaFromJson(ReadJson(file), file, &tolerances);
  ASSERT_TRUE(criteria.fit.has_value());
  EXPECT_LT(criteria.fit->p_low, 2.0 / 3.0);
  EXPECT_GT(criteria.fit->p_high, 2.0 / 3.0);
  EXPECT_GT(criteria.fit->p_low, 0.5);
  const SceneAdvice advice = AdviseScene(LoadScene(kRowScene), criteria);
  const SceneAdvice err_srf = RowAdvice();
  ASSERT_EQ(advice.beams.size(), err_srf.beams.size());
  for (std::size_t b = 0; b < advice.beams.size(); ++b) {
    const bool pin = advice.beams[b].name != "wrapper";
    EXPECT_GE(advice.beams[b].r_ftrunc, (pin ? 9.0 : 1.0 / 3.0) * err_srf.beams[b].r_ftrunc)
        << advice.beams[b].name;
  }
}

// A rung scales every beam's advised truncation; the bundle's pins share the largest of theirs,
// each with a mesh at least the scene's and DefaultElementCount's; dt at the advised ratio.
TEST(AdviceLadder, ARungScalesEveryBeamsTruncationWithAMeshThatResolvesIt) {
  const json scene_json = ReadJson(kRowScene);
  const Scene scene = LoadScene(kRowScene);
  const SceneAdvice advice = RowAdvice();
  double pins = 0.0, wrapper = 0.0;
  for (const BeamAdvice& b : advice.beams) {
    (b.name == "wrapper" ? wrapper : pins) =
        std::max(b.name == "wrapper" ? wrapper : pins, b.r_ftrunc);
  }
  for (double factor : LadderFactors(5)) {
    const json s = RungSetting(scene_json, scene, advice, factor);
    EXPECT_NEAR(s.at("bundle.pin.r_ftrunc").get<double>(), factor * pins, 1e-3) << factor;
    EXPECT_NEAR(s.at("bundle.wrapper.r_ftrunc").get<double>(), factor * wrapper, 1e-3) << factor;
    EXPECT_EQ(s.at("bundle.pin.elements").get<int>(),
              std::max(55, DefaultElementCount(s.at("bundle.pin.r_ftrunc").get<double>())));
    EXPECT_EQ(s.at("solver.dt.factor").get<double>(), advice.dt_ratio);
    EXPECT_EQ(s.size(), 5u);
  }
  EXPECT_EQ(LadderFactors(5), (std::vector<double>{1.0 / 3.0, 1.0, 3.0, 9.0, 27.0}));
  EXPECT_TRUE(RungFits(advice, 27.0));
  EXPECT_FALSE(RungFits(advice, 1e5 / pins * 1.01));
  EXPECT_THROW(RungSetting(scene_json, scene, advice, 1e5 / pins * 1.01), InputError);
  // A time step in seconds is no ratio of the sharp bound to set.
  json seconds = scene_json;
  seconds["solver"]["dt"] = {{"seconds", 1e-6}};
  EXPECT_THROW(RungSetting(seconds, ParseScene(seconds, kRowScene), advice, 1.0), InputError);
}

class AdviceCheckCli : public testing::TempDirTest {
 protected:
  // The shipped row ensemble, one clearance state, over `window_s`.
  json RowEnsemble(int members, double window_s) {
    json s = ReadJson(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/bundle_row_ensemble.json");
    s["scene"] = kRowScene;
    s["name"] = "row";
    s["members"] = members;
    s["window_s"] = window_s;
    s["clearance_states"] = json::array({s["clearance_states"][1]});
    return s;
  }
  std::string Write(const json& j, const std::string& name) {
    WriteText(Path(name), j.dump());
    return Path(name);
  }
};

// The ladder's study reads its listed settings in order, the keys the scene left at their
// default written by scene_set; bad lists and scene_set paths are refused naming the key.
TEST_F(AdviceCheckCli, ListedSettingsAndSceneSetAreReadAndRefusedAsFilesAre) {
  const json ensemble = RowEnsemble(3, 0.02);
  const json scene_json = ReadJson(kRowScene);
  const std::vector<double> factors = LadderFactors(4);
  const json study = AdviceCheckStudy(ensemble, Path("row.json"), scene_json, LoadScene(kRowScene),
                                      RowAdvice(), {factors, 1, 0.95, 0.05}, 7, 0.015);
  const EnsembleStudySpec spec = ParseEnsembleStudySpec(study, Path("study.json"));
  EXPECT_EQ(spec.window_s, 0.015);
  ASSERT_EQ(spec.settings.size(), factors.size());
  for (std::size_t k = 0; k < factors.size(); ++k)
    EXPECT_EQ(spec.settings[k], study["settings"][k]);
  EXPECT_EQ(spec.refined, 3);
  EXPECT_EQ(spec.members, 7);
  EXPECT_EQ(spec.name, "row_advice_check");
  const auto refused = [&](json bad, const std::string& words) {
    bad["name"] = "bad";
    try {
      ParseEnsembleStudySpec(bad, Path("bad.json"));
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  json twice = study;
  twice["settings"].push_back(twice["settings"][0]);
  refused(twice, "settings[4]: {");
  json other_paths = study;
  other_paths["settings"][1].erase("solver.dt.factor");
  refused(other_paths, "settings[1]: sets other paths than settings[0]");
  json no_parent = study;
  no_parent["scene_set"]["bundle.spacer.r_ftrunc"] = 10;
  refused(no_parent, "scene_set.bundle.spacer.r_ftrunc: the scene has no object to hold it");
  json unset = study;
  unset.erase("scene_set");
  refused(unset, "the scene has no number at \"bundle.pin.r_ftrunc\"");
  json ladder = study;
  ladder["advice_check"]["factors"].erase(0);
  refused(ladder, "advice_check.factors: expected a list of 4 numbers, one per setting");
  ladder = study;
  ladder["advice_check"]["factors"][2] = 0.5;
  refused(ladder, "advice_check.factors: 0.5 is not a positive number above the one before");
}

// Criteria whose truncations are a tenth of the Err and SRf ones (the pins at ~125 f1, the duct
// at ~22): the check finds the advised median off the finest rung's beyond their intervals (the
// duct pad by about half) and says the advice failed. The median, which 30 members bound, keeps
// the test short; the ladder stops at 9 times the advice.
TEST_F(AdviceCheckCli, ADeliberatelyBadAdviceIsReportedAsFailing) {
  json criteria = ReadJson(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/baselines/paper_fig4.json");
  for (const char* c : {"c", "c_envelope"})
    criteria["fit"][c] = criteria["fit"][c].get<double>() / 10;
  for (json& row : criteria["boundary"]) {
    if (row.contains("r_ftrunc_min") && row["r_ftrunc_min"].is_number())
      row["r_ftrunc_min"] = row["r_ftrunc_min"].get<double>() / 10;
  }
  const std::string file = Write(RowEnsemble(30, 0.05), "row.json");
  const auto out =
      RunShockmap("check-advice " + file + " --criteria " + Write(criteria, "tenth.json") +
                  " --db " + Path("c.db") + " --jobs 2 --quiet --quantile 0.5 --max-rungs 4");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_TRUE(
      std::regex_search(out.output, std::regex("It failed (already )?at mid_life duct pad")))
      << out.output;
  EXPECT_EQ(out.output.find("Advice held at 3 of 3"), std::string::npos) << out.output;
  // The study's report opens with the same verdict.
  const auto report =
      RunShockmap("report row_advice_check --db " + Path("c.db") + " --out " + Path("report"));
  ASSERT_EQ(report.exit_code, 0) << report.output;
  std::ifstream page(Path("report/index.html"));
  const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_LT(html.find("id=\"advice-check-table\""), html.find("id=\"sizing-hottest-table\""));
  EXPECT_TRUE(std::regex_search(html, std::regex("It failed (already )?at mid_life duct pad")));
}

// --states checks the states named only; a name the study lacks is refused before anything runs.
TEST_F(AdviceCheckCli, StatesAreChosenByNameAndAnUnknownOneIsRefused) {
  json row = RowEnsemble(3, 0.005);
  row["clearance_states"] =
      ReadJson(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/bundle_row_ensemble.json")
          .at("clearance_states");
  const std::string file = Write(row, "row.json");
  const auto unknown =
      RunShockmap("check-advice " + file + " --states mid_life,eol --db " + Path("c.db"));
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("--states: \"eol\" is not a clearance state of " + file +
                                " (it has: new, mid_life, end_of_life)"),
            std::string::npos)
      << unknown.output;
  EXPECT_FALSE(std::filesystem::exists(Path("c.db")));
  const auto one = RunShockmap("check-advice " + file + " --states new --db " + Path("c.db") +
                               " --jobs 2 --quiet --quantile 0.5 --max-rungs 3");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_NE(one.output.find("9 members in the ladder"), std::string::npos) << one.output;
  EXPECT_NE(one.output.find("\nnew "), std::string::npos) << one.output;
  EXPECT_EQ(one.output.find("mid_life"), std::string::npos) << one.output;
}

TEST_F(AdviceCheckCli, AStudyOfAnotherKindIsRefusedWithExitCode2) {
  const auto out = RunShockmap("check-advice " + std::string(SHOCKMAP_SOURCE_DIR) +
                               "/studies/quick.json --db " + Path("c.db"));
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("check-advice needs an ensemble study"), std::string::npos)
      << out.output;
  EXPECT_FALSE(std::filesystem::exists(Path("c.db")));
}

}  // namespace
}  // namespace shockmap

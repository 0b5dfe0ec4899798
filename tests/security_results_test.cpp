// Results that used to be silently wrong, and checks that disagreed between commands: small
// or edited ensembles, settings matched by their text, picture files shared by two states,
// parameters a study overrides, windows inside one step, unchecked criteria and gap laws, and
// flags refused by one command and taken by another. Each either works as documented or is
// refused with exit code 2 and a message naming the file, key or flag, leaving no file behind.

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "db/sqlite_handle.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::Outcome;
using testing::RunShockmap;
using testing::WriteText;

// The planar bundle over 0.01 s (a few milliseconds per member), two clearance states, two
// settings of the truncation.
json SmallEnsemble(int members) {
  return {{"kind", "scene_ensemble"},
          {"name", "small"},
          {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json"},
          {"members", members},
          {"seed", 11},
          {"window_s", 0.01},
          {"clearance_states",
           {{{"name", "new"}, {"pin_gap_m", {{"mean", 5e-5}, {"std", 5e-6}}}},
            {{"name", "worn"}, {"pin_gap_m", {{"mean", 1e-5}, {"std", 5e-6}}}}}},
          {"settings", {{"solver.r_ftrunc", {30, 100}}}},
          {"refined", {{"solver.r_ftrunc", 100.0}}}};
}

class SecurityResults : public testing::TempDirTest {
 protected:
  std::string Write(const json& spec, const std::string& name = "study.json") {
    const std::string file = Path(name);
    WriteText(file, spec.dump(2));
    return file;
  }
  Outcome RunStudy(const json& spec, const std::string& db = "e.db") {
    return RunShockmap("study run " + Write(spec) + " --db " + Path(db) + " --jobs 2 --quiet");
  }
  // A refusal: exit code 2, every expected word in the message, no database created.
  void ExpectRefused(const json& spec, const std::vector<std::string>& words) {
    const Outcome o = RunStudy(spec, "refused.db");
    EXPECT_EQ(o.exit_code, 2) << o.output;
    for (const std::string& w : words) EXPECT_NE(o.output.find(w), std::string::npos) << o.output;
    EXPECT_FALSE(fs::exists(Path("refused.db")));
  }
};

bool Has(const Outcome& o, const std::string& text) {
  return o.output.find(text) != std::string::npos;
}

// Fewer than 10 members per state still give every table and picture.
TEST_F(SecurityResults, SmallEnsembleWritesItsPicturesAndReport) {
  ASSERT_EQ(RunStudy(SmallEnsemble(3)).exit_code, 0);
  const Outcome sizing = RunShockmap("sizing --db " + Path("e.db") + " --out " + Path("sizing"));
  ASSERT_EQ(sizing.exit_code, 0) << sizing.output;
  // Per state the maps; per state and zone family (the hottest wire, pad and pin-wrapper
  // contact, never the pad alone) the convergence and the histogram; per family the states and
  // the settings.
  std::vector<std::string> pictures = {"map_new.png", "map_worn.png"};
  for (const std::string family : {"pin-pin_wire", "duct_pad", "pin-wrapper"}) {
    for (const std::string state : {"new", "worn"}) {
      pictures.push_back("convergence_" + state + "_" + family + ".png");
      pictures.push_back("histogram_" + state + "_" + family + ".png");
    }
    pictures.push_back("states_" + family + ".png");
    pictures.push_back("settings_" + family + ".png");
  }
  for (const std::string& picture : pictures) {
    EXPECT_GT(fs::file_size(Path("sizing/" + picture)), 1000u) << picture;
  }
  const Outcome report = RunShockmap("report --db " + Path("e.db") + " --out " + Path("report"));
  ASSERT_EQ(report.exit_code, 0) << report.output;
  EXPECT_TRUE(fs::exists(Path("report/index.html")));
  EXPECT_TRUE(fs::exists(Path("report/sizing/convergence_new_pin-pin_wire.png")));
}

// Class 8: "refined": 100.0 names the setting 100 (as the study file accepted it).
TEST_F(SecurityResults, RefinedSettingIsMatchedByValue) {
  ASSERT_EQ(RunStudy(SmallEnsemble(3)).exit_code, 0);
  const Outcome o = RunShockmap("sizing --db " + Path("e.db") + " --out " + Path("sizing"));
  ASSERT_EQ(o.exit_code, 0) << o.output;
  // The refined setting's rows, the setting named by its value, say so in their "agrees"
  // column.
  EXPECT_TRUE(std::regex_search(o.output, std::regex("solver\\.r_ftrunc = 100 [^\n]* refined *\n")))
      << o.output;
  EXPECT_TRUE(Has(o, "solver.r_ftrunc = 30 against the refined setting")) << o.output;
  EXPECT_FALSE(Has(o, "solver.r_ftrunc = 100 against the refined setting")) << o.output;
  EXPECT_FALSE(Has(o, "{\"solver")) << o.output;
  EXPECT_GT(fs::file_size(Path("sizing/settings_duct_pad.png")), 1000u);
}

// Two states whose names give the same picture files are refused, naming both.
TEST_F(SecurityResults, StateNamesSharingPictureFilesAreRefused) {
  for (const char* second : {"a_b", "A B"}) {
    json spec = SmallEnsemble(3);
    spec["clearance_states"][0]["name"] = "a b";
    spec["clearance_states"][1]["name"] = second;
    ExpectRefused(spec, {"clearance_states[1]", "name", std::string("\"") + second + "\"",
                         "\"a b\"", "same picture files"});
  }
}

// The window and the outputs are the study's own; varying them is refused.
TEST_F(SecurityResults, WindowAndOutputsCannotBeVaried) {
  json settings = SmallEnsemble(3);
  settings["settings"] = {{"solver.end_time_s", {0.01, 0.02}}};
  settings["refined"] = {{"solver.end_time_s", 0.02}};
  ExpectRefused(settings, {"settings.solver.end_time_s", "window_s", "override"});
  json draws = SmallEnsemble(3);
  draws["draws"] = {{"outputs.record_stride", {{"uniform", {{"min", 1}, {"max", 20}}}}}};
  ExpectRefused(draws, {"draws.outputs.record_stride", "records", "override"});
  const json sweep = {
      {"kind", "scene_sweep"},
      {"name", "sweep"},
      {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json"},
      {"sweep", {{"solver.end_time_s", {0.01, 0.02}}}},
      {"reference", {{"solver.r_ftrunc", 1000}}},
      {"scoring",
       {{"displacement", "duct_top"}, {"zone", "duct-pad"}, {"rest_duration_s", 0.005}}}};
  ExpectRefused(sweep, {"sweep.solver.end_time_s", "window_s"});
}

// Members, states and settings the study file no longer has are not counted.
TEST_F(SecurityResults, SizingCountsOnlyTheMembersOfTheCurrentFile) {
  ASSERT_EQ(RunStudy(SmallEnsemble(4)).exit_code, 0);
  {  // Members the next file drops, stored as not ok: not to be counted as such either.
    Connection c(Path("e.db"), Connection::Mode::kReadWriteCreate);
    c.Execute("UPDATE ensemble_members SET status = 'failed' WHERE state = 'worn' OR member = 3");
  }
  json fewer = SmallEnsemble(2);
  fewer["clearance_states"].erase(1);
  fewer["settings"] = {{"solver.r_ftrunc", {100}}};
  const Outcome rerun = RunStudy(fewer);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  const Outcome o = RunShockmap("sizing --db " + Path("e.db") + " --format csv");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_FALSE(Has(o, "worn")) << o.output;
  EXPECT_FALSE(Has(o, "\":30}")) << o.output;
  EXPECT_TRUE(Has(o, "new,\"{\"\"solver.r_ftrunc\"\":100} (refined)\",2,")) << o.output;
  const Outcome table = RunShockmap("sizing --db " + Path("e.db"));
  EXPECT_TRUE(Has(table, "4 stored members the study file no longer has: not counted"))
      << table.output;
  EXPECT_FALSE(Has(table, "not ok")) << table.output;
}

// A window inside one step has nothing to score: `compare` refuses it with the step, and a
// study's points fail, never pass.
TEST_F(SecurityResults, WindowShorterThanOneStepFails) {
  const Outcome compare = RunShockmap("compare --rk 10 --rftrunc 10 --window 1e-7");
  EXPECT_EQ(compare.exit_code, 2) << compare.output;
  EXPECT_TRUE(Has(compare, "--window: the 1e-07 s window is shorter than one time step, 0.000231"))
      << compare.output;
  EXPECT_TRUE(Has(compare, "nothing to compare")) << compare.output;
  const json study = {
      {"name", "short"},
      {"scoring",
       {{"window_s", 1e-7}, {"reference", {{"r_fref_min", 300}, {"r_fref_per_sqrt_rk", 3}}}}},
      {"grids", {{{"rk", {10, 100}}, {"rftrunc", {10}}}}}};
  ASSERT_EQ(RunStudy(study, "short.db").exit_code, 0);
  const Outcome q = RunShockmap("query --db " + Path("short.db") +
                                " --format csv \"SELECT status, err FROM results ORDER BY r_k\"");
  EXPECT_EQ(q.output, "status,err\nfailed,\nfailed,\n");
  const json sweep = {
      {"kind", "scene_sweep"},
      {"name", "sweep"},
      {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json"},
      {"sweep", {{"solver.r_ftrunc", {30}}}},
      {"reference", {{"solver.r_ftrunc", 100}}},
      {"scoring",
       {{"displacement", "tip"},
        {"zone", "tip_spring"},
        {"window_s", 1e-8},
        {"rest_duration_s", 0.005}}}};
  ASSERT_EQ(RunStudy(sweep, "sweep.db").exit_code, 0);
  const Outcome s = RunShockmap("query --db " + Path("sweep.db") +
                                " --format csv \"SELECT status, err, message FROM scene_results\"");
  EXPECT_TRUE(Has(s, "failed,,the window 1e-08 s is shorter than one time step")) << s.output;
}

// An ensemble's window inside one step would size nothing: refused before anything runs, with
// the window, the state and setting and the step, as canonical and scene studies end such a
// point failed.
TEST_F(SecurityResults, EnsembleWindowShorterThanOneStepIsRefused) {
  json spec = SmallEnsemble(3);
  spec["window_s"] = 1e-9;
  ExpectRefused(spec, {"study.json: window_s: 1e-09 s in state \"new\", setting "
                       "{\"solver.r_ftrunc\":30}: shorter than one time step (",
                       " s): a member would have nothing to size; it must hold at least one "
                       "step"});
}

// Criteria of a study where no truncation passes say so: no agreement with the paper's rule is
// claimed, and no empty value is printed as a number.
TEST_F(SecurityResults, CriteriaWhereNoTruncationPassesSayNoneDoes) {
  const json study = {
      {"name", "none"},
      {"scoring",
       {{"window_s", 0.02}, {"reference", {{"r_fref_min", 300}, {"r_fref_per_sqrt_rk", 3}}}}},
      {"grids", {{{"rk", {10, 1000}}, {"rftrunc", {10}}}}}};
  ASSERT_EQ(RunStudy(study, "none.db").exit_code, 0);
  const Outcome o = RunShockmap("criteria derive --db " + Path("none.db") + " --err-max 1e-9");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(Has(o,
                  "paper eq. 11  R_ftrunc > 300 for R_k > 1e2: no studied truncation passes at "
                  "R_k = 1e+03, so the data cannot confirm it."))
      << o.output;
  EXPECT_TRUE(Has(o, "time step   no studied time step passes at every R_k with a boundary"))
      << o.output;
  EXPECT_FALSE(Has(o, "agrees")) << o.output;
  EXPECT_FALSE(Has(o, "- dt_sharp")) << o.output;
}

// A power law of exponent 1 is the linear law: its tangent stiffness is constant, so the bound
// taken at the given penetration holds at any depth, and the run reports that bound and the
// sharp bound it used.
TEST_F(SecurityResults, PowerLawOfExponentOneReportsItsBound) {
  json scene = json::parse(
      testing::ReadBytes(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json"));
  json& zone = scene["zones"][0];
  zone["power_law"] = {{"coefficient_n_per_m_exponent", zone["stiffness_n_per_m"]},
                       {"exponent", 1.0},
                       {"bound_penetration_m", 1e-4}};
  zone.erase("stiffness_n_per_m");
  scene["solver"]["end_time_s"] = 0.02;
  const Outcome o = RunShockmap("simulate " + Write(scene, "scene.json") + " --json --quiet");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const json summary = json::parse(o.output);
  const json& bound = summary["power_law_bound"];
  EXPECT_EQ(bound["bound_penetration_m"], 1e-4) << bound;
  EXPECT_EQ(bound["deepest_zone"], "tip_spring") << bound;
  EXPECT_GT(bound["largest_penetration_m"].get<double>(), 0.0) << bound;
  EXPECT_FALSE(bound["exceeded"].get<bool>()) << bound;
  const double dt_sharp = summary["dt_sharp_s"].get<double>();
  EXPECT_NEAR(bound["dt_sharp_at_reached_penetrations_s"].get<double>(), dt_sharp, 1e-12 * dt_sharp)
      << bound;
}

// A criteria file's numbers are checked as every input file's are.
TEST_F(SecurityResults, CriteriaFileValuesAreChecked) {
  const json baseline = json::parse(
      testing::ReadBytes(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/baselines/paper_fig4.json"));
  const std::string scene = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json";
  struct Case {
    std::string key;
    std::function<void(json&)> edit;
    std::string words;
  };
  for (const auto& [key, edit, words] : std::vector<Case>{
           {"dt_ratio_max", [](json& c) { c["dt_ratio_max"] = -1; }, "must lie in (0, 1]"},
           {"dt_ratio_max", [](json& c) { c["dt_ratio_max"] = 1e300; }, "stability bound"},
           {"fit.p", [](json& c) { c["fit"]["p"] = 1e300; }, "must lie in [-10, 10]"},
           {"boundary[0].r_k", [](json& c) { c["boundary"][0]["r_k"] = 0; }, "(0, 1e+12]"},
           {"tolerances.dt_ratio_factor", [](json& c) { c["tolerances"]["dt_ratio_factor"] = 0.5; },
            "must lie in [1, 1000]"}}) {
    json criteria = baseline;
    edit(criteria);
    const std::string file = Write(criteria, "criteria.json");
    const Outcome o = RunShockmap("advise " + scene + " --criteria " + file);
    EXPECT_EQ(o.exit_code, 2) << key << ": " << o.output;
    EXPECT_TRUE(Has(o, file + ": " + key + ": value")) << o.output;
    EXPECT_TRUE(Has(o, words)) << o.output;
  }
}

// The thresholds and confidence of a criteria file lie where every use of them assumes
// (CriteriaOptions::IsValid): a confidence of 1 is an infinite interval, err_max 0 passes nothing.
TEST_F(SecurityResults, CriteriaFileOptionsAreCheckedAsDerivingThemIs) {
  const json baseline = json::parse(
      testing::ReadBytes(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/baselines/paper_fig4.json"));
  const std::string scene = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json";
  struct Case {
    std::function<void(json&)> edit;
    std::string words;
  };
  for (const auto& [edit, words] :
       std::vector<Case>{{[](json& c) { c["fit"]["confidence"] = 1; },
                          ": fit.confidence: confidence = 1: must be in [0.5, 0.9999]"},
                         {[](json& c) { c["thresholds"]["err_max"] = 0; },
                          ": thresholds.err_max: err_max = 0: must be in [1e-09, 1]"}}) {
    json criteria = baseline;
    edit(criteria);
    const std::string file = Write(criteria, "criteria.json");
    const Outcome o = RunShockmap("advise " + scene + " --criteria " + file);
    EXPECT_EQ(o.exit_code, 2) << words << ": " << o.output;
    EXPECT_TRUE(Has(o, file + words)) << o.output;
  }
}

// A gap law's bound above its mean, and a preload deeper than the pin pitch.
TEST_F(SecurityResults, GapLawsAndPreloadsAreCheckedAgainstTheGeometry) {
  json above = SmallEnsemble(3);
  above["clearance_states"][0]["pin_gap_m"] = {{"mean", 1e-5}, {"std", 1e-6}, {"min", 2e-5}};
  ExpectRefused(above, {"clearance_states[0].pin_gap_m.min: value 2e-05 m lies above the mean"});
  json deep = SmallEnsemble(3);
  deep["clearance_states"][1]["pin_gap_m"] = {{"mean", -0.1}, {"std", 0.0}, {"min", -0.1}};
  ExpectRefused(deep, {"state \"worn\"", "bundle.wire.gap_m",
                       "-0.1 m is a preload deeper than "
                       "the pin pitch (0.0072644 m)"});
}

// The same limits, and words that say what is wrong, on every flag.
TEST_F(SecurityResults, FlagChecksAgreeAcrossCommands) {
  const Outcome rk = RunShockmap("compare --rk 1e20 --rftrunc 10");
  EXPECT_EQ(rk.exit_code, 2) << rk.output;
  EXPECT_TRUE(Has(rk, "--rk: value 1e20 is out of range: must be > 0 and <= 1e+12")) << rk.output;
  const Outcome tiny = RunShockmap("compare --rk 4.9e-324 --rftrunc 10");
  EXPECT_EQ(tiny.exit_code, 2);
  EXPECT_TRUE(Has(tiny, "--rk: value 4.9e-324 is out of range")) << tiny.output;
  const Outcome factor = RunShockmap("compare --rk 10 --rftrunc 10 --dt-factor 1e-300");
  EXPECT_EQ(factor.exit_code, 2) << factor.output;
  EXPECT_TRUE(Has(factor,
                  "--dt-factor: 1e-300 of the sharp bound, 2.311e-303 s, over the 0.06 s "
                  "window is 2.6e+301 steps; at most 100000000 are allowed"))
      << factor.output;

  ASSERT_EQ(RunStudy(SmallEnsemble(1)).exit_code, 0);
  const Outcome point =
      RunShockmap("export point --db " + Path("e.db") + " --id 1 --out " + Path("point"));
  EXPECT_EQ(point.exit_code, 2) << point.output;
  EXPECT_FALSE(fs::exists(Path("point")));
  const Outcome inf = RunShockmap("query --db " + Path("e.db") +
                                  " --format json \"SELECT 1e999 AS a, -1e999 AS b, NULL AS c\"");
  EXPECT_EQ(json::parse(inf.output), json::parse(R"([{"a": "inf", "b": "-inf", "c": null}])"))
      << inf.output;

  const Outcome zsh = RunShockmap("completion zsh");
  EXPECT_EQ(zsh.exit_code, 2);
  EXPECT_TRUE(Has(zsh, "completion: \"zsh\" is not a shell shockmap completes; the shells: bash"))
      << zsh.output;
  // Only completion itself takes a word it does not know; its shells refuse extras.
  for (const char* extra : {"junk", "--bogus"}) {
    const Outcome bash = RunShockmap(std::string("completion bash ") + extra);
    EXPECT_EQ(bash.exit_code, 2) << extra << ": " << bash.output;
    EXPECT_TRUE(Has(bash, extra)) << bash.output;
  }
}

}  // namespace
}  // namespace shockmap

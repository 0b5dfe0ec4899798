// The command line as a user meets it: exit codes, messages naming the flag, JSON keys.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/run_command.h"

namespace {

using shockmap::testing::Outcome;
using shockmap::testing::RunShockmap;

struct BadFlag {
  const char* name;
  const char* args;
  const char* must_mention;
};

void PrintTo(const BadFlag& f, std::ostream* os) { *os << f.name << ": " << f.args; }

class CompareRejects : public ::testing::TestWithParam<BadFlag> {};

TEST_P(CompareRejects, WithExitCodeTwoNamingTheFlag) {
  const Outcome o = RunShockmap(std::string("compare ") + GetParam().args);
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find(GetParam().must_mention), std::string::npos) << o.output;
}

INSTANTIATE_TEST_SUITE_P(
    BadValues, CompareRejects,
    ::testing::Values(
        BadFlag{"NegativeStiffness", "--rk -5 --rftrunc 300", "--rk"},
        BadFlag{"ZeroStiffness", "--rk 0 --rftrunc 300", "--rk"},
        BadFlag{"NanStiffness", "--rk nan --rftrunc 300", "--rk"},
        BadFlag{"InfStiffness", "--rk inf --rftrunc 300", "--rk"},
        BadFlag{"NotANumber", "--rk 3e3x --rftrunc 300", "--rk"},
        BadFlag{"TruncationBelowOne", "--rk 3000 --rftrunc 0.5", "--rftrunc"},
        BadFlag{"ZeroWindow", "--rk 3000 --rftrunc 300 --window 0", "--window"},
        BadFlag{"NegativeDt", "--rk 3000 --rftrunc 300 --dt -1e-5", "--dt"},
        BadFlag{"DtAndFactor", "--rk 3000 --rftrunc 300 --dt 1e-5 --dt-factor 2", "--dt"},
        BadFlag{"UnknownRule", "--rk 3000 --rftrunc 300 --dt-rule loose", "--dt-rule"},
        BadFlag{"UnknownScheme", "--rk 3000 --rftrunc 300 --scheme rk4", "--scheme"},
        BadFlag{"MissingStiffness", "--rftrunc 300", "--rk"},
        BadFlag{"PlotWithoutOut", "--rk 3000 --rftrunc 300 --plot", "--out"},
        BadFlag{"UnknownFlag", "--rk 3000 --rftrunc 300 --speed 3", "--speed"},
        BadFlag{"UnwritableOut", "--rk 3000 --rftrunc 10 --out /proc/shockmap", "/proc/shockmap"}),
    [](const auto& info) { return std::string(info.param.name); });

// A misspelt option or command is named with the one most likely meant, even where it hides a
// required option; an argument too many is named too.
TEST(CommandLineTypos, AreNamedWithTheOptionOrCommandMeant) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"compare --rk 3000 --rftruc 300",
       "compare: unknown option --rftruc (did you mean --rftrunc?); `shockmap compare --help` "
       "lists the options"},
      {"compare --rk 3000 --rftrunc 300 --jsn=1",
       "compare: unknown option --jsn (did you mean --json?); `shockmap compare --help` lists "
       "the options"},
      {"compare --rk 3000 --rftrunc 300 --turbo",
       "compare: unknown option --turbo; `shockmap compare --help` lists the options"},
      {"compare --rk 3000 --rftrunc 300 fast",
       "compare: unexpected argument \"fast\"; `shockmap compare --help` says what it takes"},
      {"simulte x.json",
       "unknown command \"simulte\" (did you mean \"simulate\"?); use one of compare, study, "},
      {"--verbose compare", "unknown option --verbose; `shockmap --help` lists the options"},
  };
  for (const auto& [args, message] : cases) {
    const Outcome o = RunShockmap(args);
    EXPECT_EQ(o.exit_code, 2) << args << ": " << o.output;
    EXPECT_EQ(o.output.rfind("shockmap: error: " + message, 0), 0u) << args << ": " << o.output;
  }
}

TEST(CompareCommand, PaperRuleDivergesAndHalfSharpBoundIsOk) {
  const Outcome paper =
      RunShockmap("compare --rk 3000 --rftrunc 10 --dt-rule paper --dt-factor 1 --json");
  ASSERT_EQ(paper.exit_code, 0) << paper.output;
  const auto p = nlohmann::json::parse(paper.output);
  EXPECT_EQ(p["status"], "diverged");
  EXPECT_TRUE(p["err"].is_null());
  EXPECT_GT(p["dt_paper_s"].get<double>(), p["dt_sharp_s"].get<double>());

  const Outcome sharp =
      RunShockmap("compare --rk 3000 --rftrunc 10 --dt-rule sharp --dt-factor 0.5 --json");
  ASSERT_EQ(sharp.exit_code, 0) << sharp.output;
  const auto s = nlohmann::json::parse(sharp.output);
  EXPECT_EQ(s["status"], "ok");
  EXPECT_NEAR(s["dt_requested_s"].get<double>(), 0.5 * s["dt_sharp_s"].get<double>(), 1e-15);
}

TEST(CompareCommand, JsonCarriesEveryDocumentedKey) {
  const Outcome o = RunShockmap("compare --rk 3000 --rftrunc 300 --json");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const auto j = nlohmann::json::parse(o.output);
  for (const char* key : {"err", "srf", "status", "n_modes", "dt_s", "dt_paper_s", "dt_sharp_s",
                          "ref_convergence", "wall_ref_s", "wall_num_s"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["status"], "ok");
  EXPECT_LT(j["err"].get<double>(), 0.10);
}

// Counts agree with their nouns: at R_k = 100 the first shock has one rebound.
TEST(CompareCommand, OneReboundIsSingular) {
  const Outcome o = RunShockmap("compare --rk 100 --rftrunc 10 --window 0.03");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find(" ms, 1 rebound\n"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("1 rebounds"), std::string::npos) << o.output;
}

// The full FE scheme has no modal basis: its model line says so instead of "modes kept".
TEST(CompareCommand, FullFeSchemePrintsItsModelNotModes) {
  const Outcome modal = RunShockmap("compare --rk 3000 --rftrunc 30 --window 0.02");
  ASSERT_EQ(modal.exit_code, 0) << modal.output;
  EXPECT_NE(modal.output.find("modes kept"), std::string::npos) << modal.output;
  const Outcome full =
      RunShockmap("compare --rk 3000 --rftrunc 30 --window 0.02 --scheme implicit-full");
  ASSERT_EQ(full.exit_code, 0) << full.output;
  EXPECT_EQ(full.output.find("modes kept"), std::string::npos) << full.output;
  EXPECT_NE(full.output.find("the full FE model"), std::string::npos) << full.output;
}

// `advise` on a shipped bundle reads the outcome of its check on the bundle's ensemble
// (studies/baselines/advice_checks.json) and warns of nothing; the same bundle with its wires
// 1 % stiffer has no recorded check, and what one beam did not measure is a warning again.
TEST(AdviseCommand, TheShippedBundleIsCheckedAndAnEditedOneIsNot) {
  const std::string scene = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json";
  const Outcome shipped = RunShockmap("advise " + scene);
  EXPECT_EQ(shipped.exit_code, 0) << shipped.output;
  EXPECT_EQ(shipped.output.find("warning"), std::string::npos) << shipped.output;
  EXPECT_NE(shipped.output.find("checked      on the scene's ensemble: the advice held"),
            std::string::npos)
      << shipped.output;

  nlohmann::json edited = nlohmann::json::parse(shockmap::testing::ReadBytes(scene));
  edited["bundle"]["wire"]["stiffness_n_per_m"] = 1.01e6;
  const std::string copy = (std::filesystem::temp_directory_path() /
                            ("shockmap_edited_row_" + std::to_string(getpid()) + ".json"))
                               .string();
  shockmap::testing::WriteText(copy, edited.dump(2));
  const Outcome changed = RunShockmap("advise " + copy);
  std::filesystem::remove(copy);
  EXPECT_EQ(changed.exit_code, 0) << changed.output;
  EXPECT_NE(changed.output.find("warning      no studied truncation passes"), std::string::npos)
      << changed.output;
  EXPECT_NE(changed.output.find("check-advice STUDY.json --record FILE"), std::string::npos)
      << changed.output;
}

// A number as the README writes it ("0.490"), rounded to as many decimals.
std::string AsQuoted(double value, const std::string& quoted) {
  const auto point = quoted.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(quoted.size() - point - 1);
  return fmt::format("{:.{}f}", value, decimals);
}

// The scores the README quotes for the paper's Fig. 3 (R_k = 3000: its defaults table and its
// fidelity paragraph), read from README.md itself, are what `compare` gives at each truncation.
TEST(Readme, QuotesTheFig3ScoresCompareGives) {
  const std::string readme =
      shockmap::testing::ReadBytes(std::string(SHOCKMAP_SOURCE_DIR) + "/README.md");
  std::map<std::string, nlohmann::json> runs;  // By R_ftrunc as quoted.
  auto run = [&](const std::string& r_ftrunc) -> const nlohmann::json& {
    if (!runs.contains(r_ftrunc)) {
      const Outcome o = RunShockmap("compare --rk 3000 --rftrunc " + r_ftrunc + " --json");
      EXPECT_EQ(o.exit_code, 0) << o.output;
      runs[r_ftrunc] = nlohmann::json::parse(o.output);
    }
    return runs[r_ftrunc];
  };
  const std::regex table_row(R"(\| (\d+) \| (\d+) \| ([0-9.]+) \| ([0-9.]+) \|)");
  const auto table = readme.find("| R_ftrunc | modes | Err | SRf |");
  ASSERT_NE(table, std::string::npos);
  std::istringstream rows(readme.substr(table));
  int checked = 0;
  for (std::string line; std::getline(rows, line) && line.starts_with("|");) {
    std::smatch m;
    if (!std::regex_match(line, m, table_row)) continue;
    const nlohmann::json& j = run(m[1]);
    EXPECT_EQ(m[2], std::to_string(j["n_modes"].get<int>())) << line;
    EXPECT_EQ(m[3], AsQuoted(j["err"].get<double>(), m[3])) << line;
    EXPECT_EQ(m[4], AsQuoted(j["srf"].get<double>(), m[4])) << line;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  const std::regex trend(
      R"(Err gives the Fig\. 3 trend \(([0-9.]+) and ([0-9.]+) at\s+R_ftrunc (\d+) and (\d+), R_k = 3000\))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(readme, m, trend));
  EXPECT_EQ(m[1], AsQuoted(run(m[3])["err"].get<double>(), m[1]));
  EXPECT_EQ(m[2], AsQuoted(run(m[4])["err"].get<double>(), m[2]));
}

TEST(CompareCommand, HelpExitsZero) {
  const Outcome o = RunShockmap("compare --help");
  EXPECT_EQ(o.exit_code, 0);
  EXPECT_NE(o.output.find("--rftrunc"), std::string::npos);
}

}  // namespace

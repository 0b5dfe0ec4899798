// Command-line conventions: --version names the release of CHANGELOG.md, SHOCKMAP_DB, the bash
// completion names every command and option and completes their values, ignored options are
// refused, default data files are found beside the binary.

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::ReadBytes;
using testing::RunShell;
using testing::RunShockmap;
using testing::WriteText;

class CliConventions : public testing::TempDirTest {};

constexpr const char* kStudy =
    R"({"name": "g", "scoring": {"window_s": 0.03},
        "grids": [{"rk": [100, 3162.2776601683795], "rftrunc": [10, 300]}]})";

TEST(CliVersion, PrintsTheTopReleaseOfTheChangelog) {
  const std::string changelog = ReadBytes(std::string(SHOCKMAP_SOURCE_DIR) + "/CHANGELOG.md");
  std::smatch top;
  ASSERT_TRUE(std::regex_search(changelog, top, std::regex(R"(\n## \[(\d+\.\d+\.\d+)\])")));
  const auto o = RunShockmap("--version");
  EXPECT_EQ(o.exit_code, 0);
  EXPECT_EQ(o.output.rfind("shockmap " + top[1].str() + " (git ", 0), 0u) << o.output;
  EXPECT_NE(o.output.find(SHOCKMAP_TEST_BUILD_TYPE), std::string::npos) << o.output;
}

TEST_F(CliConventions, ShockmapDbNamesTheDefaultDatabaseAndABadValueIsRefused) {
  WriteText(Path("g.json"), kStudy);
  const std::string env = "SHOCKMAP_DB=" + Path("env.db") + " ";
  ASSERT_EQ(RunShell("cd " + Path("") + " && " + env + SHOCKMAP_BIN + " study run g.json --quiet")
                .exit_code,
            0);
  EXPECT_TRUE(std::filesystem::exists(Path("env.db")));
  EXPECT_FALSE(std::filesystem::exists(Path("shockmap.db")));
  const auto count =
      RunShell(env + SHOCKMAP_BIN + " query 'SELECT count(*) FROM results' --format csv");
  EXPECT_EQ(count.output, "count(*)\n4\n");
  // --db wins over the variable.
  EXPECT_EQ(RunShell(env + SHOCKMAP_BIN + " study status --db " + Path("none.db")).exit_code, 2);
  for (const std::string& bad : {std::string("SHOCKMAP_DB= "), "SHOCKMAP_DB=" + Path("") + " "}) {
    const auto o = RunShell(bad + SHOCKMAP_BIN + " study status");
    EXPECT_EQ(o.exit_code, 2) << bad;
    EXPECT_NE(o.output.find("environment variable SHOCKMAP_DB"), std::string::npos) << o.output;
  }
}

// Subcommands and options of one command as its --help lists them.
struct HelpListing {
  std::vector<std::string> subcommands, options;
};

HelpListing Help(const std::string& command) {
  const std::string text = RunShockmap(command + " --help").output;
  HelpListing h;
  std::istringstream lines(text);
  std::string line;
  bool in_subcommands = false;
  while (std::getline(lines, line)) {
    if (line.rfind("Subcommands:", 0) == 0) in_subcommands = true;
    std::smatch m;
    if (in_subcommands && std::regex_search(line, m, std::regex(R"(^  ([a-z0-9]+)\s)"))) {
      h.subcommands.push_back(m[1]);
    }
    // An option line: "  -h,--help  ..." or "  --db TEXT  ...", its names before the text.
    static const std::regex option(R"(^\s+(-[a-zA-Z],)?(--[a-z-]+))");
    std::smatch o;
    if (!in_subcommands && std::regex_search(line, o, option)) h.options.push_back(o[2]);
  }
  return h;
}

TEST(CliCompletion, TheBashScriptNamesEveryCommandAndOptionAndCompletes) {
  const auto script = RunShockmap("completion bash");
  ASSERT_EQ(script.exit_code, 0);
  std::vector<std::string> paths = {""};
  std::size_t checked = 0;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const HelpListing h = Help(paths[i]);
    std::string words;
    const std::string head = "    \"" + paths[i] + "\") words=\"";
    const auto at = script.output.find(head);
    ASSERT_NE(at, std::string::npos) << "no branch for \"" << paths[i] << "\"";
    words = " " +
            script.output.substr(at + head.size(),
                                 script.output.find('"', at + head.size()) - at - head.size()) +
            " ";
    for (const auto& sub : h.subcommands) {
      EXPECT_NE(words.find(" " + sub + " "), std::string::npos) << paths[i] << ": " << sub;
      paths.push_back(paths[i] + " " + sub);
    }
    for (const auto& option : h.options) {
      EXPECT_NE(words.find(" " + option + " "), std::string::npos) << paths[i] << ": " << option;
      ++checked;
    }
  }
  EXPECT_GE(paths.size(), 20u);  // Every command and subcommand was visited.
  EXPECT_GE(checked, 60u);
  // The script completes in bash: a subcommand, then an option of it.
  const std::string file = ::testing::TempDir() + "/shockmap_completion.bash";
  WriteText(file, script.output);
  const auto completes = [&](const std::string& words, int cword) {
    return RunShell("bash -c 'source " + file + "; COMP_WORDS=(" + words + "); COMP_CWORD=" +
                    std::to_string(cword) + "; _shockmap; echo \"${COMPREPLY[*]}\"'")
        .output;
  };
  EXPECT_EQ(completes("shockmap study r", 2), "run\n");
  EXPECT_EQ(completes("shockmap study run --ret", 3), "--retry-failed\n");
  EXPECT_EQ(completes("shockmap map --db \"\"", 3), "\n");  // A file name follows --db.
  // After a flag, the next word completes.
  EXPECT_EQ(completes("shockmap study run --quiet --ret", 4), "--retry-failed\n");
  EXPECT_EQ(completes("shockmap advise --json --zo", 3), "--zones\n");
}

// The values `command --help` lists for `option` ("--metric TEXT:{err,srf}" gives "err srf").
std::string ListedValues(const std::string& command, const std::string& option) {
  const std::string help = RunShockmap(command + " --help").output;
  std::smatch m;
  if (!std::regex_search(help, m, std::regex("  " + option + R"( TEXT:\{([a-z,-]+)\})"))) return "";
  return std::regex_replace(m[1].str(), std::regex(","), " ");
}

class CliCompletionValues : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    const auto script = RunShockmap("completion bash");
    ASSERT_EQ(script.exit_code, 0);
    WriteText(Path("completion.bash"), script.output);
  }
  // COMPREPLY for the words typed (the binary's path first) with the cursor on word `cword`.
  std::string Completes(const std::string& words, int cword, const std::string& env = "") {
    return RunShell(env + "bash -c 'source " + Path("completion.bash") + "; COMP_WORDS=(" +
                    SHOCKMAP_BIN + " " + words + "); COMP_CWORD=" + std::to_string(cword) +
                    "; _shockmap; echo \"${COMPREPLY[*]}\"'")
        .output;
  }
};

TEST_F(CliCompletionValues, ListedOptionsCompleteTheValuesTheCommandAccepts) {
  const std::vector<std::pair<std::string, std::string>> listed = {
      {"map", "--metric"},      {"map", "--y"},        {"compare", "--scheme"},
      {"compare", "--dt-rule"}, {"query", "--format"}, {"sizing", "--format"}};
  for (const auto& [command, option] : listed) {
    const std::string values = ListedValues(command, option);
    ASSERT_NE(values, "") << command << " " << option << " lists no values in --help";
    EXPECT_EQ(Completes(command + " " + option + " \"\"", 3), values + "\n")
        << command << " " << option;
  }
  EXPECT_NE(ListedValues("map", "--metric").find("status"), std::string::npos);
  EXPECT_EQ(Completes("compare --dt-rule s", 3), "sharp\n");
  EXPECT_EQ(Completes("query --format c", 3), "csv\n");
  EXPECT_EQ(Completes("compare --scheme = i", 4), "implicit-full\n");  // --scheme=i
  // After the value, options again.
  EXPECT_EQ(Completes("map --y dt --met", 4), "--metric\n");
  // --allow-path takes a folder.
  std::filesystem::create_directories(Path("data_folder"));
  WriteText(Path("data_file"), "");
  EXPECT_EQ(Completes("advise --allow-path " + Path("data_"), 3), Path("data_folder") + "\n");
}

TEST_F(CliCompletionValues, StudyArgumentsCompleteTheStoredStudiesOfTheDatabase) {
  WriteText(Path("g.json"), kStudy);
  ASSERT_EQ(
      RunShockmap("study run " + Path("g.json") + " --db " + Path("s.db") + " --quiet").exit_code,
      0);
  EXPECT_EQ(Completes("map --db " + Path("s.db") + " \"\"", 4).rfind("g --help", 0), 0u);
  EXPECT_EQ(Completes("report --db " + Path("s.db") + " g", 4), "g\n");
  EXPECT_EQ(Completes("advise --json --db " + Path("s.db") + " g", 5), "g\n");
  // Both studies `diff` compares.
  EXPECT_EQ(Completes("diff --db " + Path("s.db") + " g", 4), "g\n");
  EXPECT_EQ(Completes("diff --db " + Path("s.db") + " g g", 5), "g\n");
  // The default database, as the command opens it: $SHOCKMAP_DB.
  EXPECT_EQ(Completes("criteria derive g", 3, "SHOCKMAP_DB=" + Path("s.db") + " "), "g\n");
  // A study file, not a name, follows `study run`; no database, no names.
  EXPECT_EQ(Completes("study run --db " + Path("s.db") + " g", 5), "\n");
  EXPECT_EQ(Completes("map --db " + Path("none.db") + " g", 4), "\n");
  EXPECT_FALSE(std::filesystem::exists(Path("none.db")));
}

TEST_F(CliConventions, OptionsThatWouldBeIgnoredAreRefused) {
  WriteText(Path("g.json"), kStudy);
  const std::string db = " --db " + Path("s.db");
  ASSERT_EQ(RunShockmap("study run " + Path("g.json") + db + " --quiet").exit_code, 0);
  const std::string bytes = ReadBytes(Path("s.db"));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"cost --out " + Path("x.png") + db, "--out"},
      {"map --rftrunc 100 --out " + Path("m.png") + db, "--rftrunc"},
      {"compare --rk 3000 --rftrunc 300 --plot", "--plot"},
      {"export reference --out " + Path("r.csv") + db, "--rk"},
      {"export reference --rk 100 --point 1 --out " + Path("r.csv") + db, "--point"},
  };
  for (const auto& [args, flag] : cases) {
    const auto o = RunShockmap(args);
    EXPECT_EQ(o.exit_code, 2) << args << ": " << o.output;
    EXPECT_NE(o.output.find(flag), std::string::npos) << o.output;
  }
  EXPECT_FALSE(std::filesystem::exists(Path("x.png")));
  EXPECT_FALSE(std::filesystem::exists(Path("m.png")));
  EXPECT_FALSE(std::filesystem::exists(Path("r.csv")));
  EXPECT_TRUE(ReadBytes(Path("s.db")) == bytes);
}

// A file or folder that is not there is said so in one wording by every command, and --db,
// whose file `study run` creates, is not shown as a file that must exist.
TEST_F(CliConventions, MissingFilesAreNamedAlikeAndTheDatabaseMayBeNew) {
  const std::string missing = Path("nothere.json");
  for (const std::string& args :
       {"study run " + missing + " --db " + Path("s.db"), "simulate " + missing}) {
    const auto o = RunShockmap(args);
    EXPECT_EQ(o.exit_code, 2) << args << o.output;
    EXPECT_EQ(o.output, "shockmap: error: " + missing + ": no such file\n") << args;
  }
  WriteText(Path("file"), "");
  for (const std::string& folder : {Path("none"), Path("file")}) {
    const auto o = RunShockmap("simulate " + missing + " --allow-path " + folder);
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_EQ(o.output, "shockmap: error: --allow-path: " + folder +
                            (folder == Path("file") ? ": not a folder\n" : ": no such folder\n"));
  }
  for (const std::string command : {"study run", "study status", "map", "sizing"}) {
    const std::string help = RunShockmap(command + " --help").output;
    EXPECT_NE(help.find("  --db FILE "), std::string::npos) << command << ":\n" << help;
    EXPECT_NE(help.find("created by `study run` when missing"), std::string::npos) << help;
  }
}

TEST_F(CliConventions, DefaultFileNamesCarryNoFloatNoise) {
  WriteText(Path("g.json"), kStudy);
  ASSERT_EQ(
      RunShockmap("study run " + Path("g.json") + " --db " + Path("s.db") + " --quiet").exit_code,
      0);
  // The nearest studied R_k to 3000 is 10^3.5 = 3162.2776601683795.
  const auto o = RunShell("cd " + Path("") + " && " + SHOCKMAP_BIN + " cost --db s.db --rk 3000");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("plot written to out/g_cost_rk3162.28.png"), std::string::npos)
      << o.output;
  EXPECT_TRUE(std::filesystem::exists(Path("out/g_cost_rk3162.28.png")));
}

// `advise SCENE.json` reads its default criteria from the working folder, else from the shared
// data beside the binary (<bin>/../share/shockmap); a path the user gives is used as given.
TEST_F(CliConventions, AdviseFindsItsDefaultCriteriaBesideTheBinary) {
  const std::string source = SHOCKMAP_SOURCE_DIR;
  const std::string scene = source + "/scenes/bundle_hex_7.json";
  const std::string baseline = "studies/baselines/modes_fig4_peak_force.json";
  std::filesystem::create_directories(Path("work"));
  std::filesystem::create_directories(Path("prefix/bin"));
  std::filesystem::copy_file(SHOCKMAP_BIN, Path("prefix/bin/shockmap"));
  const auto advise = [&](const std::string& binary, const std::string& flags = "") {
    return RunShell("cd " + Path("work") + " && " + binary + " advise " + scene + flags);
  };
  // The build's binary finds the sources' baseline through build/share/shockmap.
  const auto built = advise(SHOCKMAP_BIN);
  EXPECT_EQ(built.exit_code, 0) << built.output;
  EXPECT_NE(built.output.find("/share/shockmap/" + baseline), std::string::npos) << built.output;

  const std::string shared = Path("prefix/share/shockmap/" + baseline);
  const auto missing = advise(Path("prefix/bin/shockmap"));
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("--criteria"), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find(Path("work/" + baseline)), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find(shared), std::string::npos) << missing.output;

  std::filesystem::create_directories(Path("prefix/share/shockmap/studies/baselines"));
  std::filesystem::copy_file(source + "/" + baseline, shared);
  // The recorded checks of the advice are a default data file too.
  const std::string checks = "studies/baselines/advice_checks.json";
  const auto without_checks = advise(Path("prefix/bin/shockmap"));
  EXPECT_EQ(without_checks.exit_code, 2) << without_checks.output;
  EXPECT_NE(without_checks.output.find("--checks: the default file " + checks), std::string::npos)
      << without_checks.output;
  std::filesystem::copy_file(source + "/" + checks, Path("prefix/share/shockmap/" + checks));
  const auto found = advise(Path("prefix/bin/shockmap"));
  EXPECT_EQ(found.exit_code, 0) << found.output;
  EXPECT_EQ(found.output.rfind("criteria from " + shared + "\n", 0), 0u) << found.output;
  std::string same_advice = built.output;
  same_advice.replace(0, same_advice.find('\n'), "criteria from " + shared);
  // The recorded check is named by where it was read.
  const std::string built_share =
      (std::filesystem::path(SHOCKMAP_BIN).parent_path().parent_path() / "share" / "shockmap")
          .lexically_normal()
          .string();
  const std::size_t at = same_advice.find(built_share);
  ASSERT_NE(at, std::string::npos) << same_advice;
  same_advice.replace(at, built_share.size(), Path("prefix/share/shockmap"));
  EXPECT_EQ(found.output, same_advice);

  // Given, the same relative path is read from the working folder only.
  const auto given = advise(Path("prefix/bin/shockmap"), " --criteria " + baseline);
  EXPECT_EQ(given.exit_code, 2) << given.output;
  EXPECT_NE(given.output.find(baseline), std::string::npos) << given.output;
  EXPECT_EQ(given.output.find(shared), std::string::npos) << given.output;
  // A copy in the working folder comes first.
  std::filesystem::create_directories(Path("work/studies/baselines"));
  std::filesystem::copy_file(source + "/" + baseline, Path("work/" + baseline));
  EXPECT_EQ(advise(Path("prefix/bin/shockmap")).output.rfind("criteria from " + baseline + "\n", 0),
            0u);
}

}  // namespace
}  // namespace shockmap

// Outputs under attack and under faults: names and paths that try to run commands through
// gnuplot or a shell, standard output and files on a full disk, outputs that cannot exist,
// unbounded queries, databases on read-only media. One suite per class of fault.

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/run_command.h"
#include "tests/temp_dir.h"
#include "views/gnuplot.h"

namespace shockmap {
namespace {

using testing::Outcome;
using testing::ReadBytes;
using testing::TempDirTest;
using testing::WriteText;

const std::string kBin = SHOCKMAP_BIN;
const std::string kInjection = "n\" ; system \"touch PWNED\" ; print \"";
const std::string kSingleInjection = "z' ; system('touch PWNED') ; print '";

// Runs `command` with /bin/sh; its stderr (and stdout unless redirected) is captured.
Outcome Shell(const std::string& command) { return testing::RunShell(command); }

// `text` as one single-quoted /bin/sh word.
std::string Sh(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Any file named PWNED below `dir` or in the current directory.
bool Pwned(const std::filesystem::path& dir) {
  if (std::filesystem::exists("PWNED")) return true;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.path().filename() == "PWNED") return true;
  }
  return false;
}

// The shipped one-beam scene, renamed; its zone renamed too.
void WriteScene(const std::string& path, const std::string& name, const std::string& zone) {
  auto scene = nlohmann::json::parse(
      ReadBytes(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json"));
  scene["name"] = name;
  scene["zones"][0]["name"] = zone;
  WriteText(path, scene.dump(2));
}

// A six-point study named `name`, run into `db`.
void RunTinyStudy(const std::string& spec, const std::string& db, const std::string& name) {
  nlohmann::json study = {{"name", name},
                          {"scoring", {{"window_s", 0.03}}},
                          {"grids",
                           {{{"rk", {{"logspace", {1, 3, 3}}}},
                             {"rftrunc", {{"logspace", {1, 2, 2}}}},
                             {"dt", {{"rule", "sharp"}, {"factor", {0.5}}}}}}}};
  WriteText(spec, study.dump(2));
  const Outcome run = Shell(kBin + " study run " + Sh(spec) + " --db " + Sh(db) + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
}

// Runs the command limited to `kib` KiB per file (RLIMIT_FSIZE) with SIGXFSZ ignored: writes
// past the limit fail with EFBIG ("File too large"), as writes on a full disk fail.
Outcome WithFileSizeLimit(int kib, const std::string& args) {
  return Shell("sh -c " + Sh("trap '' XFSZ; exec prlimit --fsize=" + std::to_string(1024 * kib) +
                             " " + kBin + " " + args));
}

// The first line of simulate's summary.
const std::string kSimulateSummary = "shockmap simulate:";

class GnuplotScripts : public TempDirTest {};

// Strings reach a script only as single-quoted gnuplot strings: a quote doubled, a line break
// or other control character (which would end the command) turned into a space.
TEST(GnuplotQuoting, QuotesAreDoubledAndLineBreaksCannotEndTheCommand) {
  EXPECT_EQ(GnuplotQuoted("plain"), "'plain'");
  EXPECT_EQ(GnuplotQuoted("a'; system('x'); '"), "'a''; system(''x''); '''");
  EXPECT_EQ(GnuplotQuoted("one\ntwo\r\tthree"), "'one two  three'");
  EXPECT_EQ(GnuplotQuoted("\"double\" \\n"), "'\"double\" \\n'");
}

// Names may not hold line breaks (refused when read, security_input_test); quotes and gnuplot's
// command separators are what remains to be escaped.
TEST_F(GnuplotScripts, SceneAndZoneNamesCannotRunCommands) {
  WriteScene(Path("scene.json"), kInjection + " second part", kSingleInjection);
  const Outcome o =
      Shell("cd " + Sh(dir_.string()) + " && " + kBin + " simulate scene.json --out out");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_GT(std::filesystem::file_size(dir_ / "out" / "contact_force_map.png"), 1000u);
  EXPECT_FALSE(Pwned(dir_)) << ReadBytes(Path("out/contact_force_map.gp"));
}

TEST_F(GnuplotScripts, StudyNamesCannotRunCommandsInMapsAndFig4) {
  RunTinyStudy(Path("study.json"), Path("s.db"), kInjection + " " + kSingleInjection);
  const std::string cd = "cd " + Sh(dir_.string()) + " && " + kBin;
  const Outcome map = Shell(cd + " map --db s.db --out maps/m.png");
  ASSERT_EQ(map.exit_code, 0) << map.output;
  const Outcome fig4 = Shell(cd + " plot fig4 --db s.db --out f.svg");
  ASSERT_EQ(fig4.exit_code, 0) << fig4.output;
  EXPECT_GT(std::filesystem::file_size(dir_ / "maps" / "m.png"), 1000u);
  EXPECT_FALSE(Pwned(dir_)) << ReadBytes(Path("maps/m.gp"));
}

class GnuplotProcess : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    RunTinyStudy(Path("study.json"), Path("s.db"), "tiny");
  }
  // `map` run from the test's folder, with `env` before the command.
  Outcome Map(const std::string& out, const std::string& env = "") {
    return Shell("cd " + Sh(dir_.string()) + " && " + env + kBin + " map --db s.db --out " +
                 Sh(out));
  }
  // A stand-in gnuplot first on the PATH, running `body`.
  std::string FakeGnuplot(const std::string& body) {
    std::filesystem::create_directories(dir_ / "bin");
    WriteText(Path("bin/gnuplot"), "#!/bin/sh\n" + body + "\n");
    std::filesystem::permissions(Path("bin/gnuplot"), std::filesystem::perms::owner_all);
    return "PATH=" + Sh(Path("bin") + ":/usr/bin:/bin") + " ";
  }
};

TEST_F(GnuplotProcess, OutputPathWithQuotesIsAFileNotAShellCommand) {
  const Outcome o = Map("x';touch PWNED;'.png");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_GT(std::filesystem::file_size(dir_ / "x';touch PWNED;'.png"), 1000u);
  EXPECT_FALSE(Pwned(dir_));
}

TEST_F(GnuplotProcess, OutputNamedLikeAPipeIsAFile) {
  for (const std::string out : {"|touch PWNED.png", "<touch PWNED.png"}) {
    const Outcome o = Map(out);
    ASSERT_EQ(o.exit_code, 0) << out << ": " << o.output;
    EXPECT_GT(std::filesystem::file_size(dir_ / out), 1000u) << out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "PWNED.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "PWNED.dat"));
}

TEST_F(GnuplotProcess, OutputNamedLikeAnOptionIsDrawn) {
  const Outcome o = Map("-m.png");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_GT(std::filesystem::file_size(dir_ / "-m.png"), 1000u);
}

TEST_F(GnuplotProcess, MissingGnuplotIsNamedAsSuch) {
  const Outcome o = Map("a.png", "PATH=/nonexistent ");
  EXPECT_EQ(o.exit_code, 1) << o.output;
  EXPECT_NE(o.output.find("gnuplot was not found"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("written"), std::string::npos) << o.output;
}

TEST_F(GnuplotProcess, FailingGnuplotGivesItsStatusAndMessageAndKeepsTheOldImage) {
  ASSERT_EQ(Map("a.png").exit_code, 0);
  const std::string before = ReadBytes(Path("a.png"));
  // It starts the file it is told to draw (-e "shockmap_output = './NAME'") and fails.
  const Outcome o = Map("a.png", FakeGnuplot("out=${2#*\\'}; out=${out%\\'}; echo 'line 3: boom' "
                                             ">&2; printf x > \"$out\"; exit 3"));
  EXPECT_EQ(o.exit_code, 1) << o.output;
  EXPECT_NE(o.output.find("status 3"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("line 3: boom"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("is gnuplot installed"), std::string::npos) << o.output;
  EXPECT_EQ(ReadBytes(Path("a.png")), before);
}

TEST_F(GnuplotProcess, GnuplotExitingWithoutAnImageIsAFailure) {
  const Outcome o = Map("b.png", FakeGnuplot("exit 0"));
  EXPECT_EQ(o.exit_code, 1) << o.output;
  EXPECT_NE(o.output.find("without writing"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("map written"), std::string::npos) << o.output;
}

class StandardOutput : public TempDirTest {
 protected:
  // The command with its standard output on a full device and its stderr captured.
  Outcome OnFullDevice(const std::string& args) {
    return Shell("{ cd " + Sh(dir_.string()) + " && " + kBin + " " + args + " >/dev/full; }");
  }
  void ExpectRefused(const Outcome& o) {
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find("standard output: No space left on device"), std::string::npos)
        << o.output;
  }
};

TEST_F(StandardOutput, FullDeviceFailsQueryStatusAndJsonSummaries) {
  RunTinyStudy(Path("study.json"), Path("s.db"), "tiny");
  ExpectRefused(OnFullDevice("query 'SELECT * FROM results' --db s.db --format csv"));
  ExpectRefused(OnFullDevice("study status --db s.db"));
  WriteScene(Path("scene.json"), "scene", "zone");
  ExpectRefused(OnFullDevice("simulate scene.json --json"));
  ExpectRefused(OnFullDevice("compare --rk 100 --rftrunc 10 --json"));
}

class PartialOutputs : public TempDirTest {};

TEST_F(PartialOutputs, FullDiskLeavesNoTruncatedFileAndClaimsNoSuccess) {
  WriteScene(Path("scene.json"), "scene", "zone");
  const Outcome full =
      Shell(kBin + " simulate " + Sh(Path("scene.json")) + " --out " + Sh(Path("full")));
  ASSERT_EQ(full.exit_code, 0) << full.output;
  std::filesystem::create_directories(dir_ / "cut");
  WriteText(Path("cut/energies.csv"), "earlier\n");
  const Outcome cut =
      WithFileSizeLimit(48, "simulate " + Sh(Path("scene.json")) + " --out " + Sh(Path("cut")));
  EXPECT_EQ(cut.exit_code, 2) << cut.output;
  EXPECT_NE(cut.output.find("File too large"), std::string::npos) << cut.output;
  EXPECT_EQ(cut.output.find("wrote"), std::string::npos) << cut.output;
  EXPECT_EQ(cut.output.find(kSimulateSummary), std::string::npos) << cut.output;
  // Each file left is complete, or the one that was there before.
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "cut")) {
    const auto name = entry.path().filename();
    if (name == "energies.csv" && ReadBytes(entry.path()) == "earlier\n") continue;
    EXPECT_EQ(ReadBytes(entry.path()), ReadBytes(dir_ / "full" / name)) << name;
  }
}

TEST_F(PartialOutputs, ImageCutShortByAFullDiskIsAFailure) {
  RunTinyStudy(Path("study.json"), Path("s.db"), "tiny");
  const Outcome o = WithFileSizeLimit(
      36, "map --db " + Sh(Path("s.db")) + " --metric status --out " + Sh(Path("m.png")));
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("only part of"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("map written"), std::string::npos) << o.output;
  EXPECT_FALSE(std::filesystem::exists(Path("m.png")));
}

class ImpossibleOutputs : public TempDirTest {};

TEST_F(ImpossibleOutputs, SimulateRefusesAFileAsItsOutputDirectoryBeforeRunning) {
  WriteScene(Path("scene.json"), "scene", "zone");
  WriteText(Path("taken"), "a file\n");
  const Outcome o =
      Shell(kBin + " simulate " + Sh(Path("scene.json")) + " --out " + Sh(Path("taken")));
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("--out"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("not a directory"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find(kSimulateSummary), std::string::npos) << o.output;
  EXPECT_EQ(ReadBytes(Path("taken")), "a file\n");
}

TEST_F(ImpossibleOutputs, PathsOverTheSystemLimitsAreRefusedByName) {
  WriteScene(Path("scene.json"), "scene", "zone");
  std::string deep = Path("d");
  while (deep.size() < 5000) deep += "/abcdefgh";
  const Outcome path = Shell(kBin + " simulate " + Sh(Path("scene.json")) + " --out " + Sh(deep));
  EXPECT_EQ(path.exit_code, 2) << path.output;
  EXPECT_NE(path.output.find("--out"), std::string::npos) << path.output;
  EXPECT_NE(path.output.find("bytes long"), std::string::npos) << path.output;
  EXPECT_EQ(path.output.find(kSimulateSummary), std::string::npos) << path.output;
  RunTinyStudy(Path("study.json"), Path("s.db"), "tiny");
  const Outcome name = Shell(kBin + " map --db " + Sh(Path("s.db")) + " --out " +
                             Sh(Path(std::string(300, 'a') + ".png")));
  EXPECT_EQ(name.exit_code, 2) << name.output;
  EXPECT_NE(name.output.find("255"), std::string::npos) << name.output;
}

class BoundedQuery : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    RunTinyStudy(Path("study.json"), Path("s.db"), "tiny");
  }
  Outcome Query(const std::string& sql, const std::string& flags) {
    return Shell(kBin + " query " + Sh(sql) + " --db " + Sh(Path("s.db")) + " " + flags);
  }
  const std::string endless_ = "WITH RECURSIVE c(x) AS (SELECT 1 UNION ALL SELECT x + 1 FROM c) ";
};

TEST_F(BoundedQuery, RowLimitStopsAnEndlessResultAfterStreamingIt) {
  const Outcome o = Query(endless_ + "SELECT x FROM c", "--format csv --max-rows 1000");
  EXPECT_EQ(o.exit_code, 2) << o.output.substr(0, 500);
  EXPECT_EQ(o.output.rfind("x\n1\n2\n", 0), 0u) << o.output.substr(0, 100);
  EXPECT_NE(o.output.find("\n1000\n"), std::string::npos);
  EXPECT_EQ(o.output.find("\n1001\n"), std::string::npos);
  EXPECT_NE(o.output.find("--max-rows"), std::string::npos)
      << o.output.substr(o.output.size() - 300);
}

TEST_F(BoundedQuery, TimeLimitStopsAStatementThatNeverReturns) {
  const auto start = std::chrono::steady_clock::now();
  const Outcome o = Query(endless_ + "SELECT count(*) FROM c", "--timeout-s 0.5");
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("time limit of 0.5 s"), std::string::npos) << o.output;
  EXPECT_LT(took, 20.0);
}

TEST_F(BoundedQuery, BadLimitsAreRefusedByFlag) {
  for (const std::string flags : {"--max-rows -1", "--timeout-s -2", "--timeout-s soon"}) {
    const Outcome o = Query("SELECT 1", flags);
    EXPECT_EQ(o.exit_code, 2) << flags << ": " << o.output;
    // "--flag: value V must be ...": the flag, the value and what is allowed.
    const std::string flag = flags.substr(0, flags.find(' '));
    EXPECT_NE(o.output.find(flag + ": value"), std::string::npos) << o.output;
    EXPECT_NE(o.output.find(flags.substr(flags.find(' ') + 1)), std::string::npos) << o.output;
  }
}

TEST_F(BoundedQuery, FormatsKeepTheirShape) {
  const std::string sql = "SELECT 1 AS a, 'x,y' AS b UNION ALL SELECT 22, NULL";
  EXPECT_EQ(Query(sql, "--format csv").output, "a,b\n1,\"x,y\"\n22,\n");
  EXPECT_EQ(Query(sql, "").output, "a   b  \n--  ---\n1   x,y\n22     \n(2 rows)\n");
  EXPECT_EQ(Query(sql, "--format json").output,
            "[\n  {\n    \"a\": 1,\n    \"b\": \"x,y\"\n  },\n  {\n    \"a\": 22,\n    \"b\": "
            "null\n  }\n]\n");
  EXPECT_EQ(Query("SELECT 1 WHERE 0", "--format json").output, "[]\n");
}

class ReadOnlyMedia : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    std::filesystem::create_directories(dir_ / "ro");
    RunTinyStudy(Path("study.json"), Path("ro/s.db"), "tiny");
  }
};

TEST_F(ReadOnlyMedia, FinishedDatabaseOnAReadOnlyMountAnswersReadOnlyCommands) {
  const std::string ro = Sh(Path("ro"));
  if (Shell("unshare -rm sh -c " + Sh("mount --bind " + ro + " " + ro)).exit_code != 0) {
    GTEST_SKIP() << "no mount namespace to make a read-only folder in";
  }
  const std::string db = Sh(Path("ro/s.db"));
  const Outcome o =
      Shell("unshare -rm sh -c " +
            Sh("mount --bind " + ro + " " + ro + " && mount -o remount,bind,ro " + ro + " && " +
               kBin + " query 'SELECT count(*) AS n FROM results' --db " + db + " && " + kBin +
               " study status --db " + db + " && " + kBin + " map --db " + db + " --out " +
               Sh(Path("maps/m.png")) + " && ! touch " + Sh(Path("ro/probe"))));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("6\n(1 row)"), std::string::npos) << o.output;
  EXPECT_TRUE(std::filesystem::exists(Path("maps/m.png")));
}

TEST_F(ReadOnlyMedia, ReadOnlyDatabaseFileGetsNoWalOrShmBesideIt) {
  namespace fs = std::filesystem;
  fs::permissions(Path("ro"), fs::perms::all);
  fs::permissions(Path("ro/s.db"),
                  fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(dir_, fs::perms::all);
  // Root writes any file: the query then runs as nobody.
  const std::string as_reader =
      ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const Outcome o = Shell(as_reader + kBin + " query 'SELECT count(*) AS n FROM results' --db " +
                          Sh(Path("ro/s.db")));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_FALSE(fs::exists(Path("ro/s.db-wal")));
  EXPECT_FALSE(fs::exists(Path("ro/s.db-shm")));
}

TEST_F(ReadOnlyMedia, OldSchemaAdviceNamesACommandThatMigrates) {
  // A file of schema version 2, as an older shockmap wrote it.
  std::filesystem::copy_file(std::string(SHOCKMAP_SOURCE_DIR) + "/tests/data/schema_v2.db",
                             Path("ro/s.db"), std::filesystem::copy_options::overwrite_existing);
  const Outcome o = Shell(kBin + " query 'SELECT 1' --db " + Sh(Path("ro/s.db")));
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("study run"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("study status"), std::string::npos) << o.output;
}

}  // namespace
}  // namespace shockmap

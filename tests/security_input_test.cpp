// Security and faults (issue 12): files a scene names stay in its folder, JSON nesting and
// repeated keys are refused while parsing, names hold no control characters and are unique,
// meshes beyond the eigenproblem budget are refused before anything is allocated, and messages
// quote at most a short escaped excerpt of any file. Each class: exit code 2, a message naming
// the file and key path (or flag), and nothing written.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "formats/json_reader.h"
#include "formats/scene_file.h"
#include "specs/scene_study_spec.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;
using testing::Outcome;
using testing::WriteText;

const std::string kSource = SHOCKMAP_SOURCE_DIR;

// The binary run as RunShockmap does, but stopped after `seconds` (exit code 124), so that a
// refusal that does not come is a failure rather than a hung test.
Outcome RunWithin(int seconds, const std::string& args) {
  return testing::RunShell("timeout " + std::to_string(seconds) + " " + SHOCKMAP_BIN + " " + args);
}

Json CanonicalScene() {
  std::ifstream in(kSource + "/scenes/cantilever_spring.json");
  return Json::parse(in);
}

class Security : public testing::TempDirTest {
 protected:
  // Runs `args` (DIR: the test's directory) and checks the refusal: exit 2, every part of
  // `named` in the message, and `secret` nowhere in it.
  std::string Refused(const std::string& args, const std::vector<std::string>& named,
                      const std::string& secret = "") {
    std::string a = args;
    for (auto at = a.find("DIR"); at != std::string::npos; at = a.find("DIR"))
      a.replace(at, 3, dir_.string());
    const Outcome r = RunWithin(30, a);
    EXPECT_EQ(r.exit_code, 2) << "shockmap " << a << "\n" << r.output;
    for (const auto& part : named)
      EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
    if (!secret.empty()) {
      EXPECT_EQ(r.output.find(secret), std::string::npos) << r.output;
    }
    std::printf("[security] %s\n", r.output.substr(0, r.output.find('\n')).c_str());
    return r.output;
  }

  // The canonical scene with one change, written to `name` in the test's directory.
  std::string Scene(const std::string& name, const std::function<void(Json&)>& change) {
    Json scene = CanonicalScene();
    change(scene);
    std::filesystem::create_directories((dir_ / name).parent_path());
    WriteText(Path(name), scene.dump(2));
    return Path(name);
  }
};

// 1. Reading arbitrary files.

TEST_F(Security, DataFilesOutsideTheScenesFolderAreRefused) {
  const std::string secret = "TOPSECRET_first_line_of_a_private_file_0123456789";
  WriteText(Path("private.csv"), secret + "\n0,1\n1,2\n");
  std::filesystem::create_directories(dir_ / "scenes");
  std::filesystem::create_symlink(dir_ / "private.csv", dir_ / "scenes" / "link.csv");
  for (const std::string& csv : {std::string("../private.csv"), Path("private.csv"),
                                 std::string("/proc/self/environ"), std::string("link.csv")}) {
    const std::string scene = Scene("scenes/s.json", [&](Json& s) {
      s["effects"]["base_motion"] = {{"csv", csv}};
    });
    Refused("simulate " + scene, {"s.json", "effects.base_motion.csv", "--allow-path"}, secret);
  }
  // Given explicitly on the command line, the folder is allowed: the file is read, and its bad
  // header is quoted as a short excerpt only.
  const std::string scene = Scene("scenes/s.json", [&](Json& s) {
    s["effects"]["base_motion"] = {{"csv", "../private.csv"}};
  });
  Refused("simulate " + scene + " --allow-path DIR", {"line 1", "TOPSECRET_first_line"}, secret);
}

TEST_F(Security, CsvExcerptsAreShortAndEscaped) {
  const std::string header = "t_s\x01" + std::string(100, 'A');
  WriteText(Path("shock.csv"), header + "\n0,1\n1,2\n");
  const std::string scene = Scene("s.json", [](Json& s) {
    s["effects"]["base_motion"] = {{"csv", "shock.csv"}};
  });
  const std::string message = Refused("simulate " + scene, {"line 1", "t_s\\x01AAA"});
  EXPECT_EQ(message.find(std::string(40, 'A')), std::string::npos) << message;
  EXPECT_EQ(message.find('\x01'), std::string::npos);
}

TEST_F(Security, JsonSyntaxErrorsQuoteAShortExcerpt) {
  const std::string secret = "PASSWORD=" + std::string(100, 'S');
  WriteText(Path("secret.txt"), secret + "\n");
  WriteText(Path("study.json"), R"({"name": "s", "scene": "secret.txt", "sweep": {}})");
  Refused("study run DIR/study.json --db DIR/s.db", {"secret.txt", "not valid JSON", "byte"},
          std::string(40, 'S'));
  WriteText(Path("bad.json"), "{\"name\": \"" + std::string(100, 'S') + "\x01\"}");
  Refused("simulate DIR/bad.json", {"bad.json", "not valid JSON", "byte"}, std::string(60, 'S'));
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

TEST_F(Security, AStudysScenePathLeavesTheStudysFolder) {
  // The shipped study names "../scenes/bundle_row.json": a study's author picks its scene.
  const std::string study = kSource + "/studies/bundle_row_truncation.json";
  EXPECT_NO_THROW(ParseSceneStudySpec(ReadJsonFile(study), study));
}

// 2. Nesting depth.

TEST_F(Security, DeepNestingIsRefusedWithItsPath) {
  // Well formed: the parser accepts any depth, the code walking the result would not.
  const std::string deep = std::string(70000, '[') + std::string(70000, ']');
  WriteText(Path("deep.json"), deep);
  WriteText(Path("deep_study.json"),
            R"({"name": "d", "grids": [{"rk": )" + deep + R"(, "rftrunc": [300]}]})");
  WriteText(Path("deep_scene.json"), R"({"name": "d", "solver": {"dt": )" + deep + "}}");
  Refused("study run DIR/deep.json --db DIR/s.db", {"deep.json", "[0][0]", "at most 64"});
  Refused("study run DIR/deep_study.json --db DIR/s.db", {"deep_study.json", "grids[0].rk[0]"});
  Refused("simulate DIR/deep.json", {"deep.json", "at most 64"});
  Refused("simulate DIR/deep_scene.json", {"deep_scene.json", "solver.dt[0][0]", "at most 64"});
  Refused("criteria check --baseline DIR/deep.json --db DIR/s.db", {"deep.json", "at most 64"});
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

TEST_F(Security, NestingUpToTheLimitIsParsed) {
  const int depth = kMaxJsonDepth;
  EXPECT_NO_THROW(ParseJsonText(std::string(depth, '[') + std::string(depth, ']'), "ok.json"));
  EXPECT_THROW(ParseJsonText(std::string(depth + 1, '[') + std::string(depth + 1, ']'), "no.json"),
               InputError);
}

// 3. Repeated keys and names.

TEST_F(Security, RepeatedKeysAreRefusedWithTheirPath) {
  std::string scene = CanonicalScene().dump(2);
  scene.replace(scene.find("\"r_ftrunc\""), 0, "\"r_ftrunc\": 10, ");
  WriteText(Path("dup.json"), scene);
  Refused("simulate DIR/dup.json", {"dup.json", "solver.r_ftrunc", "twice"});
  WriteText(Path("dup_study.json"),
            R"({"name": "a", "grids": [{"rk": 1, "rk": 2, "rftrunc": [300]}]})");
  Refused("study run DIR/dup_study.json --db DIR/s.db", {"dup_study.json", "grids[0].rk", "twice"});
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

TEST_F(Security, RepeatedNamesAreRefusedWithTheirPath) {
  const Json zone = CanonicalScene()["zones"][0];
  Refused(
      "simulate " + Scene("zones.json", [&](Json& s) { s["zones"].push_back(zone); }),
      {"zones[1].name", "tip_spring", "already the name given at zones[0].name", "must be unique"});
  Refused("simulate " +
              Scene("outputs.json",
                    [](Json& s) {
                      s["outputs"]["displacements"].push_back(s["outputs"]["displacements"][0]);
                    }),
          {"outputs.displacements[1].name", "tip", "already the name given at", "must be unique"});
  Refused("simulate " + Scene("listed.json",
                              [](Json& s) {
                                s["outputs"]["contact_forces"] = {"tip_spring", "tip_spring"};
                              }),
          {"outputs.contact_forces[1]", "twice"});
  Json bundle;
  std::ifstream(kSource + "/scenes/bundle_row.json") >> bundle;
  Json heights = bundle;
  heights["bundle"]["wire"]["heights_m"] = {0.5, 0.5};
  WriteText(Path("heights.json"), heights.dump());
  Refused("simulate DIR/heights.json", {"bundle.wire.heights_m", "twice"});
  Json wrapper = bundle;
  wrapper["beams"] = Json::array({CanonicalScene()["beams"][0]});
  wrapper["beams"][0]["name"] = "wrapper";
  WriteText(Path("wrapper.json"), wrapper.dump());
  Refused("simulate DIR/wrapper.json", {"bundle", "\"wrapper\"", "unique"});
}

TEST_F(Security, ControlCharactersInNamesAreRefused) {
  WriteText(Path("nul_study.json"),
            R"({"name": "quick\u0000evil", "grids": [{"rk": 1, "rftrunc": [300]}]})");
  Refused("study run DIR/nul_study.json --db DIR/s.db", {"nul_study.json", "name", "\\x00"});
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
  const std::vector<std::pair<std::function<void(Json&)>, std::string>> cases = {
      {[](Json& s) { s["name"] = std::string("a\x07") + "b"; }, "name"},
      {[](Json& s) { s["beams"][0]["name"] = "be\nam"; }, "beams[0].name"},
      {[](Json& s) { s["zones"][0]["name"] = std::string("tip\0x", 5); }, "zones[0].name"},
      {[](Json& s) { s["outputs"]["displacements"][0]["name"] = "t\x7fip"; },
       "outputs.displacements[0].name"},
      {[](Json& s) { s["description"] = std::string("a\0b", 3); }, "description"},
  };
  for (const auto& [change, path] : cases) {
    const std::string scene = Scene("names.json", change);
    Refused("simulate " + scene, {"names.json", path, "control character"});
  }
  // Descriptions may hold tabs and line breaks.
  const std::string scene = Scene("text.json", [](Json& s) { s["description"] = "a\n\tb\r\n"; });
  EXPECT_NO_THROW(LoadScene(scene));
}

// 4. Meshes beyond the eigenproblem budget.

TEST_F(Security, MeshesBeyondTheBudgetAreRefusedAtOnce) {
  for (const char* elements : {"3000", "10000", "1000000000"}) {
    Refused(std::string("compare --rk 3000 --rftrunc 300 --elements ") + elements,
            {"--elements", elements, "GB", "flops", "at most"});
  }
  Refused("compare --rk 3000 --rftrunc 1e8", {"--rftrunc", "elements", "flops", "at most"});
  Refused("simulate " + Scene("mesh.json", [](Json& s) { s["beams"][0]["elements"] = 10000; }),
          {"beams[0].elements", "10000", "flops", "at most"});
  Refused("simulate " + Scene("many.json",
                              [](Json& s) {
                                for (int i = 1; i < 5; ++i) {  // Four distinct 1000-element beams.
                                  Json b = s["beams"][0];
                                  b["name"] = "b" + std::to_string(i);
                                  b["length_m"] = 1.0 + 0.1 * i;
                                  b["elements"] = 1000;
                                  s["beams"].push_back(b);
                                }
                              }),
          {"many.json", "beams", "distinct beams", "flops"});
  WriteText(Path("mesh_study.json"),
            R"({"name": "m", "grids": [{"rk": 1, "rftrunc": [300], "n_elements": [55, 3000]}]})");
  Refused("study run DIR/mesh_study.json --db DIR/s.db",
          {"mesh_study.json", "grids[0].n_elements", "3000", "flops"});
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

// 4b. One limit on the beams, whichever key makes them, stated with the memory they would take.

TEST_F(Security, BeamsBeyondTheLimitAreRefusedAtTheKeyThatMakesThem) {
  std::ifstream in(kSource + "/scenes/bundle_row.json");
  Json row = Json::parse(in);
  row["bundle"]["pins"] = 9999;  // With the wrapper, the 10000 beams a scene may hold.
  WriteText(Path("most.json"), row.dump());
  EXPECT_NO_THROW(LoadScene(Path("most.json")));
  row["bundle"]["pins"] = 10000;
  WriteText(Path("pins.json"), row.dump());
  Refused("simulate DIR/pins.json --quiet",
          {Path("pins.json") + ": bundle.pins: value 10000 makes 10000 pins, 10001 beams with the "
                               "wrapper: a scene may hold at most 10000 beams; 10001 beams and "
                               "70007 contact zones would take about 0.087 GB of memory"});
  row["bundle"]["pins"] = 2000000000;  // Refused before a pin is placed.
  WriteText(Path("huge.json"), row.dump());
  Refused("simulate DIR/huge.json --quiet",
          {"bundle.pins: value 2000000000 makes 2000000000 pins", "about 1.7e+04 GB"});
  Json hex = Json::parse(std::ifstream(kSource + "/scenes/bundle_hex.json"));
  hex["bundle"]["rings"] = 50;  // 7651 pins, with the 2349 beams below and the wrapper 10001.
  for (int i = 0; i < 2349; ++i) {
    Json beam = CanonicalScene()["beams"][0];
    beam["name"] = "extra_" + std::to_string(i);
    hex["beams"].push_back(beam);
  }
  WriteText(Path("rings.json"), hex.dump());
  Refused("simulate DIR/rings.json --quiet",
          {"bundle.rings: value 50 makes 7651 pins, 10001 beams with the wrapper and the 2349 of "
           "\"beams\": a scene may hold at most 10000 beams"});
}

// 5. The fuzzers' seeds reach the limits through the parse path the fuzz targets use.

TEST_F(Security, FuzzSeedsHitTheLimits) {
  for (const char* seed : {"scene/deep_nesting.json", "scene/duplicate_key.json",
                           "study/deep_nesting.json", "study/duplicate_key.json"}) {
    const std::string path = kSource + "/fuzz/corpus/" + seed;
    ASSERT_TRUE(std::filesystem::is_regular_file(path)) << path;
    try {
      ParseJsonText(testing::ReadBytes(path), path);
      ADD_FAILURE() << seed << " was parsed";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_TRUE(m.find("at most 64") != std::string::npos || m.find("twice") != std::string::npos)
          << m;
    }
  }
}

// 6. Messages that name what was given: numbers beyond a double, values on the edge of an open
// interval, whole numbers beyond their type, a window inside one step, advice blamed on the
// file it came from, a tangential spring too soft to slide, a database on a read-only mount.

TEST_F(Security, JsonNumberBeyondADoubleIsNamedWithItsFileLineAndKey) {
  std::string text = CanonicalScene().dump(2);
  const std::size_t key = text.find("\"gap_m\": ");
  ASSERT_NE(key, std::string::npos);
  const std::size_t value = key + std::string("\"gap_m\": ").size();
  text.replace(value, text.find_first_of(",\n}", value) - value, "1e400");
  const std::string line =
      "line " + std::to_string(1 + std::count(text.begin(), text.begin() + value, '\n'));
  WriteText(Path("huge.json"), text);
  Refused("simulate DIR/huge.json", {"huge.json", "gap_m", line, "the number 1e400",
                                     "beyond a double's range", "at most about 1.8e308"});
  try {
    ParseJsonText("{\"a\": [1,\n  -1e400]}", "f.json");
    ADD_FAILURE() << "parsed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.json: a[1] (line 2): the number -1e400"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(Security, QuantileOfOneIsRefusedAsOutsideTheOpenInterval) {
  const std::string study = kSource + "/studies/bundle_hex_ensemble.json";
  const std::string criteria = kSource + "/studies/baselines/paper_fig4.json";
  for (const std::string& args :
       {"check-advice " + study + " --criteria " + criteria + " --db DIR/s.db --quantile 1",
        std::string("sizing --db DIR/s.db --quantile 1"),
        std::string("sizing --db DIR/s.db --confidence 1")}) {
    const std::string out = Refused(args, {"value 1 must be greater than 0 and less than 1"});
    EXPECT_EQ(out.find("<= 1"), std::string::npos) << out;
  }
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

TEST_F(Security, WholeNumberFlagsNameTheValueAsGiven) {
  const std::string id_range = "must be a whole number from 1 to 9223372036854775807";
  std::string out = Refused("export reference --point -1 --out DIR/r.csv --db DIR/s.db",
                            {"--point", "value -1 " + id_range});
  EXPECT_LT(out.size(), 200u) << out;
  Refused("export point --id 99999999999999999999 --out DIR/p --db DIR/s.db",
          {"--id", "value 99999999999999999999 " + id_range});
  Refused("export point --id 0x10 --out DIR/p --db DIR/s.db", {"--id", "value '0x10' " + id_range});
  out = Refused(
      "compare --rk 100 --rftrunc 10 --elements 99999999999",
      {"--elements", "value 99999999999 is out of range: must be a whole number from 0 to 1500"});
  EXPECT_EQ(out.find("Could not convert"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(Path("p")));
}

// A leading zero is decimal: 013 is thirteen (refused above 12), not octal eleven.
TEST_F(Security, WholeNumberFlagsWithALeadingZeroAreDecimal) {
  const std::string study = kSource + "/studies/bundle_hex_ensemble.json";
  Refused("check-advice " + study + " --db DIR/s.db --max-rungs 013",
          {"--max-rungs", "value 013 must be a whole number from 3 to 12"});
  Refused("study run " + study + " --db DIR/s.db --jobs 02000",
          {"--jobs", "value 02000 must be a whole number from 1 to 1024"});
  Refused("check-advice " + study + " --db DIR/s.db --members 0x10",
          {"--members", "value '0x10' must be a whole number from 1 to 100000"});
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

TEST_F(Security, CompareWindowInsideOneStepIsRefusedWithTheStep) {
  const std::string out = Refused("compare --rk 100 --rftrunc 10 --window 1e-7 --out DIR/c",
                                  {"--window", "1e-07 s window is shorter than one time step",
                                   "--dt-factor 0.1 of the sharp bound", "at least 0.0001125"});
  EXPECT_EQ(out.find("dt used"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(Path("c")));
}

TEST_F(Security, AdviceTooSmallToCheckBelowItBlamesTheCriteriaFile) {
  Json criteria = Json::parse(testing::ReadBytes(kSource + "/studies/baselines/modes_fig4.json"));
  criteria["fit"]["p"] = -10;
  WriteText(Path("steep.json"), criteria.dump(2));
  const std::string out = Refused(
      "check-advice " + kSource +
          "/studies/bundle_hex_ensemble.json --criteria "
          "DIR/steep.json --db DIR/s.db --write-study DIR/ladder.json",
      {"steep.json: fit.c = ", "fit.p = -10", "R_ftrunc 1.001", "lowest rung", "at least 3"});
  EXPECT_EQ(out.find("bundle_hex_7.json:"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(Path("ladder.json")));
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
}

TEST_F(Security, TangentialSpringTooSoftToSlideIsRefused) {
  const std::string path = kSource + "/scenes/bundle_hex_7_friction.json";
  Json scene = Json::parse(testing::ReadBytes(path));
  scene["bundle"]["wire"]["friction"]["tangential_stiffness_n_per_m"] = 1e-300;
  try {
    ParseScene(scene, path);
    ADD_FAILURE() << "a tangential stiffness of 1e-300 N/m was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    for (const char* part : {"bundle.wire.friction.tangential_stiffness_n_per_m", "1e-300",
                             "normal stiffness 1000000.0", "never slide", "at least 1.0"}) {
      EXPECT_NE(m.find(part), std::string::npos) << part << "\n" << m;
    }
  }
  // The shipped law, k_t equal to the normal stiffness, is kept.
  EXPECT_NO_THROW(ParseScene(Json::parse(testing::ReadBytes(path)), path));
}

// Runs shockmap with `args` in a child whose own mount namespace has `folder` bind-mounted
// read-only onto itself, its output in `output`; nullopt where the system allows no mount
// namespace (no CAP_SYS_ADMIN).
std::optional<Outcome> RunWithReadOnlyFolder(const std::filesystem::path& folder,
                                             const std::filesystem::path& output,
                                             std::vector<std::string> args) {
  constexpr int kNoNamespace = 77;
  const pid_t pid = fork();
  if (pid == 0) {
    const char* dir = folder.c_str();
    if (unshare(CLONE_NEWNS) != 0 || mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) ||
        mount(dir, dir, nullptr, MS_BIND, nullptr) != 0 ||
        mount(nullptr, dir, nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY, nullptr) != 0) {
      _exit(kNoNamespace);
    }
    const int fd = open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<char*> argv = {const_cast<char*>(SHOCKMAP_BIN)};
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(SHOCKMAP_BIN, argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == kNoNamespace) return std::nullopt;
  return Outcome{WIFEXITED(status) ? WEXITSTATUS(status) : -1, testing::ReadBytes(output)};
}

TEST_F(Security, StudyRunOnAReadOnlyMountSaysSoAndWhere) {
  const std::string study = Path("small.json");
  WriteText(study, R"({"name": "small", "scoring": {"window_s": 0.02},
                       "grids": [{"rk": [10], "rftrunc": [10]}]})");
  const std::filesystem::path ro = dir_ / "ro";
  std::filesystem::create_directories(ro);
  const auto fresh = RunWithReadOnlyFolder(
      ro, dir_ / "out.txt", {"study", "run", study, "--db", (ro / "s.db").string(), "--quiet"});
  if (!fresh) GTEST_SKIP() << "no mount namespace here: a read-only mount cannot be made";
  EXPECT_EQ(fresh->exit_code, 2) << fresh->output;
  for (const std::string& part :
       {"cannot write database " + (ro / "s.db").string(), "its folder " + ro.string(),
        std::string("read-only file system")}) {
    EXPECT_NE(fresh->output.find(part), std::string::npos) << part << "\n" << fresh->output;
  }
  // A database already there: the same words, and its bytes as they were.
  const std::string db = (ro / "s.db").string();
  ASSERT_EQ(testing::RunShockmap("study run " + study + " --db " + db + " --quiet").exit_code, 0);
  const std::string before = testing::ReadBytes(db);
  const auto stored =
      RunWithReadOnlyFolder(ro, dir_ / "out.txt", {"study", "run", study, "--db", db, "--quiet"});
  ASSERT_TRUE(stored);
  EXPECT_EQ(stored->exit_code, 2) << stored->output;
  EXPECT_NE(stored->output.find("read-only file system"), std::string::npos) << stored->output;
  EXPECT_EQ(testing::ReadBytes(db), before);
}

}  // namespace
}  // namespace shockmap

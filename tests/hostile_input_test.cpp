// Hostile input at every entry point of the command line (flags, study files, scene files, CSV
// tables, the database path): each class is refused with exit code 2 and a message naming the
// flag, file or key, before anything is allocated or stored. The messages are printed, as the
// table of issue 6's closing note quotes them.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::RunShockmap;
using testing::WriteText;

struct Hostile {
  std::string what;
  std::string args;   // After "shockmap"; DIR is replaced by the test's directory.
  std::string named;  // The message must contain this.
};

class HostileInput : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    std::filesystem::create_directories(dir_ / "a_directory.json");
    WriteText(Path("huge_grid.json"),
              R"({"name": "huge", "grids": [{"rk": {"logspace": [0, 6, 1000000000]}, )"
              R"("rftrunc": [300]}]})");
    WriteText(Path("huge_reference.json"),
              R"({"name": "r", "grids": [{"rk": [1e3, 1e12], "rftrunc": [300]}]})");
    WriteText(Path("nan.json"), R"({"name": "x", "grids": [{"rk": NaN, "rftrunc": [300]}]})");
    WriteText(Path("huge_bundle.json"), std::string(R"({"name": "b", "bundle": {"layout": "hex",
      "rings": 50, "pin_pitch_m": 0.007,
      "pin": {"length_m": 2, "ei_n_m2": 5, "rho_a_kg_per_m": 0.15},
      "wrapper": {"length_m": 2, "ei_n_m2": 4e5, "rho_a_kg_per_m": 9.5},
      "wire": {"heights_m": {"linspace": [0.1, 1.9, 10000]}, "stiffness_n_per_m": 1e6,
               "gap_m": 0}}, "solver": {"end_time_s": 1}})"));
    WriteText(Path("endless.json"),
              R"({"name": "e", "beams": [{"name": "b", "length_m": 1, "ei_n_m2": 1.5e5,
                  "rho_a_kg_per_m": 127}], "solver": {"end_time_s": 1e4, "dt": {"seconds": 1e-8}}})");
  }

  void Check(const std::vector<Hostile>& cases) {
    for (Hostile c : cases) {
      for (std::string* s : {&c.args, &c.named}) {
        for (auto at = s->find("DIR"); at != std::string::npos; at = s->find("DIR"))
          s->replace(at, 3, dir_.string());
        for (auto at = s->find("SRC"); at != std::string::npos; at = s->find("SRC"))
          s->replace(at, 3, SHOCKMAP_SOURCE_DIR);
      }
      const auto r = RunShockmap(c.args);
      EXPECT_EQ(r.exit_code, 2) << c.what << ": shockmap " << c.args << "\n" << r.output;
      EXPECT_NE(r.output.find(c.named), std::string::npos) << c.what << "\n" << r.output;
      std::string first_line = r.output.substr(0, r.output.find('\n'));
      std::printf("[hostile] %s | %s\n", c.what.c_str(), first_line.c_str());
    }
  }
};

TEST_F(HostileInput, CommandLineFlags) {
  Check({
      {"NaN value", "compare --rk nan --rftrunc 300", "--rk"},
      {"negative value", "compare --rk -3000 --rftrunc 300", "--rk"},
      {"zero value", "compare --rk 3000 --rftrunc 300 --window 0", "--window"},
      {"infinite value", "compare --rk 3000 --rftrunc inf", "--rftrunc"},
      {"not a number", "compare --rk three --rftrunc 300", "--rk"},
      {"1e12 steps", "compare --rk 3000 --rftrunc 300 --dt 1e-13", "--dt"},
      {"absurd mesh", "compare --rk 3000 --rftrunc 300 --elements 1000000000", "--elements"},
      {"reference of 19 000 modes", "compare --rk 3000 --rftrunc 300 --rfref 1e9",
       "--rfref: 1e+09"},
      {"reference over 10 min", "compare --rk 3000 --rftrunc 300 --window 600", "--window"},
      {"unknown flag", "compare --rk 3000 --rftrunc 300 --turbo", "--turbo"},
      {"unknown command", "simulte x.json", "simulte"},
      {"no command", "", "shockmap --help"},
      {"missing argument", "simulate", "scene"},
      {"zero workers", "study run SRC/studies/quick.json --jobs 0", "--jobs"},
      {"unknown format", "query \"SELECT 1\" --format xml", "--format"},
  });
}

TEST_F(HostileInput, FilesAndPaths) {
  Check({
      {"study file missing", "study run DIR/none.json --db DIR/s.db", "DIR/none.json"},
      {"study file is a directory", "study run DIR/a_directory.json --db DIR/s.db",
       "not a regular file"},
      {"study file is a device", "study run /dev/zero --db DIR/s.db", "/dev/zero"},
      {"study grid of 1e9 points", "study run DIR/huge_grid.json --db DIR/s.db", "grids[0]"},
      {"NaN in a study file", "study run DIR/nan.json --db DIR/s.db", "nan.json"},
      {"study reference at R_fref 3e7", "study run DIR/huge_reference.json --db DIR/s.db",
       "scoring.reference"},
      {"scene file is a directory", "simulate DIR/a_directory.json", "directory"},
      {"bundle of 1e8 zones", "simulate DIR/huge_bundle.json", "at most 1000000"},
      {"scene of 1e12 steps", "simulate DIR/endless.json", "solver.dt"},
      {"database in a missing folder", "study run SRC/studies/quick.json --db DIR/no/such/s.db",
       "DIR/no/such/s.db"},
      {"database is a directory", "study run SRC/studies/quick.json --db DIR/a_directory.json",
       "a_directory.json"},
      {"database not writable", "study run SRC/studies/quick.json --db /proc/s.db", "/proc/s.db"},
      {"query on a missing database", "query \"SELECT 1\" --db DIR/none.db", "DIR/none.db"},
      {"output folder not writable", "compare --rk 3000 --rftrunc 300 --out /proc/out",
       "/proc/out"},
  });
  // Nothing was created by any refusal.
  EXPECT_FALSE(std::filesystem::exists(Path("s.db")));
  EXPECT_FALSE(std::filesystem::exists(Path("none.db")));
  EXPECT_FALSE(std::filesystem::exists(Path("no")));
}

}  // namespace
}  // namespace shockmap

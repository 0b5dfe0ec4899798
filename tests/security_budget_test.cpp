// The largest meshes the eigenproblem budget accepts finish within a minute of CPU time (the
// machine may be shared, so wall time would measure the neighbours),
// on the command line: the paper's beam with 1500 elements, and a scene beam of 1500 elements
// (its basis is solved once). Slow by design: label `long`.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::RunShockmap;

class LargestAcceptedMesh : public testing::TempDirTest {
 protected:
  // Runs `args`, expecting success, and returns the CPU time it took in seconds.
  static double Seconds(const std::string& args) {
    const double before = ChildrenCpuSeconds();
    const auto r = RunShockmap(args);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.output;
    return ChildrenCpuSeconds() - before;
  }

  static double ChildrenCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
};

TEST_F(LargestAcceptedMesh, CompareFinishes) {
  const double s = Seconds("compare --rk 3000 --rftrunc 300 --elements 1500 --window 0.01");
  std::printf("[budget] compare --elements 1500: %.1f s CPU\n", s);
  EXPECT_LT(s, 60.0);
  EXPECT_EQ(RunShockmap("compare --rk 3000 --rftrunc 300 --elements 1501").exit_code, 2);
}

TEST_F(LargestAcceptedMesh, SceneFinishes) {
  nlohmann::json scene;
  std::ifstream(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json") >> scene;
  scene["beams"][0]["elements"] = 1500;
  scene["solver"]["end_time_s"] = 0.001;
  testing::WriteText(Path("scene.json"), scene.dump());
  const double s = Seconds("simulate " + Path("scene.json"));
  std::printf("[budget] simulate, one beam of 1500 elements: %.1f s CPU\n", s);
  EXPECT_LT(s, 60.0);
  scene["beams"][0]["elements"] = 1501;
  testing::WriteText(Path("scene.json"), scene.dump());
  EXPECT_EQ(RunShockmap("simulate " + Path("scene.json")).exit_code, 2);
}

}  // namespace
}  // namespace shockmap

// The report a user opens: every figure of the HTML page loads in a real browser (Debian's
// headless Chromium), and the other views of a study answer.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "tests/run_command.h"

namespace shockmap {
namespace {

using testing::RunShockmap;

class QuickStudyViews : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::filesystem::temp_directory_path() / ("shockmap_report_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    db_ = (dir_ / "study.db").string();
    const auto run = RunShockmap("study run " + std::string(SHOCKMAP_SOURCE_DIR) +
                                 "/studies/quick.json --db " + db_ + " --quiet");
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }

  static inline std::filesystem::path dir_;
  static inline std::string db_;
};

TEST_F(QuickStudyViews, ReportImagesAllLoadInHeadlessChromium) {
  const auto out = dir_ / "report";
  const auto report = RunShockmap("report --db " + db_ + " --out " + out.string());
  ASSERT_EQ(report.exit_code, 0) << report.output;
  const auto page = out / "report.html";
  ASSERT_TRUE(std::filesystem::exists(page));
  // Flags as the machine's own Chromium check uses them: no sandbox as root, no network.
  const std::string chromium =
      "chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir=" +
      (dir_ / "chromium").string() + " --virtual-time-budget=10000 --dump-dom file://" +
      page.string() + " 2>/dev/null";
  FILE* pipe = popen(chromium.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string dom;
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) dom += buffer;
  ASSERT_EQ(pclose(pipe), 0) << "chromium did not run (is Debian's chromium installed?)";
  // Five maps, Fig. 4 and the cost front.
  EXPECT_NE(dom.find("data-images-loaded=\"7/7\""), std::string::npos)
      << dom.substr(0, dom.find("<h1>"));
}

TEST_F(QuickStudyViews, Fig4CostAndAdviceAnswer) {
  const auto fig4 = RunShockmap("plot fig4 --db " + db_ + " --out " + (dir_ / "fig4.svg").string());
  ASSERT_EQ(fig4.exit_code, 0) << fig4.output;
  EXPECT_GT(std::filesystem::file_size(dir_ / "fig4.svg"), 1000u);

  const auto cost =
      RunShockmap("cost --db " + db_ + " --rk 3000 --out " + (dir_ / "cost.png").string());
  ASSERT_EQ(cost.exit_code, 0) << cost.output;
  EXPECT_NE(cost.output.find("R_k = 3162"), std::string::npos) << cost.output;
  EXPECT_NE(cost.output.find("*"), std::string::npos) << "no Pareto point marked";

  const auto inside = RunShockmap("advise --db " + db_ + " --rk 5000");
  ASSERT_EQ(inside.exit_code, 0) << inside.output;
  EXPECT_EQ(inside.output.find("outside the studied range"), std::string::npos) << inside.output;
  EXPECT_NE(inside.output.find("nearest stored points"), std::string::npos) << inside.output;
  const auto outside = RunShockmap("advise --db " + db_ + " --rk 1e7");
  ASSERT_EQ(outside.exit_code, 0) << outside.output;
  EXPECT_NE(outside.output.find("outside the studied range"), std::string::npos) << outside.output;

  const auto bad = RunShockmap("map --db " + db_ + " --metric speed");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  const auto bad_out = RunShockmap("map --db " + db_ + " --out " + (dir_ / "map.jpg").string());
  EXPECT_EQ(bad_out.exit_code, 2) << bad_out.output;
  EXPECT_NE(bad_out.output.find(".png or .svg"), std::string::npos) << bad_out.output;
}

}  // namespace
}  // namespace shockmap

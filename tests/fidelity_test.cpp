// The mode-resolution studies against their shipped criteria baselines (docs/fidelity.md):
// the Err and SRf boundary of the explicit modal scheme at one point per retained-mode count,
// and with the first shock's peak force (the criteria a scene's zones are advised with).
// Long: two studies of 1000 points each.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/run_command.h"

namespace shockmap {
namespace {

using testing::RunShockmap;

std::string Source(const std::string& relative) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
}

class ModeResolutionStudies : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    db_ = (std::filesystem::temp_directory_path() /
           ("shockmap_fidelity_" + std::to_string(getpid()) + ".db"))
              .string();
    std::filesystem::remove(db_);
    for (const char* study : {"studies/modes_fig4.json", "studies/modes_fig4_first_contact.json"}) {
      const auto run = RunShockmap("study run " + Source(study) + " --db " + db_ + " --quiet");
      ASSERT_EQ(run.exit_code, 0) << run.output;
    }
  }
  static void TearDownTestSuite() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db_ + suffix);
  }
  static inline std::string db_;
};

// One test, so that CTest (one process per test) runs the two studies once.
TEST_F(ModeResolutionStudies, AgreeWithTheirBaselinesAtExactModeCounts) {
  const auto check = RunShockmap("criteria check modes_fig4 --db " + db_ + " --baseline " +
                                 Source("studies/baselines/modes_fig4.json"));
  EXPECT_EQ(check.exit_code, 0) << check.output;
  const auto peak_force = RunShockmap("criteria check modes_fig4 --db " + db_ + " --baseline " +
                                      Source("studies/baselines/modes_fig4_peak_force.json"));
  EXPECT_EQ(peak_force.exit_code, 0) << peak_force.output;

  const auto srf =
      RunShockmap("criteria check modes_fig4_first_contact --db " + db_ + " --baseline " +
                  Source("studies/baselines/modes_fig4_first_contact_srf.json"));
  EXPECT_EQ(srf.exit_code, 0) << srf.output;

  // The n-th truncation of each R_k keeps n modes: no point with another count.
  const auto wrong = RunShockmap(
      "query --db " + db_ +
      " --format csv \"SELECT count(*) AS wrong FROM results p WHERE study = 'modes_fig4' AND "
      "n_modes != (SELECT count(*) FROM results q WHERE q.study = 'modes_fig4' AND q.r_k = "
      "p.r_k AND q.r_ftrunc <= p.r_ftrunc)\"");
  ASSERT_EQ(wrong.exit_code, 0) << wrong.output;
  EXPECT_EQ(wrong.output, "wrong\n0\n") << wrong.output;
}

}  // namespace
}  // namespace shockmap

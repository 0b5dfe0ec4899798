// What the reference of docs/physics.md §2 changed in the quick study (docs/fidelity.md, "The
// quick study under the new reference"; `ctest -L long -R QuickStudyReferenceChange -V`
// prints the table). For every R_k of studies/quick.json: how many of its 28 points moved from
// the scores of the earlier reference and eigensolution
// (tests/data/quick_results_earlier_reference.txt, as the code of commit 4816a50 stored them,
// the statuses before 'unstable'), by how much,
// and whether the stored Err and SRf lie within the spread of the point's scores under
// rounding-level perturbations (ScoreUnderPerturbations); and how far the study's reference is
// from one at 9 times its truncation, which its estimate must bound.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "compare/reference_estimate.h"
#include "compare/reference_run.h"
#include "compare/score_spread.h"
#include "engine/study_run.h"
#include "specs/study_file.h"
#include "tests/database_rows.h"

namespace shockmap {
namespace {

// Moves below these are the math library's last digits (tests/refactor_parity_test.cpp).
constexpr double kErrMoved = 1e-10;
constexpr double kSrfMoved = 1e-10;

struct StoredPoint {
  double r_k = 0.0, r_ftrunc = 0.0, dt_factor = 0.0;
  std::string status;
  double err = NAN, srf = NAN;
};

double Number(const std::string& field) { return field == "NULL" ? NAN : std::stod(field); }

// study|point_id|r_k|r_ftrunc|scheme|status|err|srf|... (the fixture's columns), in point order.
std::vector<StoredPoint> Stored(const std::vector<std::string>& rows) {
  std::vector<StoredPoint> points;
  for (const std::string& row : rows) {
    const auto f = testing::RowFields(row);
    points.push_back({std::stod(f[2]), std::stod(f[3]), 0.0, f[5], Number(f[6]), Number(f[7])});
  }
  return points;
}

std::vector<std::string> Lines(const std::string& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

struct RkRow {
  int points = 0, scored_both = 0, moved = 0, old_err_in_spread = 0, old_srf_in_spread = 0;
  int new_err_in_old_band = 0;
  double max_err_move = 0.0, max_srf_move = 0.0, max_err_width = 0.0, max_srf_width = 0.0;
};

TEST(QuickStudyReferenceChange, MovedScoresAgainstTheirSpreadAndTheReferenceAgainst9RFref) {
  const std::string db = (std::filesystem::temp_directory_path() /
                          ("shockmap_reference_change_" + std::to_string(getpid()) + ".db"))
                             .string();
  std::filesystem::remove(db);
  const StudySpec spec = LoadStudySpec(std::string(SHOCKMAP_SOURCE_DIR) + "/studies/quick.json");
  StudyRunOptions options;
  options.database_path = db;
  options.jobs = 2;
  options.progress = false;
  RunStudy(StudyFile(spec), options);
  std::vector<StoredPoint> now = Stored(testing::Rows(
      db,
      "SELECT study, point_id, quote(r_k), quote(r_ftrunc), scheme, status, quote(err), "
      "quote(srf) FROM results ORDER BY study, point_id"));
  const std::vector<std::string> factors =
      testing::Rows(db, "SELECT quote(dt_factor) FROM results ORDER BY study, point_id");
  for (std::size_t i = 0; i < now.size(); ++i) now[i].dt_factor = std::stod(factors[i]);
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db + suffix);
  const std::vector<StoredPoint> old = Stored(
      Lines(std::string(SHOCKMAP_SOURCE_DIR) + "/tests/data/quick_results_earlier_reference.txt"));
  ASSERT_EQ(now.size(), old.size());

  std::map<double, RkRow> rows;
  for (std::size_t i = 0; i < now.size(); ++i) {
    RkRow& row = rows[now[i].r_k];
    ++row.points;
    const StoredPoint &a = now[i], &b = old[i];
    ASSERT_EQ(a.r_ftrunc, b.r_ftrunc);
    if (std::isnan(a.err) || std::isnan(b.err) || std::isnan(a.srf) || std::isnan(b.srf)) continue;
    ++row.scored_both;
    const double err_move = std::abs(a.err - b.err);
    const double srf_move = std::abs(a.srf - b.srf) / std::abs(b.srf);
    if (err_move <= kErrMoved && srf_move <= kSrfMoved) continue;
    ++row.moved;
    row.max_err_move = std::max(row.max_err_move, err_move);
    row.max_srf_move = std::max(row.max_srf_move, srf_move);
    StudyPoint point;
    point.r_k = a.r_k;
    point.r_ftrunc = a.r_ftrunc;
    point.dt.rule = DtRule::kSharp;
    point.dt.factor = a.dt_factor;
    point.window_s = spec.scoring.window_s;
    const ScoreSpread s = ScoreUnderPerturbations(ProblemOf(spec, point), OptionsOf(spec, point));
    row.max_err_width = std::max(row.max_err_width, s.Width("err"));
    row.max_srf_width = std::max(row.max_srf_width, s.Width("srf"));
    auto within = [&s](std::string_view score, double v) {
      return s.low[score] && v >= *s.low[score] && v <= *s.high[score];
    };
    row.old_err_in_spread += within("err", b.err);
    row.old_srf_in_spread += within("srf", b.srf);
    // The new score within the old one plus or minus the spread's width.
    row.new_err_in_old_band += err_move <= s.Width("err");
  }

  std::printf(
      "| R_k | points scored | moved | max |dErr| | max |dSRf|/SRf | max Err spread | "
      "max SRf spread | stored Err in spread | stored SRf in spread | |dErr| <= spread | "
      "R_fref | estimate | tip diff from 9 R_fref | impulse diff from 9 R_fref |\n");
  for (const auto& [r_k, row] : rows) {
    StudyPoint point;
    point.r_k = r_k;
    point.r_ftrunc = 100.0;
    point.dt.rule = DtRule::kSharp;
    point.dt.factor = 0.5;
    point.window_s = spec.scoring.window_s;
    const CantileverImpact problem = ProblemOf(spec, point);
    const ComparisonOptions o = OptionsOf(spec, point);
    const ShockSegmentationOptions shocks = o.Shocks(problem.F1Hz());
    ReferenceOptions ro = o.reference;
    if (ro.target_error == 0.0) ro.target_error = o.reference_tolerance;
    const ReferenceRun ref = ComputeReferenceRun(problem, ro, point.window_s, shocks);
    const ReferenceConvergence& c = ref.convergence;
    const ReferenceLevel finest =
        SolveReferenceLevel(problem, ro, 9.0 * c.r_fref, point.window_s, shocks, ref.tip_m.dt_s);
    double diff = 0.0, amplitude = 0.0;
    for (std::size_t k = 0; k < ref.tip_m.values.size(); ++k) {
      diff = std::max(diff, std::abs(finest.histories.tip_m.values[k] - ref.tip_m.values[k]));
      amplitude = std::max(amplitude, std::abs(ref.tip_m.values[k]));
    }
    ASSERT_FALSE(ref.shocks.empty() || finest.shocks.empty());
    const double impulse_diff =
        std::abs(ref.shocks.front().impulse_n_s / finest.shocks.front().impulse_n_s - 1.0);
    std::printf(
        "| %.3g | %d | %d | %.1e | %.1e | %.1e | %.1e | %d | %d | %d | %.0f | %.1e | %.1e | %.1e "
        "|\n",
        r_k, row.scored_both, row.moved, row.max_err_move, row.max_srf_move, row.max_err_width,
        row.max_srf_width, row.old_err_in_spread, row.old_srf_in_spread, row.new_err_in_old_band,
        c.r_fref, c.difference, diff / amplitude, impulse_diff);
    std::printf("  (R_k %.3g: first-shock impulse %.10g N s at R_fref %.0f, %.10g at %.0f)\n", r_k,
                ref.shocks.front().impulse_n_s, c.r_fref, finest.shocks.front().impulse_n_s,
                9.0 * c.r_fref);
    std::fflush(stdout);
    EXPECT_LE(diff / amplitude, c.tip.error) << "R_k " << r_k;
    EXPECT_LE(impulse_diff, c.impulse.error) << "R_k " << r_k;
  }
}

}  // namespace
}  // namespace shockmap

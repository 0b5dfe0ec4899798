// A reference checked against R_fref / 3 alone (scoring.reference.check = "coarser",
// docs/physics.md §2): the two truncations solved, their differences taken as they are, and no
// raise.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "compare/comparison.h"
#include "compare/reference_estimate.h"
#include "compare/reference_run.h"
#include "validation/psd.h"
#include "validation/spectral_error.h"

namespace shockmap {
namespace {

constexpr double kWindow = 0.03;

TEST(CoarserCheck, IsTheDifferenceFromAThirdOfTheTruncationAndNeverRaises) {
  CantileverImpact p;
  p.r_k = 1e5;
  ShockSegmentationOptions shocks;
  shocks.rest_duration_s = 0.1 / p.F1Hz();
  ReferenceOptions o;
  o.r_fref = 3000.0;
  o.target_error = 1e-6;  // Far below the difference: the finer check would raise.
  o.check = ReferenceCheck::kCoarser;
  const ReferenceRun run = ComputeReferenceRun(p, o, kWindow, shocks);
  EXPECT_EQ(run.convergence.r_fref, 3000.0);
  EXPECT_EQ(run.convergence.r_fref_check, 1000.0);
  EXPECT_FALSE(run.convergence.r_fref_needed);

  // The same two truncations solved here, the coarser on the reference's grid.
  const ReferenceLevel level = SolveReferenceLevel(p, o, 3000.0, kWindow, shocks);
  const ReferenceLevel coarser =
      SolveReferenceLevel(p, o, 1000.0, kWindow, shocks, level.histories.tip_m.dt_s);
  ASSERT_EQ(run.tip_m.values, level.histories.tip_m.values);
  double diff = 0.0, amplitude = 0.0;
  for (std::size_t k = 0; k < run.tip_m.values.size(); ++k) {
    diff = std::max(diff, std::abs(run.tip_m.values[k] - coarser.histories.tip_m.values[k]));
    amplitude = std::max(amplitude, std::abs(run.tip_m.values[k]));
  }
  const double impulse = level.shocks.front().impulse_n_s;
  const double impulse_diff = std::abs(coarser.shocks.front().impulse_n_s - impulse) / impulse;
  const double err = SpectralError(coarser.histories.tip_m, run.tip_m, 0.0, kWindow, PsdOptions{});
  const ReferenceConvergence& c = run.convergence;
  EXPECT_DOUBLE_EQ(c.tip.difference, diff / amplitude);
  EXPECT_DOUBLE_EQ(c.impulse.difference, impulse_diff);
  EXPECT_DOUBLE_EQ(c.induced_err.difference, err);
  for (const QuantityConvergence* q : {&c.tip, &c.impulse, &c.induced_err}) {
    EXPECT_FALSE(q->order);
    EXPECT_EQ(q->error, q->difference);  // No factor of safety.
  }
  EXPECT_EQ(c.difference, std::max({c.tip.error, c.impulse.error, c.induced_err.error}));
  EXPECT_GT(c.difference, o.target_error);
  // Its refusal says how it was checked and that it is not raised, not "above R_fref / 3".
  const std::string message = UnconvergedMessage({p, o, kWindow}, c, o.target_error);
  EXPECT_NE(message.find("R_fref = 3000 checked against 1000"), std::string::npos) << message;
  EXPECT_NE(message.find("scoring.reference.check = \"coarser\""), std::string::npos) << message;
  EXPECT_NE(message.find("R_fref above 3000 is needed"), std::string::npos) << message;
}

}  // namespace
}  // namespace shockmap

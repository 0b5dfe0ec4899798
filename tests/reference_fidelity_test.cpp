// The reference over R_k = 1 to 1e8 (17 values) on the Fig. 4 window (0.03 s), as docs/fidelity.md
// tabulates it (`ctest -L long -R ReferenceFidelity -V` prints the table): the truncation the
// shared rule and the adaptive raise reach for a target of 1e-3, its estimated errors (tip,
// first-shock impulse, induced Err) beside its difference from a reference three times finer
// than its check, and CPU times. Where the estimate meets the target with a regular order, it
// must bound that difference.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "compare/reference_estimate.h"
#include "compare/reference_run.h"
#include "core/cpu_timer.h"

namespace shockmap {
namespace {

constexpr double kWindow = 0.03;
constexpr double kTarget = 1e-3;

TEST(ReferenceFidelity, EstimateBoundsTheDifferenceFromAFinerReferenceFromRk1To1e8) {
  std::printf(
      "| R_k | R_fref | order | est. tip | est. impulse | est. Err | finest | tip diff | "
      "impulse diff | CPU (s) | CPU with estimate (s) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 0; i <= 16; ++i) {
    CantileverImpact p;
    p.r_k = std::pow(10.0, 0.5 * i);
    ShockSegmentationOptions shocks;
    shocks.rest_duration_s = 0.1 / p.F1Hz();
    ReferenceOptions o;
    o.r_fref = ReferenceTruncationRule{}.For(p.r_k);
    o.target_error = kTarget;
    const CpuTimer total;
    const ReferenceRun ref = ComputeReferenceRun(p, o, kWindow, shocks);
    const double cpu_with_estimate = total.CpuSeconds();
    const ReferenceConvergence& c = ref.convergence;
    const CpuTimer alone;
    SolveReferenceLevel(p, o, c.r_fref, kWindow, shocks);
    const double cpu = alone.CpuSeconds();
    const double finest_r = 3.0 * c.r_fref_check;
    const ReferenceLevel finest = SolveReferenceLevel(p, o, finest_r, kWindow, shocks);
    const UniformSignal tip = finest.solution.SampleTipDisplacement(ref.tip_m.dt_s, kWindow);
    double diff = 0.0, amplitude = 0.0;
    for (std::size_t k = 0; k < tip.values.size(); ++k) {
      diff = std::max(diff, std::abs(tip.values[k] - ref.tip_m.values[k]));
      amplitude = std::max(amplitude, std::abs(ref.tip_m.values[k]));
    }
    const double tip_diff = diff / amplitude;
    const double impulse_diff =
        std::abs(ref.shocks.front().impulse_n_s / finest.shocks.front().impulse_n_s - 1.0);
    std::printf("| %.3g | %.0f | %s | %.1e | %.1e | %.1e | %.0f | %.1e | %.1e | %.3f | %.2f |\n",
                p.r_k, c.r_fref, c.order ? std::to_string(*c.order).substr(0, 4).c_str() : "–",
                c.tip_error, c.impulse_error, c.induced_err, finest_r, tip_diff, impulse_diff, cpu,
                cpu_with_estimate);
    std::fflush(stdout);
    if (c.difference <= kTarget && c.order && *c.order > 0.5) {
      EXPECT_LE(tip_diff, c.tip_error) << "R_k = " << p.r_k;
      EXPECT_LE(impulse_diff, c.impulse_error) << "R_k = " << p.r_k;
    }
  }
}

}  // namespace
}  // namespace shockmap

// The reference over R_k = 1 to 1e8 (17 values), as docs/fidelity.md tabulates it
// (`ctest -L long -R ReferenceFidelity -V` prints one table row per R_k and window): the
// truncation the shared rule and the adaptive raise reach for a target of 1e-3, each quantity's
// estimate (its difference from 3 R_fref, observed order and grid convergence index) beside its
// difference from the finest reference computed (9 R_fref), that difference over the
// Richardson estimate (the measured justification of the factor of safety 1.25), and CPU times.
// The estimate must bound that difference on every row.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "compare/reference_estimate.h"
#include "compare/reference_run.h"
#include "core/cpu_timer.h"
#include "validation/psd.h"
#include "validation/spectral_error.h"

namespace shockmap {
namespace {

constexpr double kTarget = 1e-3;

struct Row {
  double r_k = 0.0;
  double window_s = 0.0;
};

std::string Order(const QuantityConvergence& q) {
  return q.order ? std::to_string(*q.order).substr(0, 4) : "–";
}

// The difference from the finest over the Richardson estimate (the index without its factor of
// safety): at most 1 where the observed order is asymptotic.
double Effectivity(double difference, const QuantityConvergence& q) {
  const double fs = q.order ? kSafetyFactorObserved : kSafetyFactorUnobserved;
  return q.error > 0.0 ? difference / (q.error / fs) : 0.0;
}

// How far the reference moves when released from (1 +- 1e-12) times the amplitude, scaled back
// (the problem is homogeneous): the largest tip difference over the amplitude and the largest
// first-shock impulse difference, relative. A truncation error below this is not observable.
struct Spread {
  double tip = 0.0;
  double impulse = 0.0;
};

Spread RoundingSpread(const CantileverImpact& problem, const ReferenceOptions& options,
                      double r_fref, double window_s, const ShockSegmentationOptions& shocks,
                      const ReferenceRun& nominal) {
  Spread s;
  for (double perturbation : {1e-12, -1e-12}) {
    CantileverImpact q = problem;
    q.initial_tip_m *= 1.0 + perturbation;
    const ReferenceLevel l =
        SolveReferenceLevel(q, options, r_fref, window_s, shocks, nominal.tip_m.dt_s);
    double diff = 0.0, amplitude = 0.0;
    for (std::size_t k = 0; k < l.histories.tip_m.values.size(); ++k) {
      diff = std::max(diff, std::abs(l.histories.tip_m.values[k] / (1.0 + perturbation) -
                                     nominal.tip_m.values[k]));
      amplitude = std::max(amplitude, std::abs(nominal.tip_m.values[k]));
    }
    s.tip = std::max(s.tip, diff / amplitude);
    s.impulse = std::max(s.impulse, std::abs(l.shocks.front().impulse_n_s / (1.0 + perturbation) /
                                                 nominal.shocks.front().impulse_n_s -
                                             1.0));
  }
  return s;
}

class ReferenceFidelity : public testing::TestWithParam<Row> {};

TEST_P(ReferenceFidelity, EstimateBoundsTheDifferenceFromNineTimesTheTruncation) {
  const Row row = GetParam();
  CantileverImpact p;
  p.r_k = row.r_k;
  ShockSegmentationOptions shocks;
  shocks.rest_duration_s = 0.1 / p.F1Hz();
  ReferenceOptions o;
  o.r_fref = ReferenceTruncationRule{}.For(p.r_k);
  o.target_error = kTarget;
  const CpuTimer total;
  const ReferenceRun ref = ComputeReferenceRun(p, o, row.window_s, shocks);
  const double cpu_with_estimate = total.CpuSeconds();
  const ReferenceConvergence& c = ref.convergence;
  const CpuTimer alone;
  SolveReferenceLevel(p, o, c.r_fref, row.window_s, shocks);
  const double cpu = alone.CpuSeconds();

  const double finest_r = kReferenceCheckRatio * c.r_fref_check;
  const ReferenceLevel finest =
      SolveReferenceLevel(p, o, finest_r, row.window_s, shocks, ref.tip_m.dt_s);
  double diff = 0.0, amplitude = 0.0;
  for (std::size_t k = 0; k < ref.tip_m.values.size(); ++k) {
    diff = std::max(diff, std::abs(finest.histories.tip_m.values[k] - ref.tip_m.values[k]));
    amplitude = std::max(amplitude, std::abs(ref.tip_m.values[k]));
  }
  const double tip_diff = diff / amplitude;
  ASSERT_FALSE(ref.shocks.empty() || finest.shocks.empty());
  const double impulse_diff =
      std::abs(ref.shocks.front().impulse_n_s / finest.shocks.front().impulse_n_s - 1.0);
  const double err_diff =
      SpectralError(ref.tip_m, finest.histories.tip_m, 0.0, row.window_s, PsdOptions{});
  const Spread spread = RoundingSpread(p, o, c.r_fref, row.window_s, shocks, ref);
  std::printf(
      "| %g s | %.3g | %.0f | %.1e / %s / %.1e | %.1e / %s / %.1e | %.1e / %s / %.1e | %.0f | "
      "%.1e | %.1e | %.1e | %.2f / %.2f / %.2f | %.0e / %.0e | %.3f | %.2f |\n",
      row.window_s, p.r_k, c.r_fref, c.tip.difference, Order(c.tip).c_str(), c.tip.error,
      c.impulse.difference, Order(c.impulse).c_str(), c.impulse.error, c.induced_err.difference,
      Order(c.induced_err).c_str(), c.induced_err.error, finest_r, tip_diff, impulse_diff, err_diff,
      Effectivity(tip_diff, c.tip), Effectivity(impulse_diff, c.impulse),
      Effectivity(err_diff, c.induced_err), spread.tip, spread.impulse, cpu, cpu_with_estimate);
  std::fflush(stdout);
  EXPECT_LE(tip_diff, c.tip.error) << "R_k = " << p.r_k;
  EXPECT_LE(impulse_diff, c.impulse.error) << "R_k = " << p.r_k;
  EXPECT_LE(err_diff, c.induced_err.error) << "R_k = " << p.r_k;
}

std::vector<Row> Rows(double window_s, int last) {
  std::vector<Row> rows;
  for (int i = 0; i <= last; ++i) rows.push_back({std::pow(10.0, 0.5 * i), window_s});
  return rows;
}

// "Rk3e5_30ms": R_k = 10^5.5 over 0.03 s.
std::string Name(const testing::TestParamInfo<Row>& info) {
  const long tenths = std::lround(10.0 * std::log10(info.param.r_k));
  return "Rk" + std::string(tenths % 10 == 0 ? "1e" : "3e") + std::to_string(tenths / 10) + "_" +
         std::to_string(std::lround(1000.0 * info.param.window_s)) + "ms";
}

// Over the Fig. 4 window, R_k = 1 to 1e8; over 0.06 s, as far as the reference budget reaches.
INSTANTIATE_TEST_SUITE_P(Fig4Window, ReferenceFidelity, testing::ValuesIn(Rows(0.03, 16)), Name);
INSTANTIATE_TEST_SUITE_P(TwiceTheWindow, ReferenceFidelity, testing::ValuesIn(Rows(0.06, 16)),
                         Name);

}  // namespace
}  // namespace shockmap

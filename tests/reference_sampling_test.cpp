// The reference's sampled histories (docs/performance.md, "References and study points"): the
// rotation recurrence against the exact sum, and the one-pass tip and force histories against
// the exact evaluation at every output sample over the window.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "reference/reference_solver.h"
#include "reference/rotating_modal_sum.h"

namespace shockmap {
namespace {

// 37 damped terms, frequencies spread over four decades (incommensurate), walked over ten
// anchor intervals from an arbitrary start: each sample agrees with the direct sum to rounding.
TEST(RotatingModalSum, AgreesWithTheDirectSumAcrossAnchors) {
  const int n = 37;
  Eigen::VectorXd omega(n), c(n), s(n);
  for (int i = 0; i < n; ++i) {
    omega[i] = 100.0 * std::pow(10.0, 4.0 * i / (n - 1)) * (1.0 + 0.1 * std::sin(i));
    c[i] = std::cos(3.0 * i) / (1 + i);
    s[i] = std::sin(5.0 * i) / (1 + i);
  }
  const double decay = 7.0, step = 1e-6, tau0 = 3.3e-3;
  RotatingModalSum sum(omega, decay, step);
  sum.Start(c, s, tau0);
  const double scale = (c.array().square() + s.array().square()).sqrt().sum();
  double worst = 0.0;
  for (int k = 0; k < 10 * RotatingModalSum::kAnchorEvery; ++k) {
    const double tau = tau0 + k * step;
    const Eigen::ArrayXd w = omega.array() * tau;
    const double exact = std::exp(-decay * tau) * (c.array() * w.cos() + s.array() * w.sin()).sum();
    worst = std::max(worst, std::abs(sum.Next() - exact));
  }
  EXPECT_LT(worst, 1e-13 * scale);
}

// Skips of any length between samples land on the grid tau0 + k step: every sample summed
// after one agrees with the direct sum to rounding.
TEST(RotatingModalSum, SkippedSamplesLandOnTheGrid) {
  const Eigen::VectorXd omega = Eigen::VectorXd::LinSpaced(9, 300.0, 9e5);
  const Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(9, 1.0, -0.5);
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(9, 0.2, 0.7);
  const double decay = 3.0, step = 2e-7, tau0 = 1e-4;
  RotatingModalSum sum(omega, decay, step);
  sum.Start(c, s, tau0);
  long k = 0;
  for (long skip : {0L, 1L, 64L, 511L, 1000L, 3L}) {
    sum.Skip(skip);
    k += skip;
    for (int j = 0; j < 5; ++j, ++k) {
      const double tau = tau0 + static_cast<double>(k) * step;
      const Eigen::ArrayXd w = omega.array() * tau;
      const double exact =
          std::exp(-decay * tau) * (c.array() * w.cos() + s.array() * w.sin()).sum();
      EXPECT_NEAR(sum.Next(), exact, 1e-13) << "sample " << k;
    }
  }
}

// NextInto is Next() called `count` times, bit for bit, whatever the walk's position in its
// anchor interval (after a skip or not) and whatever the count: shorter than an interval, one
// pair of intervals side by side, several pairs and a tail. The walk then goes on alike.
// The walk's arrays start on a cache line, whatever their length, so that no four-lane access
// straddles two lines; a copy (each phase's walk starts from a copied template) is aligned too.
TEST(RotatingModalSum, ArraysStartOnACacheLine) {
  using Lanes = std::vector<double, CacheLineAllocator<double>>;
  for (std::size_t n : {1, 3, 4, 27, 60, 180, 1001}) {
    const Lanes lanes(n, 1.0);
    const Lanes copy = lanes;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(lanes.data()) % 64, 0u) << n;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(copy.data()) % 64, 0u) << n;
    EXPECT_EQ(copy, lanes);
  }
}

TEST(RotatingModalSum, FillingARangeEqualsSamplingOneByOneBitForBit) {
  const int n = 23;  // Not a multiple of the four lanes.
  Eigen::VectorXd omega(n), c(n), s(n);
  for (int i = 0; i < n; ++i) {
    omega[i] = 50.0 * std::pow(10.0, 4.0 * i / (n - 1)) * (1.0 + 0.05 * std::cos(i));
    c[i] = std::sin(2.0 * i + 1.0) / (1 + i);
    s[i] = std::cos(7.0 * i) / (2 + i);
  }
  const long anchor = RotatingModalSum::kAnchorEvery;
  for (const long skip : {0L, 1L, anchor - 3, anchor}) {
    for (const long count : {0L, 5L, anchor, 2 * anchor, 2 * anchor + 7, 5 * anchor + 300}) {
      RotatingModalSum one_by_one(omega, 2.5, 3e-7), filled(omega, 2.5, 3e-7);
      one_by_one.Start(c, s, 1.7e-3);
      filled.Start(c, s, 1.7e-3);
      one_by_one.Skip(skip);
      filled.Skip(skip);
      std::vector<double> out(static_cast<std::size_t>(count) + 3);
      filled.NextInto(out.data(), count);
      for (std::size_t k = static_cast<std::size_t>(count); k < out.size(); ++k) {
        out[k] = filled.Next();
      }
      for (std::size_t k = 0; k < out.size(); ++k) {
        ASSERT_EQ(out[k], one_by_one.Next())
            << "skip " << skip << ", count " << count << ", sample " << k;
      }
    }
  }
}

// Every output sample of the tip and the force over the window, as a study computes them (the
// output step shortened to end on the window), against TipDisplacement and ContactForce at the
// same instants: within 1e-10 of each history's amplitude at the R_k of a Fig. 4 grid's ends
// and of the paper's case, with R_fref = max(2000, 30 sqrt(R_k)).
class ReferenceSamplingTest : public testing::TestWithParam<double> {};

TEST_P(ReferenceSamplingTest, HistoriesAgreeWithTheExactEvaluationAtEverySample) {
  CantileverImpact problem;
  problem.r_k = GetParam();
  const double window = 0.06;
  ReferenceOptions options;
  options.r_fref = std::max(2000.0, 30.0 * std::sqrt(problem.r_k));
  options.end_time_s = window;
  const ReferenceSolution ref = SolveReference(problem, options);
  ASSERT_GT(ref.Summary().n_transitions, 2);
  const double dt = window / std::ceil(window / ref.OutputStep());
  const ReferenceHistories h = ref.SampleHistories(dt, window);
  ASSERT_EQ(h.tip_m.values.size(), static_cast<std::size_t>(std::llround(window / dt)) + 1);
  ASSERT_EQ(h.force_n.values.size(), h.tip_m.values.size());
  double tip_amplitude = 0.0, force_amplitude = 0.0, tip_error = 0.0, force_error = 0.0;
  for (std::size_t i = 0; i < h.tip_m.values.size(); ++i) {
    const double t = h.tip_m.TimeAt(i);
    const double tip = ref.TipDisplacement(t), force = ref.ContactForce(t);
    tip_amplitude = std::max(tip_amplitude, std::abs(tip));
    force_amplitude = std::max(force_amplitude, std::abs(force));
    tip_error = std::max(tip_error, std::abs(h.tip_m.values[i] - tip));
    force_error = std::max(force_error, std::abs(h.force_n.values[i] - force));
  }
  ASSERT_GT(force_amplitude, 0.0);
  EXPECT_LE(tip_error, 1e-10 * tip_amplitude);
  EXPECT_LE(force_error, 1e-10 * force_amplitude);
  EXPECT_EQ(ref.SampleTipDisplacement(dt, window).values, h.tip_m.values);
}

INSTANTIATE_TEST_SUITE_P(Rk, ReferenceSamplingTest, testing::Values(1.0, 3000.0, 1e6),
                         [](const testing::TestParamInfo<double>& info) {
                           return "Rk" + std::to_string(static_cast<long>(info.param));
                         });

}  // namespace
}  // namespace shockmap

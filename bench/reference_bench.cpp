// Cost of the semi-analytical reference of a study point (docs/performance.md, "References and
// study points"): the piecewise-modal solution at R_fref = max(2000, 30 sqrt(R_k)) f1, its error
// estimate at R_fref / 3 and 3 R_fref (no adaptive raise), all sampled at their output steps
// over a 0.06 s window, and the shocks, as a study computes it once per (R_k, window).
//   Reference/R_k   R_k = 1, 10, ..., 1e8;
//                   modes = retained modes of the contact basis, samples = output samples,
//                   s_per_mode_sample = time / (modes * samples)
// The cost growth against R_k is the slope of log(time) against log(R_k): modes grow as
// R_k^(1/4), samples as R_k^(1/2).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "compare/reference_estimate.h"
#include "compare/reference_run.h"
#include "core/cantilever_impact.h"

namespace shockmap {
namespace {

constexpr double kWindowS = 0.06;

void Reference(benchmark::State& state) {
  CantileverImpact problem;
  problem.r_k = std::pow(10.0, static_cast<double>(state.range(0)));
  ReferenceOptions options;
  options.r_fref = std::max(2000.0, 30.0 * std::sqrt(problem.r_k));
  ShockSegmentationOptions shocks;
  shocks.rest_duration_s = 0.1 / problem.F1Hz();
  ReferenceRun run;
  for (auto _ : state) {
    run = ComputeReferenceRun(problem, options, kWindowS, shocks);
    benchmark::DoNotOptimize(run.tip_m.values.back());
  }
  const auto samples = static_cast<double>(run.tip_m.values.size());
  state.counters["rfref"] = options.r_fref;
  state.counters["modes"] = run.summary.n_modes_contact;
  state.counters["transitions"] = run.summary.n_transitions;
  state.counters["samples"] = samples;
  state.counters["s_per_mode_sample"] = benchmark::Counter(
      samples * run.summary.n_modes_contact,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(Reference)->ArgName("log10_rk")->DenseRange(0, 8)->Unit(benchmark::kMillisecond);

// The solution alone, sampled at its output step: R_k = 1e5 and 1e6 at R_fref = 30 sqrt(R_k)
// (9 487 and 30 000) and 1e8 at 100 000, over the Fig. 4 window (0.03 s) and over 0.06 s; `check`
// adds the same problem at R_fref / 3, sampled alike (the work of a reference with a coarser check,
// as the Fig. 4 grid of docs/performance.md's comparison with a JIT-compiled script computes it).
// Only SolveReference and SampleHistories, whose signatures are those of earlier versions, so the
// same source built against an older library times the older method side by side.
void ReferenceSolutionAlone(benchmark::State& state) {
  CantileverImpact problem;
  problem.r_k = std::pow(10.0, static_cast<double>(state.range(0)));
  const double r_fref =
      state.range(0) == 8 ? 100000.0 : std::max(2000.0, 30.0 * std::sqrt(problem.r_k));
  const double window_s = 1e-3 * static_cast<double>(state.range(1));
  std::vector<double> truncations = {r_fref};
  if (state.range(2) != 0) truncations.push_back(r_fref / 3.0);
  for (auto _ : state) {
    for (const double r : truncations) {
      ReferenceOptions options;
      options.r_fref = r;
      options.end_time_s = window_s;
      const ReferenceSolution solution = SolveReference(problem, options);
      const double dt = window_s / std::ceil(window_s / solution.OutputStep());
      const ReferenceHistories h = solution.SampleHistories(dt, window_s);
      benchmark::DoNotOptimize(h.tip_m.values.back());
      state.counters["transitions"] = solution.Summary().n_transitions;
    }
  }
}
BENCHMARK(ReferenceSolutionAlone)
    ->ArgNames({"log10_rk", "window_ms", "check"})
    ->Args({6, 30, 0})
    ->Args({8, 30, 0})
    ->Args({5, 60, 0})
    ->Args({5, 60, 1})
    ->Args({6, 60, 0})
    ->Args({6, 60, 1})
    ->Unit(benchmark::kMillisecond);

// Each truncation of a reference's estimate alone, as ComputeReferenceRun solves it: the
// reference R = 30 sqrt(R_k) f1 over 0.06 s on its own output grid with its force (level 0), and
// R 3^level (R / 9, R / 3, 3 R) for the estimate, solved and sampled on the reference's grid for
// their tips alone (docs/performance.md, "What the reference's estimate needs").
void ReferenceEstimateLevel(benchmark::State& state) {
  CantileverImpact problem;
  problem.r_k = std::pow(10.0, static_cast<double>(state.range(0)));
  ShockSegmentationOptions shocks;
  shocks.rest_duration_s = 0.1 / problem.F1Hz();
  ReferenceOptions options;
  const double r_fref = std::max(2000.0, 30.0 * std::sqrt(problem.r_k));
  const ReferenceLevel reference = SolveReferenceLevel(problem, options, r_fref, kWindowS, shocks);
  const double level = static_cast<double>(state.range(1));
  const double dt_s = level == 0.0 ? 0.0 : reference.histories.tip_m.dt_s;
  for (auto _ : state) {
    const ReferenceLevel l = SolveReferenceLevel(problem, options, r_fref * std::pow(3.0, level),
                                                 kWindowS, shocks, dt_s);
    benchmark::DoNotOptimize(l.histories.tip_m.values.back());
    state.counters["modes"] = l.solution.Summary().n_modes_contact;
    state.counters["transitions"] = l.solution.Summary().n_transitions;
  }
}
BENCHMARK(ReferenceEstimateLevel)
    ->ArgNames({"log10_rk", "level"})
    ->ArgsProduct({{5, 6}, {-2, -1, 0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shockmap

BENCHMARK_MAIN();

// Cost of one run of each solver on the paper's problem at R_k = 3000 over the default window.
//   ExplicitModalRun/R_ftrunc/dt_tenths  the paper's method (the scene model of CanonicalScene),
//                                        dt = (dt_tenths / 10) * sharp bound;
//                                        s_per_unknown_step = time / (modes * steps)
//   ImplicitFullRun/dt_tenths            the full FE model (R_ftrunc = 300 mesh) with average
//                                        acceleration, dt = (dt_tenths / 10) * sharp bound
// Pairs of equal accuracy are read off `shockmap compare` (README, "What accuracy costs").
//   ReferenceRun/R_fref        the piecewise-modal reference (solution + sampling, no check)

#include <benchmark/benchmark.h>

#include "compare/comparison.h"
#include "core/cantilever_impact.h"
#include "core/transient_run.h"
#include "reference/reference_solver.h"

namespace shockmap {
namespace {

const CantileverImpact kProblem{};  // R_k = 3000, the paper's beam.
const ComparisonOptions kDefaults{};

void RunScheme(benchmark::State& state, Scheme scheme, double r_ftrunc, double dt_factor) {
  const ImpactModel model = BuildImpactModel(kProblem, scheme, r_ftrunc);
  TransientOptions options;
  options.end_time_s = kDefaults.window_s;
  options.dt_s = dt_factor * model.bounds.dt_sharp_s;
  options.observed_rows = {model.tip_row};
  options.record_energy = false;
  std::int64_t steps = 0;
  for (auto _ : state) {
    const TransientResult r =
        RunTransient(*model.system, NewmarkParametersOf(scheme), model.x0, model.v0, options);
    if (r.summary.status != RunStatus::kOk) state.SkipWithError(r.summary.message.c_str());
    steps = r.summary.steps_taken;
    benchmark::DoNotOptimize(r.displacement_m[0].values.back());
  }
  state.counters["modes"] = model.n_modes;
  state.counters["unknowns"] = model.n_dofs;
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["s_per_unknown_step"] = benchmark::Counter(
      static_cast<double>(steps) * model.n_dofs,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void ExplicitModalRun(benchmark::State& state) {
  RunScheme(state, Scheme::kExplicitModal, static_cast<double>(state.range(0)),
            static_cast<double>(state.range(1)) / 10.0);
}
BENCHMARK(ExplicitModalRun)
    ->ArgNames({"rftrunc", "dt_tenths"})
    ->Args({10, 1})
    ->Args({100, 1})
    ->Args({300, 1})
    ->Args({300, 10})
    ->Args({1000, 1})
    ->Args({1000, 5})
    ->Args({3000, 1})
    ->Unit(benchmark::kMicrosecond);

void ImplicitFullRun(benchmark::State& state) {
  RunScheme(state, Scheme::kImplicitFull, 300.0, static_cast<double>(state.range(0)) / 10.0);
}
BENCHMARK(ImplicitFullRun)
    ->ArgName("dt_tenths")
    ->Arg(1)
    ->Arg(5)
    ->Arg(10)
    ->Arg(20)
    ->Unit(benchmark::kMillisecond);

void ReferenceRun(benchmark::State& state) {
  ReferenceOptions options = kDefaults.reference;
  options.r_fref = static_cast<double>(state.range(0));
  options.end_time_s = kDefaults.window_s;
  int transitions = 0;
  for (auto _ : state) {
    const ReferenceSolution ref = SolveReference(kProblem, options);
    const UniformSignal tip = ref.SampleTipDisplacement(ref.OutputStep(), options.end_time_s);
    transitions = ref.Summary().n_transitions;
    benchmark::DoNotOptimize(tip.values.back());
  }
  state.counters["transitions"] = transitions;
}
BENCHMARK(ReferenceRun)->ArgName("rfref")->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shockmap

BENCHMARK_MAIN();

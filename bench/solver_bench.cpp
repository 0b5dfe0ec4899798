// Cost of one run of each solver on the paper's problem at R_k = 3000 over the default window.
//   ExplicitModalRun/R_ftrunc/dt_tenths  the paper's method (the scene model of CanonicalScene),
//                                        dt = (dt_tenths / 10) * sharp bound, recording what a
//                                        study's point records (RecordedHistories::kScored);
//                                        s_per_unknown_step = time / (modes * steps)
//   ImplicitFullRun/dt_tenths            the full FE model (R_ftrunc = 300 mesh) with average
//                                        acceleration, dt = (dt_tenths / 10) * sharp bound
// Pairs of equal accuracy are read off `shockmap compare` (README, "What accuracy costs").
//   ReferenceRun/R_fref        the piecewise-modal reference (solution + sampling, no check)
//   CompareCall                `shockmap compare --rk 3000 --rftrunc 300` as the library runs
//                              it (RunComparison: reference, its check, the run, the scores):
//                              the C++ call bench/python_call_overhead.py sets the Python
//                              module's compare() against
//   ExplicitModalStep/R_ftrunc one central-difference step of the paper's method alone (no
//                              recording), the state carried from step to step;
//                              s_per_unknown_step = time / modes
//   IncrementSteps/R_ftrunc    blocks of 64 steps of the same run in increment form
//                              (core/increment_stepper.h), tip and force kept per step as a
//                              run records them; s_per_step = time / 64
//   BundleStep/rings           one central-difference step of scenes/bundle_hex.json with
//                              `rings` rings (8: 217 pins, 4 360 coordinates, 4 915 zones), the
//                              state carried from step to step from the shipped initial state;
//                              s_per_step_per_term = time / (coordinates + zones)

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/comparison.h"
#include "core/cantilever_impact.h"
#include "core/increment_stepper.h"
#include "core/scene_model.h"
#include "core/transient_run.h"
#include "formats/scene_file.h"
#include "reference/reference_solver.h"

namespace shockmap {
namespace {

const CantileverImpact kProblem{};  // R_k = 3000, the paper's beam.
const ComparisonOptions kDefaults{};

void RunScheme(benchmark::State& state, Scheme scheme, double r_ftrunc, double dt_factor) {
  const ImpactModel model = BuildImpactModel(kProblem, scheme, r_ftrunc);
  TransientOptions options = NumericalRun(kDefaults, model, RecordedHistories::kScored);
  options.dt_s = dt_factor * model.bounds.dt_sharp_s;
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

void CompareCall(benchmark::State& state) {
  for (auto _ : state) {
    const ComparisonResult result = RunComparison(kProblem, kDefaults);
    benchmark::DoNotOptimize(result.scores["err"]);
  }
}
BENCHMARK(CompareCall)->Unit(benchmark::kMillisecond);

void ExplicitModalStep(benchmark::State& state) {
  const ImpactModel model =
      BuildImpactModel(kProblem, Scheme::kExplicitModal, static_cast<double>(state.range(0)));
  const double dt = 0.1 * model.bounds.dt_sharp_s;
  NewmarkIntegrator integrator(NewmarkParameters::CentralDifference(), *model.system);
  if (!integrator.Init(model.x0, model.v0)) state.SkipWithError("initial acceleration failed");
  for (auto _ : state) {
    if (!integrator.Step(dt)) state.SkipWithError("step failed");
  }
  benchmark::DoNotOptimize(integrator.X()[0]);
  state.counters["modes"] = model.n_modes;
  state.counters["s_per_unknown_step"] = benchmark::Counter(
      model.n_dofs, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(ExplicitModalStep)->ArgName("rftrunc")->Arg(300)->Arg(3000);

void IncrementSteps(benchmark::State& state) {
  const ImpactModel model =
      BuildImpactModel(kProblem, Scheme::kExplicitModal, static_cast<double>(state.range(0)));
  const std::vector<Eigen::VectorXd> observed{model.tip_row};
  auto stepper = IncrementStepper::For(*model.system, 0.1 * model.bounds.dt_sharp_s, observed);
  if (!stepper) state.SkipWithError("the model does not take the increment form");
  stepper->Init(model.x0, model.v0);
  constexpr int kBlock = 64;
  std::vector<double> tips(kBlock), forces(kBlock);
  for (auto _ : state) stepper->Advance(kBlock, tips.data(), forces.data());
  benchmark::DoNotOptimize(tips.back());
  state.counters["modes"] = model.n_modes;
  state.counters["s_per_step"] = benchmark::Counter(
      kBlock, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(IncrementSteps)->ArgName("rftrunc")->Arg(300)->Arg(3000);

Scene HexBundle(int rings) {
  std::ifstream in(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_hex.json");
  nlohmann::json json = nlohmann::json::parse(in);
  json["bundle"]["rings"] = rings;
  json["outputs"] = nlohmann::json::object();  // Its outputs name pins of the full bundle.
  const auto path = std::filesystem::temp_directory_path() / "shockmap_solver_bench_hex.json";
  std::ofstream(path) << json.dump();
  return LoadScene(path.string());
}

void BundleStep(benchmark::State& state) {
  const Scene scene = HexBundle(static_cast<int>(state.range(0)));
  SceneModel model = BuildSceneModel(scene);
  const double dt = scene.solver.dt.Resolve(model.bounds);
  NewmarkIntegrator integrator(NewmarkParameters::CentralDifference(), *model.system);
  if (!integrator.Init(model.x0, model.v0)) state.SkipWithError("initial acceleration failed");
  for (auto _ : state) {
    if (!integrator.Step(dt)) state.SkipWithError("step failed");
  }
  benchmark::DoNotOptimize(integrator.X()[0]);
  const double terms = model.system->Size() + static_cast<double>(scene.zones.size());
  state.counters["pins"] = static_cast<double>(scene.beams.size() - 1);
  state.counters["coordinates"] = model.system->Size();
  state.counters["zones"] = static_cast<double>(scene.zones.size());
  state.counters["s_per_step_per_term"] = benchmark::Counter(
      terms, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BundleStep)->ArgName("rings")->DenseRange(1, 8)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace shockmap

BENCHMARK_MAIN();

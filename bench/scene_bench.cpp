// Cost of scenes (Google Benchmark; the time of each iteration is the CPU time of the integration
// alone, the modal bases being built once per scene; CPU rather than wall time, so that other
// work on a shared machine does not count):
//   BundleRow/pins        the planar row of scenes/bundle_row.json with `pins` pins, 0.05 s
//   BundleHex/rings       scenes/bundle_hex.json with `rings` rings around the centre pin (1 to 8:
//                         7, 19, 37, 61, 91, 127, 169, 217 pins), 0.02 s
//   BundleHexFriction/rings  BundleHex with Coulomb friction at every wire zone (mu 0.3, k_t the
//                         wire's stiffness): what friction costs per step
//   BundleHexOneSecond    scenes/bundle_hex.json as shipped: 1 s simulated, one iteration
//   Effect/<name>         the paper's cantilever with one effect declared or not: an
//                         undeclared effect must cost nothing
//   PreloadedHexEquilibrium/<steps>  the static equilibrium of scenes/bundle_hex_7.json worn
//                         (wire gaps drawn as bundle_hex_ensemble's end_of_life state) at the
//                         truncations of its advice check's finest rung (x 3): `sparse_steps`
//                         factorizes at every Newton step, `closed_set_first` finds the closed
//                         set in the zones' space and factorizes once (the same vector)
// Counters: cpu_s_per_simulated_s, and ns_per_step_per_term = time / (steps * (coordinates +
// zones)), flat when the cost grows linearly with the size of the scene. The growth exponent of
// bundle time against pins is fitted from BundleHex by scripts/bundle-growth (docs/performance.md).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "core/preload_equilibrium.h"
#include "core/scene_model.h"
#include "core/transient_run.h"
#include "formats/scene_file.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

Json ReadScene(const std::string& name) {
  std::ifstream in(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/" + name + ".json");
  return Json::parse(in);
}

Scene Load(const Json& json) {
  const auto path = std::filesystem::temp_directory_path() / "shockmap_scene_bench.json";
  std::ofstream(path) << json.dump();
  return LoadScene(path.string());
}

void Integrate(benchmark::State& state, const Scene& scene) {
  SceneModel model = BuildSceneModel(scene);
  TransientOptions options;
  options.end_time_s = scene.solver.end_time_s;
  options.dt_s = scene.solver.dt.Resolve(model.bounds);
  options.record_energy = false;
  options.record_contact_forces = false;
  options.track_max_contact_force = scene.outputs.max_contact_force;
  std::int64_t steps = 0, runs = 0;
  double cpu_s = 0.0;
  for (auto _ : state) {
    const TransientResult r = RunTransient(*model.system, NewmarkParameters::CentralDifference(),
                                           model.x0, model.v0, options);
    if (r.summary.status != RunStatus::kOk) state.SkipWithError(r.summary.message.c_str());
    steps = r.summary.steps_taken;
    cpu_s += r.summary.cpu_s;
    ++runs;
    state.SetIterationTime(r.summary.cpu_s);
  }
  const double per_run = cpu_s / static_cast<double>(runs);
  const double terms = model.system->Size() + static_cast<double>(scene.zones.size());
  state.counters["pins"] = static_cast<double>(scene.beams.size() - 1);
  state.counters["coordinates"] = model.system->Size();
  state.counters["zones"] = static_cast<double>(scene.zones.size());
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["cpu_s_per_simulated_s"] = per_run / scene.solver.end_time_s;
  state.counters["ns_per_step_per_term"] = 1e9 * per_run / (static_cast<double>(steps) * terms);
  state.counters["us_per_step"] = 1e6 * per_run / static_cast<double>(steps);
}

void BundleRow(benchmark::State& state) {
  Json json = ReadScene("bundle_row");
  json["bundle"]["pins"] = state.range(0);
  json["outputs"] = {{"max_contact_force", true}};
  json["solver"]["end_time_s"] = 0.05;
  Integrate(state, Load(json));
}
BENCHMARK(BundleRow)->Arg(5)->Arg(9)->Arg(17)->Arg(33)->Arg(65)->UseManualTime()->Unit(
    benchmark::kMillisecond);

void BundleHex(benchmark::State& state) {
  Json json = ReadScene("bundle_hex");
  json["bundle"]["rings"] = state.range(0);
  json["outputs"] = {{"max_contact_force", true}};
  json["solver"]["end_time_s"] = 0.02;
  Integrate(state, Load(json));
}
BENCHMARK(BundleHex)->DenseRange(1, 8)->UseManualTime()->Unit(benchmark::kMillisecond);

void BundleHexFriction(benchmark::State& state) {
  Json json = ReadScene("bundle_hex");
  json["bundle"]["rings"] = state.range(0);
  json["bundle"]["wire"]["friction"] = {{"coefficient", 0.3},
                                        {"tangential_stiffness_n_per_m", 1e6}};
  json["outputs"] = {{"max_contact_force", true}};
  json["solver"]["end_time_s"] = 0.02;
  Integrate(state, Load(json));
}
BENCHMARK(BundleHexFriction)->DenseRange(1, 8)->UseManualTime()->Unit(benchmark::kMillisecond);

void BundleHexOneSecond(benchmark::State& state) {
  Integrate(state, Load(ReadScene("bundle_hex")));
}
BENCHMARK(BundleHexOneSecond)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

// The canonical cantilever, 0.06 s at a fixed dt (the same step for every variant).
void Effect(benchmark::State& state, const std::function<void(Json&)>& declare) {
  Json json = ReadScene("cantilever_spring");
  json.erase("zones");
  json["outputs"] = Json::object();
  json["solver"]["dt"] = {{"seconds", 5e-6}};
  declare(json);
  Integrate(state, Load(json));
}
const Json kClosingZone = {{"name", "spring"},
                           {"beam", "beam"},
                           {"height_m", 1.0},
                           {"normal", {-1, 0}},
                           {"stiffness_n_per_m", 1.35e9}};
BENCHMARK_CAPTURE(Effect, none, [](Json&) {})->UseManualTime();
BENCHMARK_CAPTURE(Effect, zone_never_closing, [](Json& s) {
  Json zone = kClosingZone;
  zone["gap_m"] = 0.5;
  s["zones"] = Json::array({zone});
})->UseManualTime();
BENCHMARK_CAPTURE(Effect, zone_closing, [](Json& s) {
  s["zones"] = Json::array({kClosingZone});
})->UseManualTime();
BENCHMARK_CAPTURE(Effect, contact_damping, [](Json& s) {
  Json zone = kClosingZone;
  zone["damping_n_s_per_m"] = 1e3;
  s["zones"] = Json::array({zone});
})->UseManualTime();
BENCHMARK_CAPTURE(Effect, modal_damping, [](Json& s) {
  s["effects"]["modal_damping"] = {{"ratios", {0.02}}};
})->UseManualTime();
BENCHMARK_CAPTURE(Effect, base_motion, [](Json& s) {
  s["effects"]["base_motion"] = {{"half_sine", {{"amplitude_m_s2", 98.1}, {"duration_s", 0.01}}}};
})->UseManualTime();
BENCHMARK_CAPTURE(Effect, static_force, [](Json& s) {
  s["effects"]["static_forces"] = {{{"beam", "beam"}, {"height_m", 0.5}, {"force_n", 100.0}}};
})->UseManualTime();

void PreloadedHexEquilibrium(benchmark::State& state,
                             Eigen::VectorXd (*equilibrium)(const SceneModalSystem&)) {
  Json json = ReadScene("bundle_hex_7");
  json["bundle"]["pin"]["elements"] = 685;
  json["bundle"]["pin"]["r_ftrunc"] = 47941.97;
  json["bundle"]["wrapper"]["elements"] = 79;
  json["bundle"]["wrapper"]["r_ftrunc"] = 631.795;
  json["bundle"]["wire"]["gap_m"] = {
      {"normal", {{"mean", 1e-5}, {"std", 3e-5}, {"min", -4e-5}, {"seed", 7}}}};
  const Scene scene = Load(json);
  const SceneModel model = BuildSceneModel(scene);
  for (auto _ : state) benchmark::DoNotOptimize(equilibrium(*model.system));
  int preloaded = 0;
  for (const ZoneTerm& z : model.system->Zones()) preloaded += z.gap_m < 0.0;
  state.counters["coordinates"] = model.system->Size();
  state.counters["zones"] = static_cast<double>(model.system->Zones().size());
  state.counters["preloaded_zones"] = preloaded;
}
BENCHMARK_CAPTURE(PreloadedHexEquilibrium, sparse_steps, &PreloadEquilibriumBySparseSteps)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(PreloadedHexEquilibrium, closed_set_first, &PreloadEquilibrium)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shockmap

BENCHMARK_MAIN();

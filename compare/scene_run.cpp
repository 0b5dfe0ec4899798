#include "compare/scene_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "core/scene_model.h"

namespace shockmap {
namespace {

// Histories beyond this are refused before allocating: a record stride was forgotten.
constexpr double kMaxRecordedBytes = 4.0 * 1024 * 1024 * 1024;

void CheckAffordable(const Scene& scene, const TransientOptions& options,
                     const StabilityBounds& bounds) {
  if (std::string error; !options.IsValid(&error)) {
    throw InputError(fmt::format(
        "solver.dt: the time step resolves to {:.4g} s (bounds: paper {:.4g} s, sharp {:.4g} s), "
        "so {}",
        options.dt_s, bounds.dt_paper_s, bounds.dt_sharp_s, error));
  }
  const double records = std::ceil(options.end_time_s / options.dt_s) / options.record_stride + 1;
  double series = 2.0 * static_cast<double>(options.observed_rows.size());
  if (options.record_contact_forces) {
    series += static_cast<double>(
        options.recorded_contacts.empty() ? scene.zones.size() : options.recorded_contacts.size());
  }
  if (options.record_energy) series += 5.0;
  if (records * series * sizeof(double) > kMaxRecordedBytes) {
    throw InputError(fmt::format(
        "outputs: {:.3g} samples of {:g} histories would take {:.1f} GiB (at most {:.0f}); raise "
        "outputs.record_stride or request fewer outputs",
        records, series, records * series * sizeof(double) / (1024.0 * 1024 * 1024),
        kMaxRecordedBytes / (1024.0 * 1024 * 1024)));
  }
}

// The run's options: the scene's end time, its dt resolved against the model's bounds, and
// what its outputs record. Takes the model's observed rows.
TransientOptions RunOptions(const Scene& scene, SceneModel& model) {
  const SceneOutputs& out = scene.outputs;
  TransientOptions options;
  options.end_time_s = scene.solver.end_time_s;
  options.dt_s = scene.solver.dt.Resolve(model.bounds);
  options.record_stride = out.record_stride;
  options.record_energy = out.energies;
  options.record_contact_forces = out.contact_forces || out.shocks;
  options.recorded_contacts = out.contact_force_zones;
  options.track_max_contact_force = out.max_contact_force;
  options.track_impact_statistics = out.impact_statistics;
  options.impact_counting = out.impact_counting;
  options.listed_impact_contacts = out.impact_table_zones;
  options.observed_rows = std::move(model.observed_rows);
  return options;
}

}  // namespace

void CheckSceneAffordable(const Scene& scene, SceneModel model) {
  CheckAffordable(scene, RunOptions(scene, model), model.bounds);
}

SceneRun RunScene(const Scene& scene, std::function<void(double t_s)> on_progress) {
  SceneRun run;
  const auto start = std::chrono::steady_clock::now();
  SceneModel model = BuildSceneModel(scene);
  run.build_wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.coordinates = model.system->Size();
  run.distinct_bases = model.distinct_bases;
  run.modes_per_beam = model.modes_per_beam;
  run.modes_per_structure = model.modes_per_structure;
  run.bounds = model.bounds;

  const SceneOutputs& out = scene.outputs;
  TransientOptions options = RunOptions(scene, model);
  options.on_progress = std::move(on_progress);
  CheckAffordable(scene, options, model.bounds);
  run.result = RunTransient(*model.system, NewmarkParameters::CentralDifference(), model.x0,
                            model.v0, options);

  if (std::ranges::any_of(scene.zones,
                          [](const SceneZone& z) { return z.power_law.has_value(); })) {
    run.reached_bound = CheckReachedBound(*model.system);
  }
  if (out.max_contact_force) run.max_contact_force_n = run.result.max_contact_force_n;
  run.impact_statistics = run.result.impact_statistics;
  if (options.record_contact_forces) {
    run.recorded_zones = out.contact_force_zones;
    if (run.recorded_zones.empty()) {
      for (std::size_t i = 0; i < scene.zones.size(); ++i)
        run.recorded_zones.push_back(static_cast<int>(i));
    }
  }
  if (out.shocks) {
    ShockSegmentationOptions segmentation;
    segmentation.rest_duration_s = out.rest_duration_s;
    for (const UniformSignal& force : run.result.contact_force_n) {
      run.shocks.push_back(
          SegmentShocks(force, segmentation, std::numeric_limits<double>::infinity()));
    }
    // The shocks needed the force histories; they are kept only if requested themselves.
    if (!out.contact_forces) run.result.contact_force_n.clear(), run.recorded_zones.clear();
  }
  return run;
}

}  // namespace shockmap

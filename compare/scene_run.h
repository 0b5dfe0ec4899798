#pragma once
// One simulation of a scene: build its modal model, integrate it explicitly with the declared
// effects only, and keep exactly the outputs the scene requests (docs/physics.md §5,
// docs/architecture.md).

#include <functional>
#include <optional>
#include <vector>

#include "core/reached_bound.h"
#include "core/scene.h"
#include "core/scene_model.h"
#include "core/transient_run.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

struct SceneRun {
  // The model that ran.
  int coordinates = 0;     // Modal coordinates integrated (all beams, both planes).
  int distinct_bases = 0;  // Modal bases computed (identical beams share one).
  std::vector<int> modes_per_beam;
  std::vector<int> modes_per_structure;
  StabilityBounds bounds;
  double build_wall_s = 0.0;  // Assembling the FE models and modal bases.

  TransientResult result;  // Histories as requested; summary always.
  // Per zone, when requested (empty otherwise): the largest force over every step.
  std::vector<double> max_contact_force_n;
  // The zones whose force histories were recorded (result.contact_force_n, in this order), and
  // when requested the shocks of each.
  std::vector<int> recorded_zones;
  std::vector<std::vector<Shock>> shocks;
  // Per zone, when requested (empty otherwise): the impact statistics over their window
  // (docs/physics.md §6), with the impacts of the zones the scene lists; empty also when the
  // window held no step.
  std::vector<ImpactStatistics> impact_statistics;
  // When some zone has a power law: the bound at the penetrations reached (docs/physics.md §7).
  std::optional<ReachedBound> reached_bound;
};

// Checks, without integrating, what RunScene checks before it integrates: the step count its dt
// resolves to on the bounds of `model` (at most TransientOptions::max_steps) and the size of the
// histories it records. Throws InputError as RunScene does. Preconditions: as RunScene's, and
// `model` is BuildSceneModel(scene) (whose own InputError, a preload's static equilibrium not
// found, the caller sees before this check).
void CheckSceneAffordable(const Scene& scene, SceneModel model);

// Preconditions: the scene was validated (LoadScene). Integrates with central differences at
// scene.solver.dt resolved against the model's bounds.
// `on_progress` gets the simulated time every few dozen steps (TransientOptions::on_progress).
SceneRun RunScene(const Scene& scene, std::function<void(double t_s)> on_progress = {});

}  // namespace shockmap

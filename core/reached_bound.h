#pragma once
// The sharp stability bound at the penetrations a run's power-law zones reached (docs/physics.md
// §7.1): their tangent stiffness p k d^(p-1) grows with the penetration, so the bound the run
// used, taken at each zone's bound penetration, holds only while no zone goes deeper.

#include <string>
#include <vector>

#include "core/scene_system.h"

namespace shockmap {

struct ReachedBound {
  // The power-law zone (index) that went deepest relative to its bound penetration, its largest
  // penetration and its bound penetration (m); -1 when none closed.
  int deepest_zone = -1;
  double largest_penetration_m = 0.0;
  double bound_penetration_m = 0.0;
  // 2 / omega_max with each power-law zone at the larger of its bound penetration and the one
  // it reached (s).
  double dt_sharp_reached_s = 0.0;
  // Some zone of exponent p > 1 went deeper than its bound penetration (of p = 1, whose tangent
  // stiffness is constant, the bound holds at any depth).
  bool exceeded = false;
};

// After a run of `system`; without a power-law zone, not exceeded and dt_sharp_reached_s 0.
// Precondition: the system integrated the run (its contact stations hold the largest
// penetrations).
ReachedBound CheckReachedBound(const SceneModalSystem& system);

}  // namespace shockmap

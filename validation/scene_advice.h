#pragma once
// Advice for a scene from derived validity criteria (the paper's "use these criteria on several
// structures with clearance"; docs/ensembles.md, "Advice for a scene"): each zone's stiffness
// ratio against each of its beams, R_k = k_s / K, K the beam's local bending stiffness at the
// zone's height (the canonical problem's K_bend = 3 EI / L^3 at its tip, the other beam taken
// as the stop), the truncation each beam needs for its stiffest zone, and the time step the
// criteria allow (the scene's model built at the advised truncations). Its text is
// views/scene_advice_summary.h's.

#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "validation/validity_criteria.h"

namespace shockmap {

struct ZoneAdvice {
  std::string name;
  double height_m = 0.0;
  double stiffness_n_per_m = 0.0;
  double k_local_a = 0.0, r_k_a = 0.0, r_ftrunc_a = 0.0;  // R_ftrunc required at R_k.
  std::optional<double> k_local_b, r_k_b, r_ftrunc_b;     // Absent against a stop.
};

struct BeamAdvice {
  std::string name;
  int zones = 0;
  double r_k_max = 0.0;
  std::string stiffest_zone;
  double r_ftrunc = 0.0;        // Required: the largest over its zones.
  double r_ftrunc_scene = 0.0;  // What the scene uses (the beam's own or the solver's).
};

struct SceneAdvice {
  std::vector<ZoneAdvice> zones;
  std::vector<BeamAdvice> beams;  // Beams with zones, in the scene's order.
  double dt_ratio = 0.0;          // dt / dt_sharp the criteria allow.
  double dt_sharp_s = 0.0;        // Of the scene at the advised truncations.
  double dt_s = 0.0;
  double scene_dt_s = 0.0;  // What the scene asks for, resolved.
  // Where the advice is not a measured single-beam boundary: R_k outside the criteria's
  // studied range; R_k the criteria's study left unscored and studied R_k where no truncation
  // passes, each among the studied R_k around the zones'. An ensemble of the scene that held the
  // advice answers them (specs/advice_check_outcomes.h).
  std::vector<std::string> warnings;
};

// Throws InputError when the criteria have no fit or no time-step bound, or the scene's beams
// have rigid-body modes.
SceneAdvice AdviseScene(const Scene& scene, const ValidityCriteria& criteria);

}  // namespace shockmap

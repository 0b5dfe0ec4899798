#pragma once
// An ensemble study file (JSON, in studies/; "kind": "scene_ensemble"; docs/ensembles.md): a
// scene run as many members, each the scene under its own random draws (the scatter of numeric
// parameters by path, and the pin and wrapper gaps of its clearance state), for every
// clearance state and every numerical setting. Members are seeded reproducibly
// (specs/ensemble_draws.h); the member count may grow, and only new members are computed.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "formats/scene_file.h"
#include "specs/ensemble_draws.h"

namespace shockmap {

// A normal law of gaps over the zones of a bundle, drawn by the scene
// (bundle.*.gap_m {"normal": ...}, formats/scene_file.h): min may be negative, a preloaded
// contact (core/preload_equilibrium.h).
struct GapLaw {
  double mean_m = 0.0, std_m = 0.0, min_m = 0.0;
};

// A named point in the life of the assembly: its pin-pin gaps and, if given, its pin-wrapper
// gaps (else the scene's).
struct ClearanceState {
  std::string name;
  std::optional<GapLaw> pin_gap, wrapper_gap;
};

// One member: indices into the spec's states and settings, and its index in the ensemble.
struct EnsembleMember {
  int state = 0;
  int setting = 0;
  int member = 0;
};

// The most members a study file may ask for ("members").
inline constexpr int kMaxEnsembleMembers = 100'000;

struct EnsembleStudySpec {
  std::string file, name, description;
  std::string scene_file;  // Resolved against the study file's folder.
  nlohmann::json scene;    // The scene file's JSON.
  SceneFileAccess access;
  std::uint64_t seed = 0;
  int members = 0;
  double window_s = 0.0;  // Every member's end time.
  // Impact statistics of every zone (docs/physics.md §6), when the file asks for them
  // ("impact_statistics": {"rest_duration_s", "force_threshold_n"?, "convention"?,
  // "window_s"?}, as a scene's outputs.impact_statistics).
  std::optional<ImpactCounting> impact_counting;
  std::vector<ParameterScatter> draws;
  // Without "clearance_states" in the file, one state named "scene": the scene's own gaps.
  std::vector<ClearanceState> states;
  // Numerical settings: each an object {"path": value} (numbers or true/false) applied over
  // the scene; the full product of the file's "settings" axes ({"path": [values]}), the
  // settings it lists ([{"path": value, ...}, ...], in its order), or one empty setting.
  std::vector<nlohmann::json> settings;
  int refined = 0;                     // Index of the setting every other is judged against.
  std::vector<EnsembleMember> points;  // Member-major: every state and setting of member 0 first.
  std::string spec_json;               // The study with the scene embedded, as stored.
};

// Parses the study, reads its scene and checks the scene of every state and setting at the
// centre and at both clip bounds of every draw, so that bad input is refused before anything
// runs. Throws InputError naming the file, the key path, the value and what is allowed.
EnsembleStudySpec ParseEnsembleStudySpec(const nlohmann::json& json, const std::string& file,
                                         const SceneFileAccess& access = {});

// The member's scene: the setting, the drawn parameters and the state's gap laws with the
// member's gap seeds applied; the end time at the window; only the largest force per zone
// recorded, and the impact statistics when the study asks for them (with the impacts of the
// zones the scene's outputs.impact_statistics.impact_table lists). Throws InputError.
Scene MemberScene(const EnsembleStudySpec& spec, const EnsembleMember& member);
// The state's nominal scene at the refined setting: every draw at its centre, every gap at its
// law's mean. Throws InputError.
Scene NominalScene(const EnsembleStudySpec& spec, int state);

std::uint64_t MemberSeedOf(const EnsembleStudySpec& spec, const EnsembleMember& member);
// {"member": i, "setting": {...}, "state": "name"}
std::string MemberKey(const EnsembleStudySpec& spec, const EnsembleMember& member);
// Identifies a state's nominal run across studies: the scene, the draws' centres, the state's
// gaps and its name (two states of one study may share their gaps; each has its nominal run,
// stored under its own name), the refined setting and the window.
std::string NominalKey(const EnsembleStudySpec& spec, int state);
// What a study keeps for life: the scene, the seed, the draws, the window, the impact counting
// and each state's gaps.
std::string EnsembleSettingsKey(const EnsembleStudySpec& spec);
// The state's gaps as JSON, as stored in the settings key.
nlohmann::json StateJson(const ClearanceState& state);

}  // namespace shockmap

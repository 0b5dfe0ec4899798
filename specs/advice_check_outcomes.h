#pragma once
// The outcomes of `check-advice` kept as evidence for `advise` (docs/ensembles.md, "Advice
// checked on the bundle"): where the single-beam criteria measured no boundary (R_k beyond the
// studied range, unscored, or with no passing truncation), the advice for a scene is still
// measured when the scene's own ensemble held it. An outcome names the scene and the criteria by
// the digests of their JSON, so it applies to that scene file and that criteria file only: an
// edit of either (a wire stiffness, a refitted constant) leaves the advice unchecked again.
//
// The file: {"kind": "advice_check_outcomes", "description": TEXT, "outcomes": [OUTCOME, ...]},
// each outcome an object with the keys of AdviceCheckOutcome below.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene.h"

namespace shockmap {

// "fnv1a64:" and 16 hexadecimal digits: FNV-1a of the JSON's compact text with its keys sorted,
// so that neither spacing nor the order of keys in the file changes it.
std::string JsonDigest(const nlohmann::json& json);
// A scene's: JsonDigest of its file's JSON, `scene_json`; with a base motion read from a table
// file, of that JSON together with the table's samples (`scene`, the scene it parses to), so
// that an edit of the table changes it too.
std::string SceneDigest(const nlohmann::json& scene_json, const Scene& scene);

struct AdviceCheckOutcome {
  std::string study;            // The ensemble study's name.
  std::string scene;            // The scene file, as check-advice read it.
  std::string scene_digest;     // SceneDigest of the scene.
  std::string criteria;         // The criteria file.
  std::string criteria_digest;  // JsonDigest of the criteria file's JSON.
  std::vector<std::string> states;
  int members = 0;        // Per clearance state and rung.
  double window_s = 0.0;  // Simulated seconds of every member.
  double quantile = 0.0, tolerance = 0.0;
  int pairs = 0;        // The state and zone family pairs judged.
  int held = 0;         // Those where the advice held.
  std::string verdict;  // The check's paragraph (views/advice_check.h AdviceVerdict).

  bool Held() const { return pairs > 0 && held == pairs; }
  bool operator==(const AdviceCheckOutcome&) const = default;
};

// Throws InputError naming `file`, the key path, the value and what is allowed.
std::vector<AdviceCheckOutcome> ParseAdviceCheckOutcomes(const nlohmann::json& json,
                                                         const std::string& file);
nlohmann::json AdviceCheckOutcomesJson(const std::vector<AdviceCheckOutcome>& outcomes);

// Replaces the outcome of the same study, scene and criteria, else appends `outcome`.
void RecordOutcome(std::vector<AdviceCheckOutcome>& outcomes, AdviceCheckOutcome outcome);

// The outcome for a scene and criteria (by digest): the first where the advice held, else the
// first recorded; nullptr when none is.
const AdviceCheckOutcome* OutcomeFor(const std::vector<AdviceCheckOutcome>& outcomes,
                                     const std::string& scene_digest,
                                     const std::string& criteria_digest);

}  // namespace shockmap

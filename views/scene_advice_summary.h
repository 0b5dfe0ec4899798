#pragma once
// The advice for a scene (validation/scene_advice.h) as the terminal shows it, with the outcome
// of the check of that advice on the scene's own ensemble when one is recorded
// (specs/advice_check_outcomes.h).

#include <string>

#include "specs/advice_check_outcomes.h"
#include "validation/scene_advice.h"

namespace shockmap {

// `check`: the recorded outcome for this scene and criteria, from `checks_file` (nullptr: none).
// Where the advice held on the ensemble, what the single-beam criteria did not measure is
// listed as such, not as a warning; elsewhere it is a warning, and the check that would answer
// it is named.
std::string SceneAdviceSummary(const Scene& scene, const SceneAdvice& advice, bool every_zone,
                               const AdviceCheckOutcome* check = nullptr,
                               const std::string& checks_file = "");

}  // namespace shockmap

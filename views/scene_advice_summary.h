#pragma once
// The advice for a scene (validation/scene_advice.h) as the terminal shows it.

#include <string>

#include "validation/scene_advice.h"

namespace shockmap {

std::string SceneAdviceSummary(const Scene& scene, const SceneAdvice& advice, bool every_zone);

}  // namespace shockmap

#pragma once
// The advice for a new R_k (validation/advice.h) as the terminal shows it and as JSON.

#include <nlohmann/json.hpp>
#include <string>

#include "validation/advice.h"

namespace shockmap {

std::string AdviceSummary(const Advice& advice);
nlohmann::json AdviceToJson(const Advice& advice);

}  // namespace shockmap

#pragma once
// The paper's Fig. 4: Err and SRf against R_k, one curve per truncation of the explicit modal
// scheme and one per truncation of the implicit full model.

#include <filesystem>
#include <string>
#include <vector>

#include "validation/validity_criteria.h"

namespace shockmap {

// Each curve takes, at every R_k, the point with the finest time step. Draws `file` (.png or
// .svg). Throws InputError when there is no scored point.
void DrawFig4(const std::string& study, const std::vector<ScoredPoint>& explicit_points,
              const std::vector<ScoredPoint>& implicit_points, const CriteriaOptions& thresholds,
              const std::filesystem::path& file);

}  // namespace shockmap

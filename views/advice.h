#pragma once
// Advice for a new R_k from a study's derived criteria: the truncation and time step to use and
// what they will cost.

#include <optional>
#include <string>
#include <vector>

#include "formats/study_spec.h"
#include "validation/validity_criteria.h"

namespace shockmap {

struct Advice {
  double r_k = 0.0;
  double r_ftrunc = 0.0;  // Required by the criteria.
  double dt_ratio = 0.0;  // dt / dt_sharp allowed by the criteria.
  double dt_s = 0.0;
  double dt_sharp_s = 0.0;
  int n_modes = 0;
  std::int64_t steps = 0;  // Over the study's observation window.
  double window_s = 0.0;
  double seconds_per_mode_step = 0.0;  // Median of the study's stored explicit runs.
  double expected_wall_s = 0.0;
  std::optional<std::string> warning;  // Outside the studied range of R_k.
};

// Throws InputError when the criteria have no fit or no time-step bound to advise from.
Advice Advise(const StudySpec& spec, const ValidityCriteria& criteria,
              const std::vector<ScoredPoint>& points, double r_k);
std::string AdviceSummary(const Advice& advice);

}  // namespace shockmap

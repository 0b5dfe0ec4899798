#pragma once
// Advice for a new R_k from a study's stored points: the truncation and time step to use, the
// stored points it rests on, and what it will cost (the explicit modal model built at the
// advised truncation). The advice is conservative: it never asks for less than the studied R_k
// around the asked one needed (docs/physics.md §4.3). Its text and JSON are
// views/advice_summary.h's.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/cantilever_impact.h"
#include "validation/validity_criteria.h"

namespace shockmap {

struct Advice {
  double r_k = 0.0;
  double r_ftrunc = 0.0;  // Required: see `basis`.
  double dt_ratio = 0.0;  // dt / dt_sharp allowed.
  double dt_s = 0.0;
  double dt_sharp_s = 0.0;
  int n_modes = 0;
  std::int64_t steps = 0;  // Over the study's observation window.
  double window_s = 0.0;
  double seconds_per_mode_step = 0.0;  // CPU time, median of the stored explicit runs.
  double expected_cpu_s = 0.0;
  // The studied R_k the advice rests on: the asked one, the two around it, or the nearest.
  std::vector<double> studied_r_k;
  std::string basis;  // How r_ftrunc and dt_ratio were chosen, in words.
  // Stored points at those R_k on either side of the advised truncation, at the largest
  // studied time step not above the advised one.
  std::vector<ScoredPoint> nearest;
  std::vector<std::string> warnings;  // Outside the studied R_k, or between sparse ones.
};

// `problem` and `window_s` are the study's (its r_k is replaced by the asked one). Throws
// InputError when the studied points give no passing truncation or time step at the R_k the
// advice would rest on.
Advice Advise(const CantileverImpact& problem, double window_s, const ValidityCriteria& criteria,
              const std::vector<ScoredPoint>& points, double r_k);

}  // namespace shockmap

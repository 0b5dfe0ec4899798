#pragma once
// What accuracy costs in time: for each R_k, Err and SRf against the CPU time of every
// (R_ftrunc, dt, scheme) point, the Pareto front (no other point both faster and more accurate)
// and the implicit/explicit time ratio at equal accuracy.

#include <optional>
#include <string>
#include <vector>

#include "validation/validity_criteria.h"

namespace shockmap {

struct CostRow {
  ScoredPoint point;
  std::string scheme;
  bool passes = false;  // Within the thresholds.
  // Passes while a finer time step of the same scheme, R_k and R_ftrunc fails: it passes by
  // error cancellation, not accuracy (quick, R_k 3162, R_ftrunc 100: Err 0.089 at 0.9 dt_sharp,
  // 0.108 at 0.1), so it is left off the front.
  bool fragile = false;
  bool pareto = false;  // On the front of the passing points that are not fragile.
};

struct CostTable {
  double r_k = 0.0;
  std::optional<double> asked_r_k;  // The R_k asked (cost --rk, the report) this one is nearest to.
  std::optional<double> err_max;    // The Err threshold the rows were judged by, when one judges.
  std::vector<CostRow> rows;        // Scored points, fastest first.
  // Median over implicit points of cpu(implicit) / cpu(cheapest explicit point at least as
  // accurate); nullopt when no implicit point has an explicit match.
  std::optional<double> implicit_over_explicit;
  int ratio_pairs = 0;
};

// One table per R_k (only `r_k` when given: the nearest studied one). The Pareto front (no
// other point both faster and more accurate) is built from the points within `thresholds`
// whose finer time steps at the same scheme and R_ftrunc pass too (CostRow::fragile).
// Wall times of short runs are medians of repeats (engine/canonical_study.cpp); the table
// shows the operation count, steps x modes, beside them.
std::vector<CostTable> BuildCostTables(const std::vector<ScoredPoint>& explicit_points,
                                       const std::vector<ScoredPoint>& implicit_points,
                                       std::optional<double> r_k,
                                       const CriteriaOptions& thresholds = {});

}  // namespace shockmap

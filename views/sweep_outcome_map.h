#pragma once
// The validity map of a scene sweep in its report: every stored point a cell on a grid of two
// swept parameters, coloured and marked by its outcome as the study maps colour theirs
// (views/map_grid.h), its <title> giving the point's parameters, scores and status. The
// truncation (solver.r_ftrunc) runs across and the time step (solver.dt.factor) up when swept,
// else the first two swept parameters in the study's order; one map per combination of the
// other swept parameters. Cells are equal boxes in the order of the swept values, whatever
// their spacing.

#include <string>
#include <vector>

#include "specs/scene_study_spec.h"
#include "validation/validity_criteria.h"

namespace shockmap {

struct SweepPoint {
  SceneParameters parameters;  // The swept paths and this point's values.
  ScoredPoint scored;          // Its status and scores (point_id included).
};

// The maps, each an <svg class="sweep-map"> with the id `id`-K (K from 0) under a heading that
// names the other parameters' values, then one legend of the categories present. Every <rect
// class="cell"> carries data-point-id, data-outcome and data-parameters ("path=value;...").
// "" when no parameter is swept.
std::string HtmlSweepOutcomeMaps(const std::vector<SweepPoint>& points,
                                 const CriteriaOptions& thresholds, const std::string& id);

}  // namespace shockmap

#pragma once
// What each task of a study run costs, measured on this thread (docs/cluster.md, "A model of
// the cluster, checked"): the engine's tasks in its order (references longest first, then the
// points), each computed by the study kind as a worker would, its answer encoded as it would
// travel, then decoded and stored by the kind into a scratch database as rank 0 would.

#include <cstddef>
#include <string>

#include "bench/cluster_model/cluster_simulation.h"
#include "specs/study_file.h"

namespace shockmap {

struct MeasuredCosts {
  StudyCosts costs;
  std::size_t references = 0, points = 0;
  std::size_t points_measured = 0;  // The others repeat their costs in turn.
};

// `scratch_database` must not hold the study (a fresh file). Measures the first
// `points_to_measure` points (0: all) and the references they need; a point beyond them
// waits for its own reference and costs what point (index mod points_to_measure) cost, and its
// outcome is that point's when the groups are stored (every point's row, for the group fit).
MeasuredCosts MeasureStudy(const StudyFile& study, const std::string& scratch_database,
                           std::size_t points_to_measure);

}  // namespace shockmap

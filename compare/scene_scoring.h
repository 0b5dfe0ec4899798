#pragma once
// A scene run measured for the two kinds of scene studies: a sweep's point against the same
// scene run with refined settings (every registered score, its cost, bounds and largest force),
// and an ensemble member zone by zone (its largest forces and impact statistics).

#include <string>
#include <vector>

#include "compare/scene_run.h"
#include "core/run_status.h"
#include "records/ensemble_records.h"
#include "records/scene_records.h"

namespace shockmap {

// How a sweep scores its points: over [0, window_s], the shocks of the scored zone grouped by
// rest_duration_s.
struct SceneScoringOptions {
  double window_s = 0.0;
  double rest_duration_s = 0.0;
};

struct SceneScore {
  RunStatus status = RunStatus::kFailed;
  std::string message;
  SceneScoreRow row;  // Its reference_id is the caller's to set.
};

// `run` (RunScene(scene), recording the scored displacement and zone with its shocks) against
// its reference's stored histories: the run's cost and bounds always; the scores when both
// ended ok and the window holds more than one step (a window inside one step holds no history
// to compare: Err would be 0 and the point pass). May throw std::invalid_argument (a signal the
// scores cannot read).
SceneScore ScoreSceneRun(const Scene& scene, const SceneRun& run,
                         const SceneReferenceRow& reference, const SceneScoringOptions& options);

// A member's zone rows of a run of `scene` that ended ok: its largest force per zone and, when
// streamed, its impact statistics (the wear work rate where the scene carries the sliding, the
// wear volume over the scene's wear life where it has a wear law, the friction power where the
// zone has friction).
std::vector<EnsembleZoneRow> MemberZoneRows(const Scene& scene, const SceneRun& run);
// The impacts of the zones the scene lists (outputs.impact_table_zones) in a run that ended ok,
// in zone then time order; none when the run did not stream impact statistics.
std::vector<EnsembleImpactRow> MemberImpactRows(const Scene& scene, const SceneRun& run);

}  // namespace shockmap

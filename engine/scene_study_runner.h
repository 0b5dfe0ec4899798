#pragma once
// Runs a scene study into a database: every point of the sweep once, each reference once per
// database, one transaction per finished point; resumable like the studies of the paper's
// problem (studies/study_runner.h), with which it shares options and summary.

#include "engine/study_runner.h"
#include "formats/scene_study_spec.h"

namespace shockmap {

// Throws InputError when the study exists in the database with another scene or scoring (its
// stored scores would no longer match), and DbError on database faults.
StudyRunSummary RunSceneStudy(const SceneStudySpec& spec, const StudyRunOptions& options);

}  // namespace shockmap

#pragma once
// Runs a study file of any kind through the one study engine (engine/study_engine.h).

#include "engine/study_engine.h"
#include "formats/study_file.h"

namespace shockmap {

// Throws InputError when the study is stored with other settings, DbError on database faults.
StudyRunSummary RunStudy(const StudyFile& study, const StudyRunOptions& options);

}  // namespace shockmap

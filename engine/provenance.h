#pragma once
// Where a result comes from: code version, compiler, build type, host, process.

#include "db/study_database.h"

namespace shockmap {

Provenance CurrentProvenance(int jobs);

}  // namespace shockmap

#pragma once
// A ReferenceRun as a database row and back, so a reference is computed once per database.

#include "db/study_database.h"
#include "studies/reference_run.h"

namespace shockmap {

ReferenceRow ToReferenceRow(const ReferenceRun& run, const std::string& reference_key, double r_k,
                            double window_s);
ReferenceRun FromReferenceRow(const ReferenceRow& row);

}  // namespace shockmap

#pragma once
// A ReferenceRun as a database row and back, so a reference is computed once per database.

#include "compare/reference_run.h"
#include "db/canonical_points.h"

namespace shockmap {

ReferenceRow ToReferenceRow(const ReferenceRun& run, const std::string& reference_key, double r_k,
                            double window_s);
// Throws DbError when its stored shocks (shocks_json) are not what ToReferenceRow writes.
ReferenceRun FromReferenceRow(const ReferenceRow& row, const std::string& database_path);

}  // namespace shockmap

#pragma once
// The scores and references of studies of the paper's problem (tables scores, reference_runs;
// the points table is kCanonicalPoints of db/point_tables.h), written by the one StudyDatabase
// writer. The records and their columns are in records/canonical_records.h.

#include <cstdint>
#include <optional>
#include <string>

#include "db/study_database.h"
#include "records/canonical_records.h"

namespace shockmap {

// Replaces the point's score row by `score` (none when it was not computed), on the writer's
// connection inside StorePointOutcomes' transaction.
void WriteScore(Connection& c, std::int64_t point_id, const std::optional<ScoreRow>& score);

// Throws DbError when the stored row is corrupt (db/corrupt_rows.h).
std::optional<ReferenceRow> FindReference(StudyDatabase& db, const std::string& reference_key);
// Stores a new reference and returns its id.
std::int64_t StoreReference(StudyDatabase& db, const ReferenceRow& reference, std::int64_t run_id);

}  // namespace shockmap

#pragma once
// The scores and references of scene studies (the score columns of kScenePoints, db/
// point_tables.h, and table scene_references), written by the one StudyDatabase writer. The
// records and their columns are in records/scene_records.h.

#include <cstdint>
#include <optional>
#include <string>

#include "db/study_database.h"
#include "records/scene_records.h"

namespace shockmap {

// Sets the point's score columns from `score` (NULL when it was not computed), on the writer's
// connection inside StorePointOutcomes' transaction.
void WriteScore(Connection& c, std::int64_t point_id, const std::optional<SceneScoreRow>& score);
// Throws DbError when the stored row is corrupt (db/corrupt_rows.h).
std::optional<SceneReferenceRow> FindSceneReference(StudyDatabase& db, const std::string& key);
// Stores a new reference and returns its id.
std::int64_t StoreSceneReference(StudyDatabase& db, const SceneReferenceRow& reference,
                                 std::int64_t run_id);

}  // namespace shockmap

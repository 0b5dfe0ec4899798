#include "db/scene_points.h"

#include <string>

#include "db/corrupt_rows.h"

namespace shockmap {

void WriteScore(Connection& c, std::int64_t point_id, const std::optional<SceneScoreRow>& score) {
  static const std::string kUpdate =
      "UPDATE scene_points SET " + Assignments(kSceneScoreColumns) + " WHERE point_id = ?";
  Statement& update = c.Cached(kUpdate);
  const int next = score ? BindRecord(update, 1, *score, kSceneScoreColumns)
                         : BindNulls(update, 1, kSceneScoreColumns);
  update.Bind(next, point_id).Run();
}

std::optional<SceneReferenceRow> FindSceneReference(StudyDatabase& db, const std::string& key) {
  auto row = FindReferenceRow<SceneReferenceRow>(db, "scene_references", "scene reference", key,
                                                 kSceneReferenceColumns);
  if (row) CheckSceneReference(db.Raw().Path(), *row);
  return row;
}

std::int64_t StoreSceneReference(StudyDatabase& db, const SceneReferenceRow& reference,
                                 std::int64_t run_id) {
  return InsertReference(db, "scene_references", reference, kSceneReferenceColumns, run_id);
}

}  // namespace shockmap

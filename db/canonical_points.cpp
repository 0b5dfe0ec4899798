#include "db/canonical_points.h"

#include <string>

#include "db/corrupt_rows.h"
#include "db/stored_record.h"

namespace shockmap {

void WriteScore(Connection& c, std::int64_t point_id, const std::optional<ScoreRow>& score) {
  c.Cached("DELETE FROM scores WHERE point_id = ?").Bind(1, point_id).Run();
  if (!score) return;
  static const std::string kInsert = "INSERT INTO scores(point_id, " + ColumnList(kScoreColumns) +
                                     ") VALUES (?, " + Placeholders(std::size(kScoreColumns)) + ")";
  Statement& insert = c.Cached(kInsert);
  insert.Bind(1, point_id);
  BindRecord(insert, 2, *score, kScoreColumns);
  insert.Run();
}

std::optional<ReferenceRow> FindReference(StudyDatabase& db, const std::string& reference_key) {
  auto row = FindReferenceRow<ReferenceRow>(db, "reference_runs", "reference", reference_key,
                                            kReferenceColumns);
  if (row) CheckReference(db.Raw().Path(), *row);
  return row;
}

std::int64_t StoreReference(StudyDatabase& db, const ReferenceRow& reference, std::int64_t run_id) {
  return InsertReference(db, "reference_runs", reference, kReferenceColumns, run_id);
}

}  // namespace shockmap

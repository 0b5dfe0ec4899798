#include "db/stored_signals.h"

#include <bit>
#include <memory>

#include "db/corrupt_rows.h"
#include "db/read_only_query.h"
#include "db/schema.h"
#include "db/stored_record.h"
#include "records/scene_records.h"

namespace shockmap {
namespace {

// The blob layout of docs/database.md is the host's: only little-endian hosts write it.
static_assert(std::endian::native == std::endian::little,
              "stored signals are little-endian float64 (docs/database.md)");

std::unique_ptr<Connection> OpenReadOnly(const std::string& database_path) {
  auto db = std::make_unique<Connection>(database_path, Connection::Mode::kReadOnly);
  CheckSchema(*db);
  return db;
}

// The reference `reference_id` of `table`, read on a read-only connection.
// `what` names its rows in a refusal ("reference", "scene reference").
template <typename Row>
std::optional<Row> ReadById(const std::string& database_path, std::string_view table,
                            std::string_view what, std::int64_t reference_id, const auto& columns) {
  const auto db = OpenReadOnly(database_path);
  Statement s = db->Prepare("SELECT " + ColumnList(columns) + " FROM " + std::string(table) +
                            " WHERE reference_id = ?");
  s.Bind(1, reference_id);
  if (!s.Step()) return std::nullopt;
  Row row;
  row.reference_id = reference_id;
  ReadRecord(s, 0, row, columns, database_path,
             [&] { return std::string(what) + " " + std::to_string(reference_id); });
  return row;
}

std::optional<std::int64_t> FirstInteger(const Table& r) {
  if (r.rows.empty() || !std::holds_alternative<std::int64_t>(r.rows.front().front())) {
    return std::nullopt;
  }
  return std::get<std::int64_t>(r.rows.front().front());
}

}  // namespace

std::vector<std::int64_t> ReferenceIdsAt(const std::string& database_path, const std::string& study,
                                         double r_k) {
  const auto db = OpenReadOnly(database_path);
  Statement s = db->Prepare(
      "SELECT DISTINCT sc.reference_id FROM points p JOIN studies st USING (study_id) "
      "JOIN scores sc USING (point_id) WHERE st.name = ?1 AND abs(p.r_k - ?2) <= 1e-9 * ?2 "
      "ORDER BY sc.reference_id");
  s.BindAll(study, r_k);
  std::vector<std::int64_t> ids;
  while (s.Step()) ids.push_back(s.GetInt(0));
  return ids;
}

std::vector<double> ScoredRks(const std::string& database_path, const std::string& study) {
  const auto db = OpenReadOnly(database_path);
  Statement s = db->Prepare(
      "SELECT DISTINCT p.r_k FROM points p JOIN studies st USING (study_id) "
      "JOIN scores sc USING (point_id) WHERE st.name = ?1 ORDER BY p.r_k");
  s.BindAll(study);
  std::vector<double> r_k;
  while (s.Step()) r_k.push_back(s.GetDouble(0));
  return r_k;
}

std::optional<ReferenceRow> ReadReference(const std::string& database_path,
                                          std::int64_t reference_id) {
  const auto r = ReadById<ReferenceRow>(database_path, "reference_runs", "reference", reference_id,
                                        kReferenceColumns);
  if (r) CheckReference(database_path, *r);
  return r;
}

StoredSignals SignalsOf(const ReferenceRow& reference) {
  return {reference.reference_id,
          reference.output_dt_s,
          {"tip_displacement_m", "contact_force_n"},
          {reference.tip_m, reference.force_n}};
}

std::optional<std::int64_t> ReferenceOfPoint(const std::string& database_path,
                                             const std::string& study, std::int64_t point_id) {
  return FirstInteger(RunReadOnlyQuery(
      database_path,
      "SELECT sc.reference_id FROM points p JOIN studies st USING (study_id) JOIN scores sc "
      "USING (point_id) WHERE st.name = ?1 AND p.point_id = CAST(?2 AS INTEGER) "
      "UNION ALL SELECT p.reference_id FROM scene_points p JOIN studies st USING (study_id) "
      "WHERE st.name = ?1 AND p.point_id = CAST(?2 AS INTEGER) AND p.reference_id IS NOT NULL",
      {study, std::to_string(point_id)}));
}

std::optional<StoredSignals> ReadSceneReferenceSignals(const std::string& database_path,
                                                       std::int64_t reference_id) {
  auto r = ReadById<SceneReferenceRow>(database_path, "scene_references", "scene reference",
                                       reference_id, kSceneReferenceColumns);
  if (!r) return std::nullopt;
  CheckSceneReference(database_path, *r);
  return StoredSignals{reference_id,
                       r->output_dt_s,
                       {"displacement_m", "contact_force_n"},
                       {std::move(r->displacement_m), std::move(r->force_n)}};
}

std::optional<std::string> CanonicalPointKey(const std::string& database_path,
                                             const std::string& study, std::int64_t point_id) {
  const Table r = RunReadOnlyQuery(
      database_path,
      "SELECT p.point_key FROM points p JOIN studies st USING (study_id) WHERE st.name = ?1 AND "
      "p.point_id = CAST(?2 AS INTEGER)",
      {study, std::to_string(point_id)});
  if (r.rows.empty()) return std::nullopt;
  return StoredText(r.rows.front().front(), database_path, "point " + std::to_string(point_id),
                    "point_key");
}

}  // namespace shockmap

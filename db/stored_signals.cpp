#include "db/stored_signals.h"

#include <bit>
#include <memory>

#include "db/corrupt_rows.h"
#include "db/read_only_query.h"
#include "db/schema.h"

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

std::optional<std::int64_t> FirstInteger(const QueryResult& r) {
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

std::optional<ReferenceRow> ReadReference(const std::string& database_path,
                                          std::int64_t reference_id) {
  const auto db = OpenReadOnly(database_path);
  Statement s = db->Prepare(
      "SELECT reference_key, r_k, r_fref, r_fref_check, window_s, convergence, n_modes_free, "
      "n_modes_contact, n_transitions, wall_s, output_dt_s, tip_m, force_n, shocks_json "
      "FROM reference_runs WHERE reference_id = ?");
  s.Bind(1, reference_id);
  if (!s.Step()) return std::nullopt;
  ReferenceRow r;
  r.reference_id = reference_id;
  s.ReadColumns(r.reference_key, r.r_k, r.r_fref, r.r_fref_check, r.window_s, r.convergence,
                r.n_modes_free, r.n_modes_contact, r.n_transitions, r.wall_s, r.output_dt_s,
                r.tip_m, r.force_n, r.shocks_json);
  CheckReference(database_path, r);
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
  const auto db = OpenReadOnly(database_path);
  Statement s = db->Prepare(
      "SELECT status, output_dt_s, displacement_m, force_n FROM scene_references WHERE "
      "reference_id = ?");
  s.Bind(1, reference_id);
  if (!s.Step()) return std::nullopt;
  SceneReferenceRow r;
  r.reference_id = reference_id;
  s.ReadColumns(r.status, r.output_dt_s, r.displacement_m, r.force_n);
  CheckSceneReference(database_path, r);
  return StoredSignals{reference_id,
                       r.output_dt_s,
                       {"displacement_m", "contact_force_n"},
                       {std::move(r.displacement_m), std::move(r.force_n)}};
}

std::optional<std::string> CanonicalPointKey(const std::string& database_path,
                                             const std::string& study, std::int64_t point_id) {
  const QueryResult r = RunReadOnlyQuery(
      database_path,
      "SELECT p.point_key FROM points p JOIN studies st USING (study_id) WHERE st.name = ?1 AND "
      "p.point_id = CAST(?2 AS INTEGER)",
      {study, std::to_string(point_id)});
  if (r.rows.empty()) return std::nullopt;
  return StoredText(r.rows.front().front(), database_path, "point " + std::to_string(point_id),
                    "point_key");
}

}  // namespace shockmap

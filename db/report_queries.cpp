#include "db/report_queries.h"

#include "db/corrupt_rows.h"
#include "db/stored_json.h"
#include "db/stored_signals.h"

namespace shockmap {

ReportTables LoadReportTables(const std::string& database_path, const std::string& study) {
  ReportTables t;
  t.outcomes = RunReadOnlyQuery(database_path,
                                "SELECT scheme, status, count(*) AS points FROM results WHERE "
                                "study = ?1 GROUP BY scheme, status ORDER BY scheme, status",
                                {study});
  t.provenance = RunReadOnlyQuery(
      database_path,
      "SELECT ru.run_id, ru.code_version, ru.compiler, ru.build_type, ru.host, ru.jobs, "
      "ru.started_utc, ru.ended_utc, ru.points_done FROM runs ru JOIN studies st USING "
      "(study_id) WHERE st.name = ?1 ORDER BY ru.run_id",
      {study});
  t.spec_json = StoredStudySpec(database_path, study).value_or("");
  return t;
}

Table StudyResultRows(const std::string& database_path, const std::string& study,
                      const PointTable& table) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT * FROM " + std::string(table.results_view) + " WHERE study = ?1 ORDER BY point_id",
      {study});
}

Table PointKeys(const std::string& database_path, const std::string& study) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT p.point_id, p.point_key, p.reference_key FROM points p JOIN studies st USING "
      "(study_id) WHERE st.name = ?1 ORDER BY p.point_id",
      {study});
}

std::optional<ReferenceRow> ReadStoredReference(const std::string& database_path,
                                                const std::string& reference_key) {
  const Table id = RunReadOnlyQuery(
      database_path, "SELECT reference_id FROM reference_runs WHERE reference_key = ?1",
      {reference_key});
  if (id.rows.empty()) return std::nullopt;
  return ReadReference(database_path, std::get<std::int64_t>(id.rows.front().front()));
}

std::optional<std::string> StoredStudySpec(const std::string& database_path,
                                           const std::string& study) {
  const Table spec =
      RunReadOnlyQuery(database_path, "SELECT spec_json FROM studies WHERE name = ?1", {study});
  if (spec.rows.empty()) return std::nullopt;
  return StoredText(spec.rows.front().front(), database_path, "study " + study, "spec_json");
}

std::optional<nlohmann::json> StoredStudyJson(const std::string& database_path,
                                              const std::string& study) {
  const auto text = StoredStudySpec(database_path, study);
  if (!text) return std::nullopt;
  return ParseStoredJson({database_path, "study " + study, "spec_json"}, *text);
}

}  // namespace shockmap

#include "db/report_queries.h"

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

std::optional<std::string> StoredStudySpec(const std::string& database_path,
                                           const std::string& study) {
  const QueryResult spec =
      RunReadOnlyQuery(database_path, "SELECT spec_json FROM studies WHERE name = ?1", {study});
  if (spec.rows.empty()) return std::nullopt;
  return std::get<std::string>(spec.rows.front().front());
}

}  // namespace shockmap

#include "db/study_queries.h"

#include <fmt/format.h>

#include "db/corrupt_rows.h"
#include "db/point_tables.h"
#include "db/study_database.h"

namespace shockmap {

namespace {

// "sum(p.status = 'ok') AS ok, ...": the points counted by each status a point may end with,
// then the pending and the running ones.
std::string StatusCounts() {
  std::string counts;
  for (const char* status :
       {"ok", "diverged", "unstable", "failed", "reference_unconverged", "pending", "running"}) {
    counts += fmt::format("sum(p.status = '{0}') AS {0}, ", status);
  }
  return counts;
}

// The points of every kind's table: `columns` of each, one after the other (UNION ALL).
std::string EveryPointTable(const std::string& columns, const std::string& where = "") {
  std::string tables;
  for (const PointTable* table : PointTables()) {
    tables += fmt::format("{}SELECT {} FROM {}{}", tables.empty() ? "" : " UNION ALL ", columns,
                          table->name, where);
  }
  return tables;
}

}  // namespace

Table StudyProgress(const std::string& database_path) {
  return RunReadOnlyQuery(
      database_path, "SELECT st.name AS study, count(*) AS points, " + StatusCounts() +
                         "max(p.updated_utc) AS last_update FROM (" +
                         EveryPointTable("study_id, status, updated_utc") +
                         ") p JOIN studies st USING (study_id) GROUP BY st.name ORDER BY st.name");
}

std::vector<StudyBreakdown> StudyProgressBreakdowns(const std::string& database_path) {
  std::vector<StudyBreakdown> breakdowns;
  for (const PointTable* table : PointTables()) {
    if (table->progress_by.empty()) continue;
    std::string by;
    for (std::string_view column : table->progress_by) by += fmt::format(", p.{}", column);
    breakdowns.push_back(
        {table, RunReadOnlyQuery(database_path,
                                 "SELECT st.name AS study" + by + ", count(*) AS points, " +
                                     StatusCounts() + "max(p.updated_utc) AS last_update FROM " +
                                     std::string(table->name) +
                                     " p JOIN studies st USING (study_id) GROUP BY st.name" + by +
                                     " ORDER BY st.name" + by)});
  }
  return breakdowns;
}

Table StudyOrigins(const std::string& database_path) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT st.name AS study, p.host, p.rank, count(*) AS points, "
      "min(p.point_id) AS first_point, max(p.point_id) AS last_point FROM (" +
          EveryPointTable("study_id, point_id, host, rank", " WHERE host IS NOT NULL") +
          ") p JOIN studies st USING (study_id) GROUP BY st.name, p.host, p.rank "
          "ORDER BY st.name, p.host, p.rank");
}

std::vector<std::string> StudyNames(const std::string& database_path) {
  const Table r = RunReadOnlyQuery(database_path, "SELECT name FROM studies ORDER BY name");
  std::vector<std::string> names;
  for (const auto& row : r.rows)
    names.push_back(StoredText(row[0], database_path, "a study", "name"));
  return names;
}

std::optional<std::string> LiveWriter(const std::string& database_path) {
  const double now = UnixNow();
  const Table r = RunReadOnlyQuery(
      database_path,
      // Cast, since a forged row may hold any type in any column.
      "SELECT run_id, coalesce(CAST(host AS TEXT), ''), coalesce(CAST(pid AS INTEGER), 0), "
      "CAST(heartbeat_unix_s AS REAL) FROM runs WHERE ended_utc IS NULL "
      "AND heartbeat_unix_s > CAST(?1 AS REAL) ORDER BY run_id DESC LIMIT 1",
      {fmt::format("{:.3f}", now - kLeaseGraceS)});
  if (r.rows.empty()) return std::nullopt;
  const auto& row = r.rows[0];
  return fmt::format("run {} (host {}, pid {}), last heartbeat {:.0f} s ago",
                     std::get<std::int64_t>(row[0]), std::get<std::string>(row[1]),
                     std::get<std::int64_t>(row[2]), now - std::get<double>(row[3]));
}

Table ScoredPointRows(const std::string& database_path, const std::string& study,
                      const std::string& scheme) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT * FROM results WHERE study = ?1 AND scheme = ?2 AND dt_requested_s IS NOT NULL "
      "ORDER BY point_id",
      {study, scheme});
}

}  // namespace shockmap

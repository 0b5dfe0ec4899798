#include "db/study_queries.h"

#include <fmt/format.h>

#include "db/corrupt_rows.h"
#include "db/study_database.h"

namespace shockmap {

QueryResult StudyProgress(const std::string& database_path) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT st.name AS study, count(*) AS points, "
      "sum(p.status = 'ok') AS ok, sum(p.status = 'diverged') AS diverged, "
      "sum(p.status = 'unstable') AS unstable, sum(p.status = 'failed') AS failed, "
      "sum(p.status = 'reference_unconverged') AS reference_unconverged, "
      "sum(p.status = 'pending') AS pending, sum(p.status = 'running') AS running, "
      "max(p.updated_utc) AS last_update "
      "FROM (SELECT study_id, status, updated_utc FROM points UNION ALL "
      "SELECT study_id, status, updated_utc FROM scene_points) p "
      "JOIN studies st USING (study_id) GROUP BY st.name ORDER BY st.name");
}

QueryResult StudyOrigins(const std::string& database_path) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT st.name AS study, p.host, p.rank, count(*) AS points, "
      "min(p.point_id) AS first_point, max(p.point_id) AS last_point "
      "FROM (SELECT study_id, point_id, host, rank FROM points WHERE host IS NOT NULL "
      "UNION ALL SELECT study_id, point_id, host, rank FROM scene_points WHERE host IS NOT NULL) "
      "p JOIN studies st USING (study_id) GROUP BY st.name, p.host, p.rank "
      "ORDER BY st.name, p.host, p.rank");
}

std::vector<std::string> StudyNames(const std::string& database_path) {
  const QueryResult r = RunReadOnlyQuery(database_path, "SELECT name FROM studies ORDER BY name");
  std::vector<std::string> names;
  for (const auto& row : r.rows)
    names.push_back(StoredText(row[0], database_path, "a study", "name"));
  return names;
}

std::optional<std::string> LiveWriter(const std::string& database_path) {
  const double now = UnixNow();
  const QueryResult r = RunReadOnlyQuery(
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

QueryResult ScoredPointRows(const std::string& database_path, const std::string& study,
                            const std::string& scheme) {
  return RunReadOnlyQuery(
      database_path,
      "SELECT point_id, r_k, r_ftrunc, status, err, srf, dt_requested_s, dt_sharp_s, dt_paper_s, "
      "wall_s, n_modes, steps, cpu_s FROM results WHERE study = ?1 AND scheme = ?2 "
      "AND dt_requested_s IS NOT NULL ORDER BY point_id",
      {study, scheme});
}

}  // namespace shockmap

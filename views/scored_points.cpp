#include "views/scored_points.h"

#include <variant>

#include "core/input_error.h"
#include "db/read_only_query.h"

namespace shockmap {
namespace {

double Real(const QueryCell& c) {
  if (const auto* d = std::get_if<double>(&c)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&c)) return static_cast<double>(*i);
  return 0.0;
}

std::optional<double> OptionalReal(const QueryCell& c) {
  if (std::holds_alternative<std::monostate>(c)) return std::nullopt;
  return Real(c);
}

}  // namespace

std::string ResolveStudyName(const std::string& database_path, const std::string& study) {
  const QueryResult r = RunReadOnlyQuery(database_path, "SELECT name FROM studies ORDER BY name");
  std::string names;
  for (const auto& row : r.rows) {
    const auto& name = std::get<std::string>(row[0]);
    if (name == study) return study;
    names += (names.empty() ? "" : ", ") + name;
  }
  if (!study.empty()) {
    throw InputError("no study named \"" + study + "\" in " + database_path +
                     " (studies: " + (names.empty() ? "none" : names) + ")");
  }
  if (r.rows.size() != 1) {
    throw InputError(database_path + " holds " + std::to_string(r.rows.size()) +
                     " studies; name one of: " + (names.empty() ? "none" : names));
  }
  return std::get<std::string>(r.rows[0][0]);
}

std::vector<ScoredPoint> LoadScoredPoints(const std::string& database_path,
                                          const std::string& study, const std::string& scheme) {
  const QueryResult r = RunReadOnlyQuery(
      database_path,
      "SELECT point_id, r_k, r_ftrunc, status, err, srf, dt_requested_s, dt_sharp_s, dt_paper_s, "
      "wall_s, n_modes, steps FROM results WHERE study = ?1 AND scheme = ?2 "
      "AND dt_requested_s IS NOT NULL ORDER BY point_id",
      {study, scheme});
  std::vector<ScoredPoint> points;
  for (const auto& row : r.rows) {
    ScoredPoint p;
    p.point_id = std::get<std::int64_t>(row[0]);
    p.r_k = Real(row[1]);
    p.r_ftrunc = Real(row[2]);
    p.status = std::get<std::string>(row[3]);
    p.err = OptionalReal(row[4]);
    p.srf = OptionalReal(row[5]);
    p.dt_s = Real(row[6]);
    p.dt_sharp_s = Real(row[7]);
    p.dt_paper_s = Real(row[8]);
    p.wall_s = Real(row[9]);
    p.n_modes = static_cast<int>(Real(row[10]));
    p.steps = static_cast<std::int64_t>(Real(row[11]));
    points.push_back(p);
  }
  return points;
}

}  // namespace shockmap

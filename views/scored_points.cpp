#include "views/scored_points.h"

#include <limits>
#include <variant>

#include "core/input_error.h"
#include "db/corrupt_rows.h"
#include "db/study_queries.h"

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
  const std::vector<std::string> stored = StudyNames(database_path);
  std::string names;
  for (const std::string& name : stored) {
    if (name == study) return study;
    names += (names.empty() ? "" : ", ") + name;
  }
  if (!study.empty()) {
    throw InputError("no study named \"" + study + "\" in " + database_path +
                     " (studies: " + (names.empty() ? "none" : names) + ")");
  }
  if (stored.size() != 1) {
    throw InputError(database_path + " holds " + std::to_string(stored.size()) +
                     " studies; name one of: " + (names.empty() ? "none" : names));
  }
  return stored.front();
}

std::vector<ScoredPoint> LoadScoredPoints(const std::string& database_path,
                                          const std::string& study, const std::string& scheme) {
  const QueryResult r = ScoredPointRows(database_path, study, scheme);
  std::vector<ScoredPoint> points;
  for (const auto& row : r.rows) {
    ScoredPoint p;
    p.point_id = std::get<std::int64_t>(row[0]);
    p.r_k = Real(row[1]);
    p.r_ftrunc = Real(row[2]);
    const std::string what = "point " + std::to_string(p.point_id);
    const std::string& status = StoredText(row[3], database_path, what, "status");
    const auto parsed = RunStatusFromString(status);
    if (!parsed) {
      throw InputError(database_path + ": point " + std::to_string(p.point_id) +
                       " has the unknown status \"" + status + "\"");
    }
    p.status = *parsed;
    p.err = OptionalReal(row[4]);
    p.srf = OptionalReal(row[5]);
    p.dt_s = Real(row[6]);
    p.dt_sharp_s = Real(row[7]);
    p.dt_paper_s = Real(row[8]);
    p.wall_s = Real(row[9]);
    p.n_modes = static_cast<int>(
        StoredCount(row[10], database_path, what, "n_modes", std::numeric_limits<int>::max()));
    p.steps = StoredCount(row[11], database_path, what, "steps",
                          std::numeric_limits<std::int64_t>::max());
    p.cpu_s = Real(row[12]);
    points.push_back(p);
  }
  return points;
}

}  // namespace shockmap

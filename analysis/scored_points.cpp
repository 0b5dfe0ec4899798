#include "analysis/scored_points.h"

#include <limits>
#include <variant>

#include "core/input_error.h"
#include "db/corrupt_rows.h"
#include "db/report_queries.h"
#include "db/study_queries.h"
#include "records/canonical_records.h"
#include "specs/study_file.h"

namespace shockmap {
namespace {

// More runs than this under perturbations is a corrupt row (compare/score_spread.h makes 7).
constexpr std::int64_t kMaxSpreadRuns = 1000;

// The names of a stored reference_undecided cell ("err,pfr"); DbError naming the point unless
// each is a registered score.
std::vector<std::string> UndecidedScores(const std::string& cell, const std::string& database_path,
                                         const std::string& what) {
  std::vector<std::string> names;
  if (cell.empty()) return names;
  for (std::size_t begin = 0, end = 0; end != std::string::npos; begin = end + 1) {
    end = cell.find(',', begin);
    std::string name = cell.substr(begin, end == std::string::npos ? end : end - begin);
    if (FindScore(name) == nullptr) {
      ThrowCorrupt(database_path, what,
                   "reference_undecided holds \"" + cell +
                       "\" (registered score names, comma "
                       "separated)");
    }
    names.push_back(std::move(name));
  }
  return names;
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

namespace {

StudyFileKind StoredKind(const std::string& database_path, const std::string& study) {
  const std::string file = database_path + ": stored study " + study;
  return StudyKindOf(StoredStudyJson(database_path, study).value_or(nlohmann::json::object()),
                     file);
}

// What judges a study of another kind than the paper's problem.
std::string CommandsFor(StudyFileKind kind, const std::string& study) {
  return kind == StudyFileKind::kSceneEnsemble
             ? "an ensemble is judged with `shockmap sizing " + study + "` and `shockmap report " +
                   study + " --out DIR`"
             : "a scene sweep is judged with `shockmap report " + study + " --out DIR`";
}

}  // namespace

std::string ResolveCanonicalStudy(const std::string& database_path, const std::string& study,
                                  const std::string& command) {
  if (!study.empty()) {
    ResolveStudyName(database_path, study);  // Throws for a name not stored.
    const StudyFileKind kind = StoredKind(database_path, study);
    if (kind == StudyFileKind::kCanonical) return study;
    throw InputError("STUDY: study " + study + " in " + database_path + " is of kind \"" +
                     ToString(kind) + "\", not of the paper's problem (kind \"canonical\") that `" +
                     command + "` reads; " + CommandsFor(kind, study));
  }
  std::vector<std::string> canonical;
  for (const std::string& name : StudyNames(database_path)) {
    if (StoredKind(database_path, name) == StudyFileKind::kCanonical) canonical.push_back(name);
  }
  if (canonical.size() == 1) return canonical.front();
  std::string names;
  for (const std::string& name : canonical) names += (names.empty() ? "" : ", ") + name;
  throw InputError("STUDY: " + database_path + " holds " + std::to_string(canonical.size()) +
                   " studies of the paper's problem (kind \"canonical\") that `" + command +
                   "` reads; " + (canonical.empty() ? "run one first" : "name one of: " + names));
}

std::vector<ScoredPoint> LoadScoredPoints(const std::string& database_path,
                                          const std::string& study, const std::string& scheme) {
  const Table r = ScoredPointRows(database_path, study, scheme);
  std::vector<ScoredPoint> points;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const NamedRow row(r, i);
    ScoredPoint p;
    p.point_id = std::get<std::int64_t>(row["point_id"]);
    const std::string what = "point " + std::to_string(p.point_id);
    p.r_k = NumberIn(row["r_k"]).value_or(0.0);
    p.r_ftrunc = NumberIn(row["r_ftrunc"]).value_or(0.0);
    const std::string& status = StoredText(row["status"], database_path, what, "status");
    const auto parsed = RunStatusFromString(status);
    if (!parsed) {
      throw InputError(database_path + ": point " + std::to_string(p.point_id) +
                       " has the unknown status \"" + status + "\"");
    }
    p.status = *parsed;
    for (const ScoreDefinition& score : Scores()) {
      const std::string name(score.name);
      p.scores.Set(name, NumberIn(row[name]));
      p.spread_low.Set(name, NumberIn(row[name + std::string(kSpreadLowSuffix)]));
      p.spread_high.Set(name, NumberIn(row[name + std::string(kSpreadHighSuffix)]));
    }
    if (!std::holds_alternative<std::monostate>(row["spread_runs"])) {  // NULL: none taken.
      p.spread_runs = static_cast<int>(
          StoredCount(row["spread_runs"], database_path, what, "spread_runs", kMaxSpreadRuns));
    }
    p.dt_s = NumberIn(row["dt_requested_s"]).value_or(0.0);
    p.dt_sharp_s = NumberIn(row["dt_sharp_s"]).value_or(0.0);
    p.dt_paper_s = NumberIn(row["dt_paper_s"]).value_or(0.0);
    p.wall_s = NumberIn(row["wall_s"]).value_or(0.0);
    p.n_modes = static_cast<int>(StoredCount(row["n_modes"], database_path, what, "n_modes",
                                             std::numeric_limits<int>::max()));
    p.steps = StoredCount(row["steps"], database_path, what, "steps",
                          std::numeric_limits<std::int64_t>::max());
    p.cpu_s = NumberIn(row["cpu_s"]).value_or(0.0);
    if (const auto* message = std::get_if<std::string>(&row["message"])) p.message = *message;
    if (const auto* undecided = std::get_if<std::string>(&row["reference_undecided"]))
      p.reference_undecided = UndecidedScores(*undecided, database_path, what);
    // Every stored value of its type and range, before the point is used.
    CheckStoredCells(database_path, what, r, i, kPointParameterColumns);
    CheckStoredCells(database_path, what, r, i, kScoreColumns);
    points.push_back(p);
  }
  return points;
}

std::vector<ScoredPoint> LoadCriteriaPoints(const std::string& database_path,
                                            const std::string& study) {
  auto points = LoadScoredPoints(database_path, study, "explicit-modal");
  if (points.empty()) {
    throw InputError("STUDY: study " + study + " in " + database_path +
                     " has no scored point of the paper's problem (explicit-modal): criteria are "
                     "derived from a study of kind \"canonical\" once its points are run (an "
                     "ensemble is judged with `shockmap sizing`)");
  }
  return points;
}

}  // namespace shockmap

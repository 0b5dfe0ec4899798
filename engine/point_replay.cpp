#include "engine/point_replay.h"

#include <algorithm>
#include <utility>

#include "core/input_error.h"
#include "db/report_queries.h"
#include "db/stored_signals.h"
#include "engine/reference_store.h"
#include "specs/study_file.h"

namespace shockmap {

ReplayedPoint ReplayCanonicalPoint(const std::string& database_path, const std::string& study,
                                   std::int64_t point_id) {
  const std::string what = "point " + std::to_string(point_id) + " of study " + study;
  const auto stored = StoredStudyJson(database_path, study);
  if (!stored) throw InputError("no study named \"" + study + "\" in " + database_path);
  const nlohmann::json& json = *stored;
  if (StudyKindOf(json, database_path) != StudyFileKind::kCanonical) {
    throw InputError(what +
                     ": a scene study's points store no signals; `shockmap export "
                     "reference --point " +
                     std::to_string(point_id) + "` writes its reference's");
  }
  const StudySpec spec = ParseStudySpec(json, database_path);
  const auto key = CanonicalPointKey(database_path, study, point_id);
  const auto reference_id = ReferenceOfPoint(database_path, study, point_id);
  if (!key || !reference_id) throw InputError(what + ": no such scored point in " + database_path);
  const auto point = std::find_if(spec.points.begin(), spec.points.end(),
                                  [&](const StudyPoint& p) { return PointKey(p) == *key; });
  if (point == spec.points.end()) {
    throw InputError(what + ": the stored study no longer lists it");
  }
  const auto reference = ReadReference(database_path, *reference_id);
  if (!reference) throw InputError(what + ": its reference is missing from " + database_path);
  return ReplayStudyPoint(
      spec, *point,
      std::make_shared<const ReferenceRun>(FromReferenceRow(*reference, database_path)));
}

ReplayedPoint ReplayStudyPoint(const StudySpec& spec, const StudyPoint& point,
                               std::shared_ptr<const ReferenceRun> reference) {
  ReplayedPoint replay{{}, ProblemOf(spec, point), OptionsOf(spec, point)};
  replay.result = ScoreAgainstReference(replay.problem, replay.options, std::move(reference));
  return replay;
}

std::shared_ptr<const ReferenceRun> StoredReferenceRuns::Find(const std::string& reference_key) {
  if (const auto found = runs_.find(reference_key); found != runs_.end()) return found->second;
  std::shared_ptr<const ReferenceRun> run;
  if (const auto row = ReadStoredReference(database_path_, reference_key)) {
    run = std::make_shared<const ReferenceRun>(FromReferenceRow(*row, database_path_));
  }
  return runs_[reference_key] = run;
}

}  // namespace shockmap

#pragma once
// A stored point of a study of the paper's problem computed again, for its histories: points
// store their scores, not their signals (docs/database.md), so `shockmap export point` reruns
// the point's numerical scheme against its stored reference. The run is deterministic: its
// scores equal the stored ones.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "compare/comparison.h"
#include "specs/study_spec.h"

namespace shockmap {

struct ReplayedPoint {
  ComparisonResult result;  // Histories of the numerical run and the stored reference.
  CantileverImpact problem;
  ComparisonOptions options;
};

// Throws InputError naming the study and the point when the study is not of the paper's
// problem, or the point is unknown or not scored; DbError as the read-only queries do.
ReplayedPoint ReplayCanonicalPoint(const std::string& database_path, const std::string& study,
                                   std::int64_t point_id);

// `point` of `spec` computed again against `reference`, a reference read from the database,
// with every history recorded: what ReplayCanonicalPoint does once it has found them.
ReplayedPoint ReplayStudyPoint(const StudySpec& spec, const StudyPoint& point,
                               std::shared_ptr<const ReferenceRun> reference);

// The stored references of a database read once each, by reference_key, for replaying many
// points. Throws DbError as the read-only queries do (a corrupt row).
class StoredReferenceRuns {
 public:
  explicit StoredReferenceRuns(std::string database_path)
      : database_path_(std::move(database_path)) {}
  // nullptr when no reference is stored under the key.
  std::shared_ptr<const ReferenceRun> Find(const std::string& reference_key);

 private:
  std::string database_path_;
  std::map<std::string, std::shared_ptr<const ReferenceRun>> runs_;
};

}  // namespace shockmap

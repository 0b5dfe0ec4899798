#pragma once
// The sampled signals stored with references, read on a read-only connection for export. Each
// blob is raw little-endian float64, sample i at t = i * output_dt_s (docs/database.md).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "records/canonical_records.h"

namespace shockmap {

// Signals sampled together: names[i] (with its unit, e.g. "tip_displacement_m") holds
// values[i]; all have the same length.
struct StoredSignals {
  std::int64_t reference_id = 0;
  double output_dt_s = 0.0;
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
};

// The references the scored points of `study` (the paper's problem) at `r_k` are scored
// against, by id; R_k matches within 1e-9 of its value. Throws DbError as RunReadOnlyQuery.
std::vector<std::int64_t> ReferenceIdsAt(const std::string& database_path, const std::string& study,
                                         double r_k);

// The distinct R_k of the scored points of `study` (the paper's problem), ascending. Throws
// DbError as RunReadOnlyQuery.
std::vector<double> ScoredRks(const std::string& database_path, const std::string& study);

// A reference of the paper's problem (table reference_runs), or nothing for an unknown id.
std::optional<ReferenceRow> ReadReference(const std::string& database_path,
                                          std::int64_t reference_id);

// Its tip displacement (m) and contact force (N).
StoredSignals SignalsOf(const ReferenceRow& reference);

// The reference a scored point of `study` is scored against: its id in reference_runs (the
// paper's problem) or scene_references (scene studies), or nothing when the point is unknown
// or not scored.
std::optional<std::int64_t> ReferenceOfPoint(const std::string& database_path,
                                             const std::string& study, std::int64_t point_id);

// A scene study's reference (table scene_references): the scored displacement (m) and the
// scored zone's contact force (N), or nothing for an unknown id.
std::optional<StoredSignals> ReadSceneReferenceSignals(const std::string& database_path,
                                                       std::int64_t reference_id);

// The point_key of a point of `study` (the paper's problem), or nothing when it has none.
std::optional<std::string> CanonicalPointKey(const std::string& database_path,
                                             const std::string& study, std::int64_t point_id);

}  // namespace shockmap

#pragma once
// The stored facts a study's report shows beside its figures, read on a read-only connection.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "db/point_tables.h"
#include "db/read_only_query.h"
#include "records/canonical_records.h"

namespace shockmap {

struct ReportTables {
  Table outcomes;         // scheme, status, points: how many points ended how.
  Table provenance;       // One row per run: code version, compiler, host, times, points done.
  std::string spec_json;  // The study file as stored ("" when the study is unknown).
};

// Throws DbError as RunReadOnlyQuery does.
ReportTables LoadReportTables(const std::string& database_path, const std::string& study);

// Every column of the results view of the kind's table (`results`, `scene_results`, ...) for
// the points of `study`, by point_id.
Table StudyResultRows(const std::string& database_path, const std::string& study,
                      const PointTable& table);

// The keys of each point of a canonical `study`: columns point_id, point_key, reference_key.
Table PointKeys(const std::string& database_path, const std::string& study);

// The stored reference of that key, read on a read-only connection; nothing when none is
// stored. Throws DbError as RunReadOnlyQuery does.
std::optional<ReferenceRow> ReadStoredReference(const std::string& database_path,
                                                const std::string& reference_key);

// The study file stored for `study`, or nothing when no study has that name.
std::optional<std::string> StoredStudySpec(const std::string& database_path,
                                           const std::string& study);

// The same, parsed; DbError "<file>: database corrupt: study <name>: spec_json: <reason>" when
// it is not JSON or nests deeper than kMaxStoredJsonDepth.
std::optional<nlohmann::json> StoredStudyJson(const std::string& database_path,
                                              const std::string& study);

}  // namespace shockmap

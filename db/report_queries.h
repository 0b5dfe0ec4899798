#pragma once
// The stored facts a study's report shows beside its figures, read on a read-only connection.

#include <optional>
#include <string>

#include "db/read_only_query.h"

namespace shockmap {

struct ReportTables {
  QueryResult outcomes;    // scheme, status, points: how many points ended how.
  QueryResult provenance;  // One row per run: code version, compiler, host, times, points done.
  std::string spec_json;   // The study file as stored ("" when the study is unknown).
};

// Throws DbError as RunReadOnlyQuery does.
ReportTables LoadReportTables(const std::string& database_path, const std::string& study);

// The study file stored for `study`, or nothing when no study has that name.
std::optional<std::string> StoredStudySpec(const std::string& database_path,
                                           const std::string& study);

}  // namespace shockmap

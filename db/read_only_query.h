#pragma once
// Arbitrary SQL from users, on a read-only connection: anything that would write is refused.

#include <cstdint>
#include <string>
#include <vector>

#include "db/sqlite_handle.h"
#include "records/table.h"

namespace shockmap {

// Bounds on one statement; 0 lifts a bound.
struct QueryLimits {
  std::int64_t max_rows = 0;  // Rows delivered at most; one more stops the statement.
  double timeout_s = 0.0;     // Wall time from the start of the statement, output included.
};

// A bound of QueryLimits was reached; the rows before it were delivered.
class QueryLimitReached : public DbError {
 public:
  using DbError::DbError;
};

// Runs exactly one statement, binding `parameters` (NULL, integers, reals, texts) to its ?1,
// ?2, ..., and hands its rows to `sink` without holding them. Throws DbError when the file does not
// exist or is not a current shockmap database, the SQL does not compile, holds more than one
// statement, or could write (sqlite3_stmt_readonly); QueryLimitReached when `limits` stop it. The
// connection is read-only (see Connection::Mode::kReadOnly).
void StreamReadOnlyQuery(const std::string& database_path, const std::string& sql,
                         const std::vector<TableCell>& parameters, const QueryLimits& limits,
                         TableSink& sink);

// StreamReadOnlyQuery without limits, its rows collected.
Table RunReadOnlyQuery(const std::string& database_path, const std::string& sql,
                       const std::vector<TableCell>& parameters = {});

}  // namespace shockmap

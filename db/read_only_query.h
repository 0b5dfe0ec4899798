#pragma once
// Arbitrary SQL from users, on a read-only connection: anything that would write is refused.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "db/sqlite_handle.h"

namespace shockmap {

using QueryCell = std::variant<std::monostate, std::int64_t, double, std::string>;

struct QueryResult {
  std::vector<std::string> columns;
  std::vector<std::vector<QueryCell>> rows;
};

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

// Takes a statement's column names once, then its rows one by one as SQLite produces them.
class QueryRowSink {
 public:
  virtual ~QueryRowSink() = default;
  virtual void Columns(const std::vector<std::string>& names) = 0;
  virtual void Row(const std::vector<QueryCell>& row) = 0;
};

// Runs exactly one statement, binding `text_parameters` to its ?1, ?2, ..., and hands its rows
// to `sink` without holding them. Throws DbError when the file does not exist or is not a
// current shockmap database, the SQL does not compile, holds more than one statement, or could
// write (sqlite3_stmt_readonly); QueryLimitReached when `limits` stop it. The connection is
// read-only (see Connection::Mode::kReadOnly).
void StreamReadOnlyQuery(const std::string& database_path, const std::string& sql,
                         const std::vector<std::string>& text_parameters, const QueryLimits& limits,
                         QueryRowSink& sink);

// StreamReadOnlyQuery without limits, its rows collected.
QueryResult RunReadOnlyQuery(const std::string& database_path, const std::string& sql,
                             const std::vector<std::string>& text_parameters = {});

}  // namespace shockmap

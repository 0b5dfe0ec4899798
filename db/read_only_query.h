#pragma once
// Arbitrary SQL from users, on a read-only connection: anything that would write is refused.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace shockmap {

using QueryCell = std::variant<std::monostate, std::int64_t, double, std::string>;

struct QueryResult {
  std::vector<std::string> columns;
  std::vector<std::vector<QueryCell>> rows;
};

// Runs exactly one statement, binding `text_parameters` to its ?1, ?2, ... Throws DbError when
// the file does not exist or is not a current shockmap database, the SQL does not compile,
// holds more than one statement, or could write (sqlite3_stmt_readonly). The connection is
// opened SQLITE_OPEN_READONLY with query_only set.
QueryResult RunReadOnlyQuery(const std::string& database_path, const std::string& sql,
                             const std::vector<std::string>& text_parameters = {});

}  // namespace shockmap

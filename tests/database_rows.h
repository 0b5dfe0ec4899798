#pragma once
// Reading a study database in tests, on read-only connections.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "db/read_only_query.h"
#include "db/sqlite_handle.h"

namespace shockmap::testing {

// The rows of `sql` as the sqlite3 shell prints them: columns joined by '|'.
inline std::vector<std::string> Rows(const std::string& database, const std::string& sql) {
  Connection c(database, Connection::Mode::kReadOnly);
  Statement s = c.Prepare(sql);
  std::vector<std::string> rows;
  while (s.Step()) {
    std::string line;
    for (int i = 0; i < s.ColumnCount(); ++i) line += (i ? "|" : "") + s.GetText(i);
    rows.push_back(line);
  }
  return rows;
}

// The columns of one of Rows' rows (or of a fixture written alike), split at '|'.
inline std::vector<std::string> RowFields(const std::string& row) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t bar; (bar = row.find('|', start)) != std::string::npos; start = bar + 1) {
    fields.push_back(row.substr(start, bar - start));
  }
  fields.push_back(row.substr(start));
  return fields;
}

// The integer `sql` answers (its first row's first column).
inline std::int64_t Count(const std::string& database, const std::string& sql) {
  return std::get<std::int64_t>(RunReadOnlyQuery(database, sql).rows.at(0).at(0));
}

// Implicit full-model points on fine meshes: ~0.1-0.5 s each (~2.5 s in all with 2 jobs), so
// that a second process (an mpirun) starts while the first still runs.
inline constexpr const char* kSlowStudy = R"({
  "name": "slow",
  "scoring": {"window_s": 0.03},
  "grids": [{"rk": [100, 1000, 3000], "rftrunc": 300, "scheme": "implicit-full",
             "n_elements": [150, 200, 250], "dt": {"factor": [0.05, 0.1]}}]
})";

// Eighteen implicit full-model points of ~0.1 s each (Release, 2 jobs: ~1 s in all; ~9 s under
// the sanitizers): a kill or a signal after a few stored points still lands mid-study, at a
// third of kSlowStudy's cost. kSlowStudy stays where a second process must start while the
// first still runs.
inline constexpr const char* kInterruptibleStudy = R"({
  "name": "interruptible",
  "scoring": {"window_s": 0.02},
  "grids": [{"rk": [100, 1000, 3000], "rftrunc": 300, "scheme": "implicit-full",
             "n_elements": [120, 160, 200], "dt": {"factor": [0.05, 0.1]}}]
})";

}  // namespace shockmap::testing

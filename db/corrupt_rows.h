#pragma once
// Checks of rows read back from a study database. A file that was mailed, edited or damaged
// must be refused with DbError "<file>: database corrupt: <row>: <reason>", never used: a
// signal of the wrong length would be read past its end, a wrong sampling step would rescore
// a point against another history.

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "db/sqlite_handle.h"
#include "records/canonical_records.h"
#include "records/columns.h"
#include "records/scene_records.h"
#include "records/table.h"

namespace shockmap {

// Throws DbError "<database_path>: database corrupt: <row>: <reason>".
[[noreturn]] void ThrowCorrupt(const std::string& database_path, const std::string& row,
                               const std::string& reason);

// The text of a cell its column declares TEXT NOT NULL; DbError "<database_path>: database
// corrupt: <row>: <column> holds <what it holds> where text belongs" when the file holds
// something else there (SQLite does not check the constraint on reading).
const std::string& StoredText(const TableCell& cell, const std::string& database_path,
                              const std::string& row, const std::string& column);

// A count stored as an integer from 0 to `max` (modes, steps); DbError "... <column> holds
// <value> (a count from 0 to <max>)" otherwise.
std::int64_t StoredCount(const TableCell& cell, const std::string& database_path,
                         const std::string& row, const std::string& column, std::int64_t max);

// What the check of one stored value knows of its column (records/columns.h).
struct StoredColumn {
  std::string_view name;
  SqlType type;
  bool nullable;
  ValueRange range;
};
template <typename Row>
StoredColumn StoredColumnOf(const Column<Row>& c) {
  return {c.name, c.Type(), c.Nullable(), c.range};
}

// Why `cell` cannot be a value of `column`, or nothing when it can: NULL in a column that may
// not hold it, a value of another type (a REAL column holds integers and reals), a number out
// of the column's range. "r_k is -5 (it must be finite and > 0)", "err is the text \"abc\" (it
// must be a number, in [0, 1] or NULL)".
std::optional<std::string> StoredValueProblem(const TableCell& cell, const StoredColumn& column);
// The same of column i of the statement's current row; a signal's column must hold a blob.
std::optional<std::string> StoredValueProblem(const Statement& s, int i,
                                              const StoredColumn& column);

// Throws DbError "<database_path>: database corrupt: <row>: <problem>" unless each non-blob
// column of `columns` that `table` holds (a query's result, a view's columns by name) holds a
// value of its type and range in row `i`.
void CheckStoredCells(const std::string& database_path, const std::string& row, const Table& table,
                      std::size_t i, const auto& columns) {
  for (const auto& c : columns) {
    const std::optional<std::size_t> at = table.ColumnIndex(c.name);
    if (!at || c.Type() == SqlType::kBlob) continue;
    if (auto problem = StoredValueProblem(table.rows[i][*at], StoredColumnOf(c))) {
      ThrowCorrupt(database_path, row, *problem);
    }
  }
}

// One stored signal, named by its column.
struct StoredSamples {
  std::string_view column;
  const std::vector<double>& values;
};

// Throws unless every value of `signal` is finite.
void CheckFinite(const std::string& database_path, const std::string& row,
                 const StoredSamples& signal);

// Signals sampled together: throws unless every one holds as many samples as the first.
void CheckEqualLengths(const std::string& database_path, const std::string& row,
                       std::initializer_list<StoredSamples> signals);

// Signals sampled together every output_dt_s: throws unless output_dt_s is finite and > 0,
// every signal holds as many samples as the first, and every sample is finite.
void CheckSampledTogether(const std::string& database_path, const std::string& row,
                          double output_dt_s, std::initializer_list<StoredSamples> signals);

// A reference of the paper's problem: its signals sampled together, as many samples as its
// window sampled every output_dt_s holds (as the reference solver samples it).
void CheckReference(const std::string& database_path, const ReferenceRow& reference);

// A scene study's reference: its signals sampled together when it ended 'ok'; of equal lengths
// otherwise (a failed or diverged reference scores nothing, and may hold no signal).
void CheckSceneReference(const std::string& database_path, const SceneReferenceRow& reference);

}  // namespace shockmap

#pragma once
// A record's SQL, derived from its column table (records/columns.h): the column lists of its
// statements, its values bound in column order and its result columns read back into its
// members. Nothing here names a column of any record.

#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

#include "db/corrupt_rows.h"
#include "db/sqlite_handle.h"
#include "records/columns.h"

namespace shockmap {

// "a, b, c": the names of `columns`, each after `prefix` ("p." for a table alias).
std::string ColumnList(const auto& columns, std::string_view prefix = "") {
  std::string list;
  for (const auto& c : columns) {
    list += (list.empty() ? "" : ", ") + std::string(prefix) + std::string(c.name);
  }
  return list;
}

// "?, ?, ?": n parameters.
std::string Placeholders(std::size_t n);

// "a = ?, b = ?": the assignments of an UPDATE of every column.
std::string Assignments(const auto& columns) {
  std::string list;
  for (const auto& c : columns) list += (list.empty() ? "" : ", ") + std::string(c.name) + " = ?";
  return list;
}

// Binds the row's values to ?first, ?first + 1, ... in column order; returns the next index.
template <typename Row>
int BindRecord(Statement& s, int first, const Row& row, const auto& columns) {
  for (const Column<Row>& c : columns) {
    VisitColumn(c, row, [&](const auto& v) { s.Bind(first, v); });
    ++first;
  }
  return first;
}

// Binds NULL to as many parameters as there are columns; returns the next index.
int BindNulls(Statement& s, int first, const auto& columns) {
  for (std::size_t i = 0; i < std::size(columns); ++i) s.BindNull(first++);
  return first;
}

// Reads the current result row's columns first, first + 1, ... into the row's members in column
// order; returns the next column. Each value is checked against its column's type and range
// first: DbError "<database_path>: database corrupt: <row_name()>: <problem>" (db/corrupt_rows.h)
// names the row of a file edited or damaged. A point's parameter values to bind later are its
// cells (CellsOf in records/columns.h).
template <typename Row, typename RowName>
int ReadRecord(const Statement& s, int first, Row& row, const auto& columns,
               const std::string& database_path, const RowName& row_name) {
  for (const Column<Row>& c : columns) {
    if (auto problem = StoredValueProblem(s, first, StoredColumnOf(c))) {
      ThrowCorrupt(database_path, row_name(), *problem);
    }
    VisitColumn(c, row, [&](auto& v) { s.ReadColumn(first, v); });
    ++first;
  }
  return first;
}

}  // namespace shockmap

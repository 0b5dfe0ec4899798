#pragma once
// The neutral table: named columns and rows of cells, whatever produced them (a query of the
// study database, a record's columns, the sizing statistics) and whatever writes them (the
// aligned table, CSV and JSON of formats/table_output.h, the report's HTML tables).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace shockmap {

// One value: NULL, an integer, a real or a text.
using TableCell = std::variant<std::monostate, std::int64_t, double, std::string>;

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<TableCell>> rows;

  // The index of the column named `name`, or nothing when there is none.
  std::optional<std::size_t> ColumnIndex(std::string_view name) const;
};

// Takes a table's column names once, then its rows one by one as they are produced.
class TableSink {
 public:
  virtual ~TableSink() = default;
  virtual void Columns(const std::vector<std::string>& names) = 0;
  virtual void Row(const std::vector<TableCell>& row) = 0;
};

// One row of a table read by column name, never by position: the reader names what it reads,
// and a column added before it leaves the reader right.
class NamedRow {
 public:
  NamedRow(const Table& table, std::size_t row) : table_(table), row_(row) {}
  // The cell of the column `name`. Throws std::out_of_range when the table has no such column
  // (the statement that produced it does not select it: a broken invariant of the reader).
  const TableCell& operator[](std::string_view name) const;

 private:
  const Table& table_;
  std::size_t row_;
};

// A real or integer cell as a double; nothing for NULL or text.
std::optional<double> NumberIn(const TableCell& cell);

}  // namespace shockmap

#pragma once
// A table (records/table.h: a query's result, a record's columns, sizing statistics) as an
// aligned table, CSV (RFC 4180) or a JSON array of objects, written row by row as they come.

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "records/table.h"

namespace shockmap {

enum class TableFormat { kTable, kCsv, kJson };
std::string ToString(TableFormat f);
std::optional<TableFormat> TableFormatFromString(std::string_view s);

// Rows held back by the table format to size its columns.
constexpr std::size_t kTableLookAhead = 1000;

// Writes each row as it arrives, holding none but the table format's look-ahead: its column
// widths come from the header and the first kTableLookAhead rows; a longer value after them
// widens its own cell only. Finish() ends the output (the table's row count, JSON's bracket).
class TableWriter : public TableSink {
 public:
  TableWriter(TableFormat format, std::ostream& out) : format_(format), out_(out) {}
  void Columns(const std::vector<std::string>& names) override;
  void Row(const std::vector<TableCell>& row) override;
  void Finish();

 private:
  void TableLine(const std::vector<std::string>& cells);
  void FlushLookAhead();

  TableFormat format_;
  std::ostream& out_;
  std::vector<std::string> columns_;
  std::vector<std::size_t> width_;
  std::vector<std::vector<std::string>> held_;
  bool widths_fixed_ = false;
  std::size_t rows_ = 0;
};

void WriteTable(const Table& result, TableFormat format, std::ostream& out);

}  // namespace shockmap

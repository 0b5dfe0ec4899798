#include "records/table.h"

#include <algorithm>
#include <stdexcept>

namespace shockmap {

std::optional<std::size_t> Table::ColumnIndex(std::string_view name) const {
  const auto found = std::ranges::find(columns, name);
  if (found == columns.end()) return std::nullopt;
  return static_cast<std::size_t>(found - columns.begin());
}

const TableCell& NamedRow::operator[](std::string_view name) const {
  const auto column = table_.ColumnIndex(name);
  if (!column) throw std::out_of_range("no column named " + std::string(name) + " in the table");
  return table_.rows.at(row_).at(*column);
}

std::optional<double> NumberIn(const TableCell& cell) {
  if (const auto* d = std::get_if<double>(&cell)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&cell)) return static_cast<double>(*i);
  return std::nullopt;
}

}  // namespace shockmap

#pragma once
// A stored record's columns, declared once. A record is a plain struct (a score row, a
// reference row, a point's parameters); its column table lists, for each column, the member
// that holds it, its SQL name, its unit and a one-line meaning. Everything else is derived from
// that table: the SQL that writes and reads the record (db/stored_record.h), its bytes between
// MPI ranks (engine/record_codec.h), its cells in a neutral table (CSV and JSON, below) and the
// column tables of docs/database.md (checked by tests/records_test.cpp).
//
// A column's SQL type and nullability follow from its member's type: INTEGER for int and
// std::int64_t, REAL for double, TEXT for std::string, BLOB for a sampled signal
// (std::vector<double>, little-endian float64); an std::optional member may be NULL.

#include <cstdint>
#include <optional>
#include <ranges>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "records/table.h"

namespace shockmap {

template <typename Row>
using ColumnMember = std::variant<int Row::*, std::int64_t Row::*, double Row::*,
                                  std::string Row::*, std::vector<double> Row::*,
                                  std::optional<int> Row::*, std::optional<std::int64_t> Row::*,
                                  std::optional<double> Row::*, std::optional<std::string> Row::*>;

enum class SqlType { kInteger, kReal, kText, kBlob };
// "INTEGER", "REAL", "TEXT", "BLOB", as SQLite's table_info names them.
std::string_view ToString(SqlType type);

namespace detail {
template <typename T>
struct ColumnValue {
  using Type = T;
  static constexpr bool kNullable = false;
};
template <typename T>
struct ColumnValue<std::optional<T>> {
  using Type = T;
  static constexpr bool kNullable = true;
};
template <typename T>
constexpr SqlType SqlTypeOf() {
  using V = typename ColumnValue<T>::Type;
  if constexpr (std::is_integral_v<V>) {
    return SqlType::kInteger;
  } else if constexpr (std::is_floating_point_v<V>) {
    return SqlType::kReal;
  } else if constexpr (std::is_same_v<V, std::string>) {
    return SqlType::kText;
  } else {
    static_assert(std::is_same_v<V, std::vector<double>>);
    return SqlType::kBlob;
  }
}
template <typename Row, typename T>
T MemberType(T Row::*);
}  // namespace detail

// What a stored number may be beyond its column's type, checked whenever a stored row is read
// (db/corrupt_rows.h: a file edited or damaged is refused naming the row, never used).
enum class ValueRange {
  kAny,          // Any number of the column's type.
  kFinite,       // Finite.
  kNonNegative,  // Finite and >= 0: counts, times measured, bounds where a run may have none.
  kPositive,     // Finite and > 0: ratios of the model, time steps and windows asked.
  kFraction,     // In [0, 1]: the scores (min/max ratios and Err).
};
bool Contains(ValueRange range, double value);
// "finite and > 0", "in [0, 1]", ...: what the range allows, for a message.
std::string_view Allowed(ValueRange range);

template <typename Row>
struct Column {
  using Record = Row;
  std::string_view name;  // In SQL, and in a table of rows (CSV, JSON).
  ColumnMember<Row> member;
  std::string_view unit;     // SI ("s", "m", "N", "N s", "W"); "" for counts, ratios, text.
  std::string_view meaning;  // One line, as docs/database.md shows it.
  ValueRange range = ValueRange::kAny;  // Of a numeric column: what a stored value may be.

  SqlType Type() const {
    return std::visit([](auto m) { return detail::SqlTypeOf<decltype(detail::MemberType(m))>(); },
                      member);
  }
  bool Nullable() const {
    return std::visit(
        [](auto m) { return detail::ColumnValue<decltype(detail::MemberType(m))>::kNullable; },
        member);
  }
};

// The record type of a column table (an array or span of Column<Row>).
template <typename ColumnTable>
using RecordOf = typename std::ranges::range_value_t<ColumnTable>::Record;

// Calls f with the member of `row` that `column` holds (a const reference for a const row).
template <typename Row, typename F>
decltype(auto) VisitColumn(const Column<std::remove_const_t<Row>>& column, Row& row, F&& f) {
  return std::visit([&](auto member) -> decltype(auto) { return f(row.*member); }, column.member);
}

// The names of a column table (an array or span of Column<Row>), in order.
std::vector<std::string> ColumnNames(const auto& columns) {
  std::vector<std::string> names;
  for (const auto& c : columns) names.emplace_back(c.name);
  return names;
}

// The column named `name`, or null.
template <typename ColumnTable>
const Column<RecordOf<ColumnTable>>* FindColumn(const ColumnTable& columns, std::string_view name) {
  for (const auto& c : columns) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

// The member of the optional real column named `name` (a score's), or null when the record has
// no such column.
template <typename ColumnTable, typename Row = RecordOf<ColumnTable>>
std::optional<double> Row::*OptionalRealMember(const ColumnTable& columns, std::string_view name) {
  const Column<Row>* c = FindColumn(columns, name);
  if (c == nullptr) return nullptr;
  const auto* member = std::get_if<std::optional<double> Row::*>(&c->member);
  return member != nullptr ? *member : nullptr;
}

namespace detail {
inline TableCell CellOf(int v) { return std::int64_t{v}; }
inline TableCell CellOf(std::int64_t v) { return v; }
inline TableCell CellOf(double v) { return v; }
inline TableCell CellOf(const std::string& v) { return v; }
// A signal has no cell of its own: its size, as a query of the database shows a blob.
inline TableCell CellOf(const std::vector<double>& v) {
  return "<blob " + std::to_string(v.size()) + " doubles>";
}
template <typename T>
TableCell CellOf(const std::optional<T>& v) {
  return v ? CellOf(*v) : TableCell();
}
}  // namespace detail

// The row's values in column order: what a table of these rows holds (formats/table_output.h
// writes it as CSV or JSON).
template <typename Row>
std::vector<TableCell> CellsOf(const Row& row, const auto& columns) {
  std::vector<TableCell> cells;
  for (const Column<Row>& c : columns) {
    cells.push_back(VisitColumn(c, row, [](const auto& v) { return detail::CellOf(v); }));
  }
  return cells;
}

// A table of `rows`, one column per declared column.
template <typename Row>
Table TableOf(const std::vector<Row>& rows, const auto& columns) {
  Table table{ColumnNames(columns), {}};
  for (const Row& row : rows) table.rows.push_back(CellsOf(row, columns));
  return table;
}

}  // namespace shockmap

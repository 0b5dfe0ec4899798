#pragma once
// The columns of a value as it leaves the library (a shock, a zone's impact statistics, an
// impact; compare/output_columns.h), declared once as a stored record's are (records/columns.h):
// each column its name, unit, meaning and the function that reads it from the value. The CSV
// header and rows, the JSON objects and the Python dicts are derived from that table
// (formats/output_values.h, python/); no header is written by hand.

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "records/columns.h"  // ColumnNames, for these tables too.

namespace shockmap {

// One value of an output column: none (an empty CSV field, JSON null, Python None), a flag (1 or
// 0 in CSV, true or false elsewhere), an integer, a real or a text.
using OutputValue = std::variant<std::monostate, bool, std::int64_t, double, std::string>;

template <typename T>
struct OutputColumn {
  std::string_view name;  // The CSV header's, the JSON key, the Python dict's key.
  OutputValue (*value)(const T&);
  std::string_view unit;     // SI ("s", "N", "N s"); "" for counts, ratios and text.
  std::string_view meaning;  // One line, as the docs show it.
};

// The values of `x` in column order.
template <typename T, typename Columns>
std::vector<OutputValue> OutputValuesOf(const T& x, const Columns& columns) {
  std::vector<OutputValue> values;
  for (const OutputColumn<T>& c : columns) values.push_back(c.value(x));
  return values;
}

namespace detail {

// Whether a member holding `Held` takes an output value of type V: a text a text, a real a real,
// a flag or an integer any number.
template <typename Held, typename V>
constexpr bool kTakes = std::is_same_v<V, std::string> ? std::is_same_v<Held, std::string>
                        : std::is_floating_point_v<V>  ? std::is_floating_point_v<Held>
                                                       : std::is_arithmetic_v<Held>;

// `member` set to `value`: none empties an optional member; a flag, an integer, a real or a text
// is assigned to a member that takes it (a flag as 0 or 1). Throws std::logic_error for a value
// the member cannot hold: a record and an output declared apart that disagree on a column.
template <typename Member>
void AssignOutputValue(Member& member, const OutputValue& value, std::string_view name) {
  std::visit(
      [&](const auto& v) {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, std::monostate>) {
          if constexpr (ColumnValue<Member>::kNullable) {
            member.reset();
          } else {
            throw std::logic_error("output column " + std::string(name) +
                                   " is none where its record's column cannot be NULL");
          }
        } else if constexpr (kTakes<typename ColumnValue<Member>::Type, V>) {
          member = static_cast<typename ColumnValue<Member>::Type>(v);
        } else {
          throw std::logic_error("output column " + std::string(name) +
                                 " does not fit its record's column");
        }
      },
      value);
}

}  // namespace detail

// Sets each column of `record` whose name an output column of `x` has (but those in `except`)
// to that output's value: a record filled from the declarations that write `x` to CSV and JSON
// instead of member by member, so that a value added to both tables reaches the database by
// itself. The record's other columns are left as they are.
template <typename Record, typename T>
void SetColumnsFromOutputs(Record& record, const auto& record_columns, const T& x,
                           const auto& output_columns,
                           std::initializer_list<std::string_view> except = {}) {
  for (const Column<Record>& column : record_columns) {
    if (std::ranges::find(except, column.name) != except.end()) continue;
    for (const OutputColumn<T>& output : output_columns) {
      if (output.name != column.name) continue;
      VisitColumn(column, record, [&](auto& member) {
        detail::AssignOutputValue(member, output.value(x), output.name);
      });
    }
  }
}

}  // namespace shockmap

#pragma once
// The columns of a value as it leaves the library (a shock, a zone's impact statistics, an
// impact; compare/output_columns.h), declared once as a stored record's are (records/columns.h):
// each column its name, unit, meaning and the function that reads it from the value. The CSV
// header and rows, the JSON objects and the Python dicts are derived from that table
// (formats/output_values.h, python/); no header is written by hand.

#include <cstdint>
#include <string>
#include <string_view>
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

}  // namespace shockmap

#pragma once
// Output columns' values (records/output_columns.h) as CSV and JSON: the header and rows of a
// CSV file and the members of a JSON object, all from one column table.

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

#include "records/columns.h"
#include "records/output_columns.h"

namespace shockmap {

// A value as JSON: null, true or false, a number or a string.
nlohmann::json JsonOf(const OutputValue& value);

// Writes `values` as the fields of a CSV row, without its end: none as an empty field, a flag as
// 1 or 0, a number as the stream writes it (formats/output_file.h: the shortest digits that read
// back), a text quoted where it must be.
void WriteCsvFields(std::ostream& out, const std::vector<OutputValue>& values);

// The table's names as a CSV header's fields, without its end: "start_s,end_s,...".
std::string CsvHeaderOf(const auto& columns) {
  std::string header;
  for (const std::string& name : ColumnNames(columns)) header += (header.empty() ? "" : ",") + name;
  return header;
}

// `x` as a JSON object, one member per column.
template <typename T, typename Columns>
nlohmann::json JsonObjectOf(const T& x, const Columns& columns) {
  nlohmann::json object = nlohmann::json::object();
  for (const OutputColumn<T>& c : columns) object[std::string(c.name)] = JsonOf(c.value(x));
  return object;
}

}  // namespace shockmap

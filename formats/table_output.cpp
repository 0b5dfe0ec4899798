#include "formats/table_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "formats/output_file.h"

namespace shockmap {

std::string ToString(TableFormat f) {
  switch (f) {
    case TableFormat::kTable:
      return "table";
    case TableFormat::kCsv:
      return "csv";
    case TableFormat::kJson:
      return "json";
  }
  return "unknown";
}

std::optional<TableFormat> TableFormatFromString(std::string_view s) {
  for (auto f : {TableFormat::kTable, TableFormat::kCsv, TableFormat::kJson}) {
    if (ToString(f) == s) return f;
  }
  return std::nullopt;
}

namespace {

std::string Text(const TableCell& c) {
  struct {
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    // Shortest digits that read back as the same double, so that a printed value can be
    // pasted into a WHERE clause or parsed by another tool without loss.
    std::string operator()(double v) const { return fmt::format("{}", v); }
    std::string operator()(const std::string& v) const { return v; }
  } visitor;
  return std::visit(visitor, c);
}

nlohmann::json CellJson(const TableCell& c) {
  struct {
    nlohmann::json operator()(std::monostate) const { return nullptr; }
    nlohmann::json operator()(std::int64_t v) const { return v; }
    // JSON has no infinity or NaN: they are written as the strings the CSV and the table show
    // ("inf", "-inf", "nan"), never as null, which reads as a missing value.
    nlohmann::json operator()(double v) const {
      return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(fmt::format("{}", v));
    }
    nlohmann::json operator()(const std::string& v) const { return v; }
  } visitor;
  return std::visit(visitor, c);
}

std::string Indented(const std::string& text) {
  std::string out = "  ";
  for (char c : text) out += c == '\n' ? std::string("\n  ") : std::string(1, c);
  return out;
}

}  // namespace

void TableWriter::Columns(const std::vector<std::string>& names) {
  columns_ = names;
  if (format_ == TableFormat::kCsv) {
    for (std::size_t i = 0; i < names.size(); ++i) out_ << (i ? "," : "") << CsvField(names[i]);
    out_ << '\n';
  }
  for (const auto& name : names) width_.push_back(name.size());
}

void TableWriter::Row(const std::vector<TableCell>& row) {
  const std::size_t n = columns_.size();
  if (format_ == TableFormat::kJson) {
    nlohmann::json o = nlohmann::json::object();
    for (std::size_t i = 0; i < n; ++i) o[columns_[i]] = CellJson(row[i]);
    out_ << (rows_ == 0 ? "[\n" : ",\n") << Indented(o.dump(2));
  } else if (format_ == TableFormat::kCsv) {
    for (std::size_t i = 0; i < n; ++i) out_ << (i ? "," : "") << CsvField(Text(row[i]));
    out_ << '\n';
  } else {
    std::vector<std::string> cells;
    for (std::size_t i = 0; i < n; ++i) cells.push_back(Text(row[i]));
    if (widths_fixed_) {
      TableLine(cells);
    } else {
      for (std::size_t i = 0; i < n; ++i) width_[i] = std::max(width_[i], cells[i].size());
      held_.push_back(std::move(cells));
      if (held_.size() == kTableLookAhead) FlushLookAhead();
    }
  }
  ++rows_;
}

void TableWriter::TableLine(const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    out_ << (i ? "  " : "") << cells[i]
         << std::string(width_[i] - std::min(width_[i], cells[i].size()), ' ');
  }
  out_ << '\n';
}

void TableWriter::FlushLookAhead() {
  TableLine(columns_);
  std::vector<std::string> rule;
  for (std::size_t w : width_) rule.emplace_back(w, '-');
  TableLine(rule);
  for (const auto& cells : held_) TableLine(cells);
  held_.clear();
  widths_fixed_ = true;
}

void TableWriter::Finish() {
  if (format_ == TableFormat::kJson) {
    out_ << (rows_ == 0 ? "[]\n" : "\n]\n");
  } else if (format_ == TableFormat::kTable) {
    if (!widths_fixed_) FlushLookAhead();
    out_ << "(" << rows_ << " row" << (rows_ == 1 ? "" : "s") << ")\n";
  }
}

void WriteTable(const Table& result, TableFormat format, std::ostream& out) {
  TableWriter writer(format, out);
  writer.Columns(result.columns);
  for (const auto& row : result.rows) writer.Row(row);
  writer.Finish();
}

}  // namespace shockmap

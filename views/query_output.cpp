#include "views/query_output.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

namespace shockmap {

std::string ToString(QueryFormat f) {
  switch (f) {
    case QueryFormat::kTable:
      return "table";
    case QueryFormat::kCsv:
      return "csv";
    case QueryFormat::kJson:
      return "json";
  }
  return "unknown";
}

std::optional<QueryFormat> QueryFormatFromString(std::string_view s) {
  for (auto f : {QueryFormat::kTable, QueryFormat::kCsv, QueryFormat::kJson}) {
    if (ToString(f) == s) return f;
  }
  return std::nullopt;
}

namespace {

std::string Text(const QueryCell& c) {
  struct {
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(double v) const {
      std::ostringstream s;
      s.precision(10);
      s << v;
      return s.str();
    }
    std::string operator()(const std::string& v) const { return v; }
  } visitor;
  return std::visit(visitor, c);
}

nlohmann::json Json(const QueryCell& c) {
  struct {
    nlohmann::json operator()(std::monostate) const { return nullptr; }
    nlohmann::json operator()(std::int64_t v) const { return v; }
    nlohmann::json operator()(double v) const { return v; }
    nlohmann::json operator()(const std::string& v) const { return v; }
  } visitor;
  return std::visit(visitor, c);
}

std::string CsvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

void WriteQueryResult(const QueryResult& result, QueryFormat format, std::ostream& out) {
  const std::size_t n = result.columns.size();
  if (format == QueryFormat::kJson) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : result.rows) {
      nlohmann::json o = nlohmann::json::object();
      for (std::size_t i = 0; i < n; ++i) o[result.columns[i]] = Json(row[i]);
      rows.push_back(std::move(o));
    }
    out << rows.dump(2) << '\n';
    return;
  }
  if (format == QueryFormat::kCsv) {
    for (std::size_t i = 0; i < n; ++i) out << (i ? "," : "") << CsvField(result.columns[i]);
    out << '\n';
    for (const auto& row : result.rows) {
      for (std::size_t i = 0; i < n; ++i) out << (i ? "," : "") << CsvField(Text(row[i]));
      out << '\n';
    }
    return;
  }
  std::vector<std::size_t> width(n);
  for (std::size_t i = 0; i < n; ++i) width[i] = result.columns[i].size();
  for (const auto& row : result.rows) {
    for (std::size_t i = 0; i < n; ++i) width[i] = std::max(width[i], Text(row[i]).size());
  }
  auto line = [&](auto cell) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::string s = cell(i);
      out << (i ? "  " : "") << s << std::string(width[i] - s.size(), ' ');
    }
    out << '\n';
  };
  line([&](std::size_t i) { return result.columns[i]; });
  line([&](std::size_t i) { return std::string(width[i], '-'); });
  for (const auto& row : result.rows) line([&](std::size_t i) { return Text(row[i]); });
  out << "(" << result.rows.size() << " row" << (result.rows.size() == 1 ? "" : "s") << ")\n";
}

}  // namespace shockmap

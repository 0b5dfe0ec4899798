#include "views/setting_legend.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "views/html_text.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// A setting's value as an engineer writes it: a real to 10 significant digits, which hides the
// last bits of a computed one; anything else as in JSON.
std::string ValueText(const Json& value) {
  return value.is_number_float() ? fmt::format("{:.10g}", value.get<double>()) : value.dump();
}

// The legend's lines of one setting, numbered `label`: one "path = value" a line.
std::string LegendOf(const std::string& label, const std::string& setting_json) {
  const Json setting = Json::parse(setting_json, nullptr, false);
  if (setting == Json::object()) return fmt::format("  {:<3}the scene's own\n", label);
  if (!setting.is_object()) return fmt::format("  {:<3}{}\n", label, setting_json);
  std::string lines;
  for (const auto& [path, value] : setting.items()) {
    lines += fmt::format("  {:<3}{} = {}\n", lines.empty() ? label : "", path, ValueText(value));
  }
  return lines;
}

}  // namespace

LabelledSettings LabelSettings(Table table) {
  const auto column = table.ColumnIndex("setting_json");
  if (!column) return {std::move(table), ""};
  // Each study's settings in the order of their values.
  std::map<std::string, std::vector<std::pair<Json, std::string>>> settings;
  for (const auto& row : table.rows) {
    auto& known = settings[CellText(row[0])];
    const std::string text = CellText(row[*column]);
    if (std::ranges::none_of(known, [&](const auto& s) { return s.second == text; })) {
      known.emplace_back(Json::parse(text, nullptr, false), text);
    }
  }
  std::map<std::pair<std::string, std::string>, std::int64_t> labels;
  std::string legend;
  for (auto& [study, known] : settings) {
    std::ranges::sort(known);
    legend += fmt::format("settings of {}:\n", study);
    for (std::size_t i = 0; i < known.size(); ++i) {
      labels[{study, known[i].second}] = static_cast<std::int64_t>(i + 1);
      legend += LegendOf(std::to_string(i + 1), known[i].second);
    }
  }
  for (auto& row : table.rows) row[*column] = labels.at({CellText(row[0]), CellText(row[*column])});
  std::ranges::stable_sort(table.rows, [&](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.begin(), a.begin() + *column + 1, b.begin(),
                                        b.begin() + *column + 1);
  });
  table.columns[*column] = "setting";
  return {std::move(table), legend};
}

}  // namespace shockmap

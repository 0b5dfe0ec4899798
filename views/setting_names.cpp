#include "views/setting_names.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "views/html_text.h"

namespace shockmap {

std::string SettingName(const GroupSizing& g, const Scene& scene, bool several) {
  const auto setting = nlohmann::json::parse(g.setting_json, nullptr, false);
  std::string name;
  if (setting.is_object()) {
    for (const auto& [path, value] : setting.items()) {
      name += fmt::format("{}{} = {}", name.empty() ? "" : ", ", path, value.dump());
    }
  }
  if (name.empty()) {
    const SceneSolver& solver = scene.solver;
    const std::string truncation = solver.f_trunc_hz
                                       ? fmt::format("f_trunc = {:g} Hz", *solver.f_trunc_hz)
                                       : fmt::format("R_ftrunc = {:g}", solver.r_ftrunc);
    const std::string dt =
        solver.dt.dt_s ? fmt::format("dt = {:g} s", *solver.dt.dt_s)
                       : fmt::format("dt = {:g} dt_{}", solver.dt.factor, ToString(solver.dt.rule));
    name = "the scene's own: " + truncation + ", " + dt;
  }
  return several && g.refined ? name + " (refined)" : name;
}

Table WithSettingNames(Table table, const EnsembleSizing& s, const Scene& scene) {
  const auto column = std::ranges::find(table.columns, "setting") - table.columns.begin();
  if (static_cast<std::size_t>(column) == table.columns.size()) return table;
  std::set<std::string> settings;
  for (const GroupSizing& g : s.groups) settings.insert(g.setting_json);
  std::map<std::string, std::string> names;
  for (const GroupSizing& g : s.groups) {
    names[g.setting_json + (g.refined ? " (refined)" : "")] =
        SettingName(g, scene, settings.size() > 1);
    // The terminal's table marks the refined setting in its "agrees" column instead.
    names.try_emplace(g.setting_json, SettingName(g, scene, false));
  }
  for (auto& row : table.rows) {
    if (const auto name = names.find(CellText(row[column])); name != names.end()) {
      row[column] = name->second;
    }
  }
  return table;
}

std::optional<std::string> TakeSingleSetting(Table& table) {
  const auto column = std::ranges::find(table.columns, "setting") - table.columns.begin();
  if (static_cast<std::size_t>(column) == table.columns.size() || table.rows.empty()) {
    return std::nullopt;
  }
  const std::string setting = CellText(table.rows.front()[column]);
  if (std::ranges::any_of(table.rows,
                          [&](const auto& row) { return CellText(row[column]) != setting; })) {
    return std::nullopt;
  }
  table.columns.erase(table.columns.begin() + column);
  for (auto& row : table.rows) row.erase(row.begin() + column);
  return setting;
}

}  // namespace shockmap

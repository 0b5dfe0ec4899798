#pragma once
// An ensemble's numerical settings as an engineer names them (docs/ensembles.md, "Sizing"): the
// scene's own solver settings when the study has one setting ("the scene's own: R_ftrunc = 300,
// dt = 0.1 dt_sharp"), else the swept values ("solver.r_ftrunc = 1000"), the refined one
// marked " (refined)". The terminal's tables, the CSV files of `sizing --out` and the report
// name settings so; `sizing --format csv|json` keeps the stored setting JSON for scripts.

#include <optional>
#include <string>

#include "analysis/ensemble_sizing.h"
#include "core/scene.h"
#include "db/read_only_query.h"

namespace shockmap {

// `g`'s setting; `several`: the study has more than one setting (the refined one is marked).
std::string SettingName(const GroupSizing& g, const Scene& scene, bool several);

// `table` with its "setting" cells (the stored setting JSON, " (refined)" after the refined
// one, as the sizing tables write them, or without it on the terminal's table) replaced by
// SettingName; a table without a "setting" column unchanged.
Table WithSettingNames(Table table, const EnsembleSizing& sizing, const Scene& scene);

// `table` without its "setting" column when every row holds the same setting, and that setting
// (for a caption: a column would repeat it on every row); nullopt, and the table unchanged,
// when the rows hold several settings or the table has no such column.
std::optional<std::string> TakeSingleSetting(Table& table);

}  // namespace shockmap

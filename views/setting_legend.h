#pragma once
// An ensemble's stored settings on the terminal without their JSON: a short label in the table,
// the setting itself once in a legend beneath (`study status`).

#include <string>

#include "records/table.h"

namespace shockmap {

struct LabelledSettings {
  Table table;         // The "setting_json" column renamed "setting", each cell its label.
  std::string legend;  // Each study's labels with their settings; empty without such a column.
};

// `table` (whose first column is "study") with each stored setting of its column
// "setting_json" ({"solver.r_ftrunc":30,...}) replaced by its number within its study, 1, 2,
// ... in the order of the settings' values, and its rows ordered by that number after the
// columns before it. The legend lists, per study, each number with its setting, one
// "path = value" a line, numbers to 10 significant digits (0.09999999999999999 is 0.1).
LabelledSettings LabelSettings(Table table);

}  // namespace shockmap

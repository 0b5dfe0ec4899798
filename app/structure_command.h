#pragma once
// `shockmap structure import` (a CalculiX deck made a structure's Matrix Market and CSV files)
// and `shockmap structure modes` (its lowest frequencies), docs/structures.md.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddStructureCommand(CLI::App& app);

}  // namespace shockmap

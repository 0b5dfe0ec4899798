#pragma once
// Views of a stored study: `shockmap plot fig4`, `cost` and `advise`.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddViewCommands(CLI::App& app);

}  // namespace shockmap

#pragma once
// `shockmap sizing`: the sizing statistics of an ensemble study (docs/ensembles.md).

#include <CLI/CLI.hpp>

namespace shockmap {

void AddSizingCommand(CLI::App& app);

}  // namespace shockmap

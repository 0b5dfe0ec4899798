#pragma once
// `shockmap map`: validity maps of a study.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddMapCommand(CLI::App& app);

}  // namespace shockmap

#pragma once
// `shockmap criteria derive|check`: validity criteria from the database, and regression checks.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddCriteriaCommand(CLI::App& app);

}  // namespace shockmap

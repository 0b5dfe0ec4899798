#pragma once
// `shockmap export`: a stored reference's signals, or a stored point's histories, as CSV.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddExportCommand(CLI::App& app);

}  // namespace shockmap

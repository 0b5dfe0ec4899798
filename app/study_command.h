#pragma once
// `shockmap study run|status` and `shockmap query`: studies into the database and out of it.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddStudyCommand(CLI::App& app);
void AddQueryCommand(CLI::App& app);

}  // namespace shockmap

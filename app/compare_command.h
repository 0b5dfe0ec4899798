#pragma once
// `shockmap compare`: one numerical run against the reference, scored (paper §2.4).

#include <CLI/CLI.hpp>

namespace shockmap {

// Registers the subcommand on `app`; its callback runs the comparison and prints the result.
void AddCompareCommand(CLI::App& app);

}  // namespace shockmap

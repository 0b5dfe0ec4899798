#pragma once
// `shockmap diff A B`: two stored studies of the paper's problem compared (views/study_diff.h).

#include <CLI/CLI.hpp>

namespace shockmap {

void AddDiffCommand(CLI::App& app);

}  // namespace shockmap

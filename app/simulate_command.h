#pragma once
// `shockmap simulate SCENE.json [--out DIR] [--json]`: one run of a scene file.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddSimulateCommand(CLI::App& app);

}  // namespace shockmap

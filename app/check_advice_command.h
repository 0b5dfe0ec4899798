#pragma once
// `shockmap check-advice STUDY.json`: the advice for an ensemble study's scene checked on its
// members (docs/ensembles.md, "Advice checked on the bundle"): the ensemble run at the advised
// settings, one rung coarser and finer rungs until the sizing statistics stop moving, and the
// verdict per state and zone family.

#include <CLI/CLI.hpp>

namespace shockmap {

void AddCheckAdviceCommand(CLI::App& app);

}  // namespace shockmap

#pragma once
// CLI11 validators whose messages name the value and what is allowed; CLI11 prefixes the flag.

#include <CLI/CLI.hpp>

namespace shockmap {

struct CriteriaOptions;
struct SceneFileAccess;

// --err-max and --srf-min, the thresholds validity is judged with.
void AddThresholdFlags(CLI::App* command, CriteriaOptions& thresholds);

// --allow-path DIR (repeatable): a folder outside the scene's own from which its data files may
// be read.
void AddAllowPathFlag(CLI::App* command, SceneFileAccess& access);

// A finite number > lo (strict) or >= lo.
CLI::Validator FiniteAbove(double lo, bool strict);
inline CLI::Validator Positive() { return FiniteAbove(0.0, true); }

}  // namespace shockmap

#pragma once
// Runs gnuplot on a script; every plot of the project goes through here.

#include <filesystem>
#include <string>

namespace shockmap {

// Writes `script` to script_file and runs `gnuplot script_file`. Throws std::runtime_error
// with gnuplot's exit status when it fails or is not installed.
void RunGnuplot(const std::string& script, const std::filesystem::path& script_file);

}  // namespace shockmap

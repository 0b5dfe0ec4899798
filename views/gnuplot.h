#pragma once
// Runs gnuplot on a script; every plot of the project goes through here.

#include <filesystem>
#include <string>

namespace shockmap {

// Writes `script` to script_file and runs `gnuplot script_file`. Throws std::runtime_error
// with gnuplot's exit status when it fails or is not installed.
// "pngcairo size W,H ..." or "svg size W,H ...": the gnuplot terminal for a file's extension.
// Throws InputError for any other extension.
std::string TerminalFor(const std::filesystem::path& file, int width, int height);

void RunGnuplot(const std::string& script, const std::filesystem::path& script_file);

}  // namespace shockmap

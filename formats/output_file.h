#pragma once
// Output files of the commands: created with their directory, written fully or reported.

#include <filesystem>
#include <fstream>
#include <string>

namespace shockmap {

// Creates `dir` and its parents. Throws InputError naming it when that fails.
void CreateOutputDirectory(const std::filesystem::path& dir);

// Opens `file` for writing with 12 significant digits. Throws InputError naming it.
std::ofstream OpenForWriting(const std::filesystem::path& file);

// Closes `out` and checks every write went through. Throws InputError naming `file`.
void CloseWritten(std::ofstream& out, const std::filesystem::path& file);

// A CSV field: quoted (with doubled quotes) when it holds a comma, a quote or a line break.
std::string CsvField(const std::string& text);

}  // namespace shockmap

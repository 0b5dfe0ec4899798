#pragma once
// Stored signals as a CSV file for users' own tools: t_s, then one column per signal, every
// number in the shortest digits that read back as the stored double.

#include <filesystem>

#include "db/stored_signals.h"

namespace shockmap {

// Writes `path` (its folder created) atomically. Throws InputError naming the file.
void WriteSignalsCsv(const StoredSignals& signals, const std::filesystem::path& path);

}  // namespace shockmap

#pragma once
// CSV files of the histories of one comparison, for plotting and for users' own tools.

#include <filesystem>

#include "compare/comparison.h"

namespace shockmap {

// Writes DIR/numerical.csv (t_s, tip_displacement_m, tip_velocity_m_s, contact_force_n and the
// energies in J) and DIR/reference.csv (t_s, tip_displacement_m, contact_force_n), creating DIR.
// Precondition: the histories were recorded RecordedHistories::kAll (std::logic_error if not).
// Throws InputError naming the file when it cannot be written.
void WriteComparisonCsv(const ComparisonResult& result, const std::filesystem::path& dir);

}  // namespace shockmap

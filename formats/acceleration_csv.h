#pragma once
// Base-motion acceleration tables (CSV): a header "t_s,a_m_s2", then rows "t,a" with times
// strictly increasing and every value finite; blank lines are skipped, CRLF is accepted.

#include <istream>
#include <string>

#include "core/scene.h"

namespace shockmap {

// Appends the rows of `in` to base.table_t_s and base.table_a_m_s2. Throws InputError naming
// `name` and the line: a wrong header, a row that is not two numbers, a non-finite value, a
// time that does not increase, more than 1e7 rows, fewer than two rows.
void ParseAccelerationCsv(std::istream& in, const std::string& name, BaseMotionEffect& base);

}  // namespace shockmap

#pragma once
// A number quoted in a message, to 17 significant digits: the value quoted reads back as the
// value checked.

#include <string>

namespace shockmap {

std::string ExactText(double value);

}  // namespace shockmap

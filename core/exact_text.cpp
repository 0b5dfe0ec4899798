#include "core/exact_text.h"

#include <sstream>

namespace shockmap {

std::string ExactText(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

}  // namespace shockmap

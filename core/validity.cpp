#include "core/validity.h"

#include <cmath>
#include <sstream>

namespace shockmap {
namespace {

bool Fail(const char* name, double value, const std::string& allowed, std::string* error) {
  if (error != nullptr) {
    std::ostringstream out;
    out.precision(17);
    out << name << " = " << value << ": must be " << allowed;
    *error = out.str();
  }
  return false;
}

std::string Str(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

}  // namespace

bool RequireFinite(const char* name, double value, std::string* error) {
  return std::isfinite(value) || Fail(name, value, "a finite number", error);
}

bool RequirePositive(const char* name, double value, std::string* error) {
  return (std::isfinite(value) && value > 0.0) || Fail(name, value, "finite and > 0", error);
}

bool RequireNonNegative(const char* name, double value, std::string* error) {
  return (std::isfinite(value) && value >= 0.0) || Fail(name, value, "finite and >= 0", error);
}

bool RequireAtLeast(const char* name, double value, double minimum, std::string* error) {
  return (std::isfinite(value) && value >= minimum) ||
         Fail(name, value, "finite and >= " + Str(minimum), error);
}

bool RequireInRange(const char* name, double value, double lo, double hi, std::string* error) {
  return (std::isfinite(value) && value >= lo && value <= hi) ||
         Fail(name, value, "in [" + Str(lo) + ", " + Str(hi) + "]", error);
}

}  // namespace shockmap

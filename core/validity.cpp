#include "core/validity.h"

#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace shockmap {
namespace {

// The shortest text that reads back as `v`: 0.9999, not 0.99990000000000001.
std::string Str(double v) {
  std::array<char, 32> text{};
  return std::string(text.data(), std::to_chars(text.data(), text.data() + text.size(), v).ptr);
}

bool Fail(const char* name, double value, const std::string& allowed, std::string* error) {
  if (error != nullptr) *error = std::string(name) + " = " + Str(value) + ": must be " + allowed;
  return false;
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

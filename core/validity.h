#pragma once
// Helpers for Options::IsValid: each check writes "<name> = <value>: must be ..." on failure.

#include <string>

namespace shockmap {

bool RequireFinite(const char* name, double value, std::string* error);
bool RequirePositive(const char* name, double value, std::string* error);
bool RequireNonNegative(const char* name, double value, std::string* error);
bool RequireAtLeast(const char* name, double value, double minimum, std::string* error);
bool RequireInRange(const char* name, double value, double lo, double hi, std::string* error);

}  // namespace shockmap

#include "records/columns.h"

#include <cmath>

namespace shockmap {

std::string_view ToString(SqlType type) {
  switch (type) {
    case SqlType::kInteger:
      return "INTEGER";
    case SqlType::kReal:
      return "REAL";
    case SqlType::kText:
      return "TEXT";
    case SqlType::kBlob:
      return "BLOB";
  }
  return "BLOB";
}

bool Contains(ValueRange range, double value) {
  switch (range) {
    case ValueRange::kAny:
      return true;
    case ValueRange::kFinite:
      return std::isfinite(value);
    case ValueRange::kNonNegative:
      return std::isfinite(value) && value >= 0.0;
    case ValueRange::kPositive:
      return std::isfinite(value) && value > 0.0;
    case ValueRange::kFraction:
      return value >= 0.0 && value <= 1.0;
  }
  return false;
}

std::string_view Allowed(ValueRange range) {
  switch (range) {
    case ValueRange::kAny:
      return "any number";
    case ValueRange::kFinite:
      return "finite";
    case ValueRange::kNonNegative:
      return "finite and >= 0";
    case ValueRange::kPositive:
      return "finite and > 0";
    case ValueRange::kFraction:
      return "in [0, 1]";
  }
  return "";
}

}  // namespace shockmap

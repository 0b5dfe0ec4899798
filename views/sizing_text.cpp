#include "views/sizing_text.h"

#include <fmt/format.h>

namespace shockmap {

std::string PercentText(double probability) { return fmt::format("{:g}", 100.0 * probability); }

std::string SignificantText(double value) { return fmt::format("{:.4g}", value); }

std::string IntervalText(const QuantileInterval& q) {
  return fmt::format("{} [{}, {}]", SignificantText(q.estimate),
                     q.lower_bounded ? SignificantText(q.lower) : "-",
                     q.upper_bounded ? SignificantText(q.upper) : "-");
}

}  // namespace shockmap

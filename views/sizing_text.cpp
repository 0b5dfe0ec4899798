#include "views/sizing_text.h"

#include <fmt/format.h>

namespace shockmap {

std::string PercentText(double probability) { return fmt::format("{:g}", 100.0 * probability); }

std::string IntervalText(const QuantileInterval& q) {
  auto side = [](bool bounded, double v) { return bounded ? fmt::format("{:.4g}", v) : "-"; };
  return fmt::format("{:.4g} [{}, {}]", q.estimate, side(q.lower_bounded, q.lower),
                     side(q.upper_bounded, q.upper));
}

}  // namespace shockmap

#include "validation/impulse_ratio.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace shockmap {

double ImpulseRatio(double impulse_a_n_s, double impulse_b_n_s) {
  for (const double impulse : {impulse_a_n_s, impulse_b_n_s}) {
    if (!std::isfinite(impulse) || impulse < 0.0) {
      std::ostringstream message;
      message.precision(17);
      message << "ImpulseRatio: impulse = " << impulse << " N s: must be finite and >= 0";
      throw std::invalid_argument(message.str());
    }
  }
  const double larger = std::max(impulse_a_n_s, impulse_b_n_s);
  return larger > 0.0 ? std::min(impulse_a_n_s, impulse_b_n_s) / larger : 1.0;
}

std::optional<double> FirstShockImpulseRatio(const std::vector<Shock>& numerical,
                                             const std::vector<Shock>& reference) {
  if (numerical.empty() && reference.empty()) {
    return std::nullopt;
  }
  if (numerical.empty() || reference.empty()) {
    return 0.0;
  }
  return ImpulseRatio(numerical.front().impulse_n_s, reference.front().impulse_n_s);
}

}  // namespace shockmap

#include "core/uniform_signal.h"

#include <algorithm>
#include <cmath>

namespace shockmap {

double UniformSignal::At(double t_s) const {
  if (values.empty()) return 0.0;
  if (values.size() == 1 || t_s <= t0_s) return values.front();
  const double x = (t_s - t0_s) / dt_s;
  const auto last = values.size() - 1;
  if (x >= static_cast<double>(last)) return values.back();
  const auto i = static_cast<std::size_t>(std::floor(x));
  const double w = x - static_cast<double>(i);
  return (1.0 - w) * values[i] + w * values[std::min(i + 1, last)];
}

}  // namespace shockmap

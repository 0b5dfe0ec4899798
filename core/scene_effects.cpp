#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/scene.h"

namespace shockmap {

double BaseMotionEffect::At(double t_s) const {
  if (!table_t_s.empty()) {
    if (t_s < table_t_s.front() || t_s > table_t_s.back()) return 0.0;
    const auto it = std::ranges::upper_bound(table_t_s, t_s);
    if (it == table_t_s.end()) return table_a_m_s2.back();
    const auto i = static_cast<std::size_t>(it - table_t_s.begin());
    const double w = (t_s - table_t_s[i - 1]) / (table_t_s[i] - table_t_s[i - 1]);
    return (1 - w) * table_a_m_s2[i - 1] + w * table_a_m_s2[i];
  }
  const double tau = t_s - start_s;
  if (tau < 0.0 || tau > duration_s) return 0.0;
  return amplitude_m_s2 * std::sin(std::numbers::pi * tau / duration_s);
}

double StaticForceEffect::At(double t_s) const {
  if (t_s < start_s) return 0.0;
  if (ramp_s <= 0.0) return force_n;
  return force_n * std::min(1.0, (t_s - start_s) / ramp_s);
}

ContactLaw SceneZone::Law() const {
  ContactLaw law;
  law.normal = {stiffness_n_per_m, damping_n_s_per_m};
  if (power_law) {
    law.normal = {power_law->coefficient, damping_n_s_per_m, power_law->exponent,
                  power_law->bound_penetration_m};
  }
  law.friction = friction;
  return law;
}

}  // namespace shockmap

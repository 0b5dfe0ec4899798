#include "compare/reference_shocks.h"

#include <cassert>
#include <cmath>

namespace shockmap {
namespace {

// The largest sample of `force` in [shock.start_s, shock.end_s] as the shock's peak.
void SetPeak(const UniformSignal& force, Shock& shock) {
  if (force.values.empty()) return;  // A check carries no force history (nor a step).
  const double from = std::ceil((shock.start_s - force.t0_s) / force.dt_s);
  for (auto i = static_cast<std::size_t>(std::max(0.0, from));
       i < force.values.size() && force.TimeAt(i) <= shock.end_s; ++i) {
    if (force.values[i] > shock.peak_force_n) {
      shock.peak_force_n = force.values[i];
      shock.peak_time_s = force.TimeAt(i);
    }
  }
}

}  // namespace

std::vector<Shock> ReferenceShocks(const ReferenceSolution& solution, const UniformSignal& force,
                                   const ShockSegmentationOptions& options, double window_s) {
  assert(options.force_threshold_n == 0.0);
  std::vector<Shock> shocks;
  for (const ReferenceContact& c : solution.Contacts(window_s)) {
    if (shocks.empty() || c.start_s - shocks.back().end_s >= options.rest_duration_s) {
      Shock shock;
      shock.start_s = c.start_s;
      shock.peak_time_s = 0.5 * (c.start_s + c.end_s);
      shock.peak_force_n = solution.ContactForce(shock.peak_time_s);
      shocks.push_back(shock);
    }
    Shock& shock = shocks.back();
    shock.end_s = c.end_s;
    shock.impulse_n_s += c.impulse_n_s;
    ++shock.n_contacts;
  }
  for (Shock& shock : shocks) {
    SetPeak(force, shock);
    shock.truncated = shock.start_s <= 0.0 || shock.end_s >= window_s;
  }
  return shocks;
}

}  // namespace shockmap

#include "validation/impulse_ratio.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "core/exact_text.h"

namespace shockmap {

double ImpulseRatio(double impulse_a_n_s, double impulse_b_n_s) {
  for (const double impulse : {impulse_a_n_s, impulse_b_n_s}) {
    if (!std::isfinite(impulse) || impulse < 0.0) {
      throw std::invalid_argument("ImpulseRatio: impulse = " + ExactText(impulse) +
                                  " N s: must be finite and >= 0");
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

std::string ToString(SrfDefinition definition) {
  switch (definition) {
    case SrfDefinition::kFirstShock:
      return "first_shock";
    case SrfDefinition::kFirstContact:
      return "first_contact";
    case SrfDefinition::kReferenceWindow:
      return "reference_window";
  }
  return "first_shock";
}

std::optional<SrfDefinition> SrfDefinitionFromString(std::string_view name) {
  for (const SrfDefinition d : {SrfDefinition::kFirstShock, SrfDefinition::kFirstContact,
                                SrfDefinition::kReferenceWindow}) {
    if (name == ToString(d)) return d;
  }
  return std::nullopt;
}

double ImpulseOver(const UniformSignal& force, double t_begin_s, double t_end_s) {
  if (!std::isfinite(t_begin_s) || !std::isfinite(t_end_s) || t_begin_s > t_end_s) {
    throw std::invalid_argument("ImpulseOver: the interval must be finite and ordered");
  }
  if (force.values.size() < 2) return 0.0;
  if (!std::isfinite(force.dt_s) || !(force.dt_s > 0.0)) {
    throw std::invalid_argument("ImpulseOver: force dt_s must be finite and > 0");
  }
  const double a = std::max(t_begin_s, force.t0_s);
  const double b = std::min(t_end_s, force.EndTime());
  if (!(a < b)) return 0.0;
  // Whole segments [t_i, t_i+1] inside (a, b) by the trapezoidal rule, the partial ones at
  // either end with the interpolated force at a and b.
  const std::size_t last = force.values.size() - 1;
  auto index_after = [&](double t) {
    const double i = std::ceil((t - force.t0_s) / force.dt_s);
    return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(last)));
  };
  const std::size_t i = index_after(a);
  std::size_t j = index_after(b);
  if (force.TimeAt(j) > b && j > 0) --j;
  if (i > j) return 0.5 * (force.At(a) + force.At(b)) * (b - a);
  double impulse = 0.5 * (force.At(a) + force.values[i]) * (force.TimeAt(i) - a);
  for (std::size_t k = i; k < j; ++k) {
    impulse += 0.5 * (force.values[k] + force.values[k + 1]) * force.dt_s;
  }
  impulse += 0.5 * (force.values[j] + force.At(b)) * (b - force.TimeAt(j));
  return impulse;
}

namespace {

// Impulse of the first contact (the first run of samples above the threshold, with the sample
// on either side, as SegmentShocks integrates a shock); std::nullopt without contact.
std::optional<double> FirstContactImpulse(const UniformSignal& force,
                                          const ShockSegmentationOptions& shocks, double t_end_s) {
  const std::vector<double>& f = force.values;
  std::size_t first = 0;
  while (first < f.size() && force.TimeAt(first) <= t_end_s &&
         !(f[first] > shocks.force_threshold_n))
    ++first;
  if (first == f.size() || force.TimeAt(first) > t_end_s) return std::nullopt;
  std::size_t last = first;
  while (last + 1 < f.size() && force.TimeAt(last + 1) <= t_end_s &&
         f[last + 1] > shocks.force_threshold_n)
    ++last;
  const std::size_t a = first > 0 ? first - 1 : first;
  const std::size_t b = last + 1 < f.size() && force.TimeAt(last + 1) <= t_end_s ? last + 1 : last;
  double impulse = 0.0;
  for (std::size_t i = a; i < b; ++i) impulse += 0.5 * (f[i] + f[i + 1]);
  return impulse * force.dt_s;
}

}  // namespace

std::optional<double> DefinedImpulseRatio(SrfDefinition definition,
                                          const UniformSignal& numerical_force,
                                          const std::vector<Shock>& numerical_shocks,
                                          const UniformSignal& reference_force,
                                          const std::vector<Shock>& reference_shocks,
                                          const ShockSegmentationOptions& shocks, double t_end_s) {
  switch (definition) {
    case SrfDefinition::kFirstShock:
      return FirstShockImpulseRatio(numerical_shocks, reference_shocks);
    case SrfDefinition::kFirstContact: {
      const auto numerical = FirstContactImpulse(numerical_force, shocks, t_end_s);
      const auto reference = FirstContactImpulse(reference_force, shocks, t_end_s);
      if (!numerical && !reference) return std::nullopt;
      if (!numerical || !reference) return 0.0;
      return ImpulseRatio(*numerical, *reference);
    }
    case SrfDefinition::kReferenceWindow: {
      if (numerical_shocks.empty() && reference_shocks.empty()) return std::nullopt;
      if (reference_shocks.empty()) return 0.0;
      const Shock& first = reference_shocks.front();
      return ImpulseRatio(ImpulseOver(numerical_force, first.start_s, first.end_s),
                          ImpulseOver(reference_force, first.start_s, first.end_s));
    }
  }
  return FirstShockImpulseRatio(numerical_shocks, reference_shocks);
}

}  // namespace shockmap

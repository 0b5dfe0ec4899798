#include "validation/shock_segmentation.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "core/exact_text.h"

namespace shockmap {
namespace {

// Number of samples with time <= t_end_s, allowing for t_end_s computed as t0 + i dt in another
// order of operations.
std::size_t SamplesConsidered(const UniformSignal& force, double t_end_s) {
  if (force.values.empty() || t_end_s < force.t0_s) {
    return 0;
  }
  if (force.values.size() == 1) {
    return 1;
  }
  const double last = std::floor((t_end_s - force.t0_s) / force.dt_s + 1e-9);
  if (last >= static_cast<double>(force.values.size() - 1)) {
    return force.values.size();
  }
  return static_cast<std::size_t>(last) + 1;
}

// Samples [first, last] are one contact.
struct Contact {
  std::size_t first = 0;
  std::size_t last = 0;
};

}  // namespace

bool ShockSegmentationOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) {
      *error = message;
    }
    return false;
  };
  if (!std::isfinite(force_threshold_n) || force_threshold_n < 0.0) {
    return fail("force_threshold_n = " + ExactText(force_threshold_n) +
                ": must be finite and >= 0");
  }
  if (!std::isfinite(rest_duration_s) || rest_duration_s <= 0.0) {
    return fail("rest_duration_s = " + ExactText(rest_duration_s) +
                ": must be finite and > 0 (required, no default)");
  }
  return true;
}

std::vector<Shock> SegmentShocks(const UniformSignal& force,
                                 const ShockSegmentationOptions& options, double t_end_s) {
  std::string error;
  if (!options.IsValid(&error)) {
    throw std::invalid_argument("ShockSegmentationOptions: " + error);
  }
  if (std::isnan(t_end_s)) {
    throw std::invalid_argument("SegmentShocks: t_end_s is NaN");
  }
  if (force.values.size() >= 2 && (!std::isfinite(force.dt_s) || !(force.dt_s > 0.0))) {
    throw std::invalid_argument("SegmentShocks: force dt_s = " + ExactText(force.dt_s) +
                                ": must be finite and > 0");
  }
  const std::size_t n = SamplesConsidered(force, t_end_s);
  const std::vector<double>& f = force.values;
  const double threshold = options.force_threshold_n;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(f[i])) {
      throw std::invalid_argument(
          "SegmentShocks: force is not finite at t = " + ExactText(force.TimeAt(i)) + " s");
    }
  }

  // Interpolated time at which the force crosses the threshold between samples i and i + 1,
  // one at or below it and the other above it.
  auto crossing_time = [&](std::size_t i) {
    return force.TimeAt(i) + force.dt_s * (threshold - f[i]) / (f[i + 1] - f[i]);
  };

  std::vector<Contact> contacts;
  for (std::size_t i = 0; i < n; ++i) {
    if (f[i] > threshold && (i == 0 || f[i - 1] <= threshold)) {
      contacts.push_back({i, i});
    }
    if (f[i] > threshold) {
      contacts.back().last = i;
    }
  }

  std::vector<Shock> shocks;
  Contact span;  // Samples of the shock being built, from its first contact to its last.
  int n_contacts = 0;
  auto close_shock = [&] {
    Shock shock;
    shock.start_s = span.first > 0 ? crossing_time(span.first - 1) : force.TimeAt(0);
    shock.end_s = span.last + 1 < n ? crossing_time(span.last) : force.TimeAt(span.last);
    shock.n_contacts = n_contacts;
    shock.truncated = span.first == 0 || span.last + 1 == n;
    shock.peak_force_n = f[span.first];
    shock.peak_time_s = force.TimeAt(span.first);
    for (std::size_t i = span.first; i <= span.last; ++i) {
      if (f[i] > shock.peak_force_n) {
        shock.peak_force_n = f[i];
        shock.peak_time_s = force.TimeAt(i);
      }
    }
    const std::size_t a = span.first > 0 ? span.first - 1 : span.first;
    const std::size_t b = span.last + 1 < n ? span.last + 1 : span.last;
    double impulse = 0.0;
    for (std::size_t i = a; i < b; ++i) {
      impulse += 0.5 * (f[i] + f[i + 1]);
    }
    shock.impulse_n_s = b > a ? impulse * force.dt_s : 0.0;  // One-sample record: no interval.
    shocks.push_back(shock);
  };
  for (const Contact& contact : contacts) {
    if (n_contacts > 0) {
      const double previous_end_s = crossing_time(span.last);
      const double start_s = crossing_time(contact.first - 1);
      if (start_s - previous_end_s < options.rest_duration_s) {
        span.last = contact.last;
        ++n_contacts;
        continue;
      }
      close_shock();
    }
    span = contact;
    n_contacts = 1;
  }
  if (n_contacts > 0) {
    close_shock();
  }
  return shocks;
}

}  // namespace shockmap

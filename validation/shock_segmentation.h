#pragma once
// Shocks and their statistics from a sampled contact force, grouped as code_aster's impact
// post-processing groups them (paper §2.4): a contact is a maximal run of samples with force
// above a threshold; contacts separated by less than a rest duration form one shock, the later
// contacts being rebounds.

#include <string>
#include <vector>

#include "core/uniform_signal.h"

namespace shockmap {

struct ShockSegmentationOptions {
  // Contact means force strictly above this (N). 0 because a compression-only spring carries
  // exactly zero force when open, so every positive sample is contact.
  double force_threshold_n = 0.0;
  // Contacts closer than this (s) are one shock. Required: no value is meaningful in general (it
  // belongs to the problem's time scale, e.g. a fraction of the first period 1 / f1), so the
  // default 0 is deliberately invalid.
  double rest_duration_s = 0.0;

  // force_threshold_n finite and >= 0; rest_duration_s finite and > 0.
  bool IsValid(std::string* error) const;
};

struct Shock {
  // Start of the first contact / end of the last: the threshold crossings, linearly interpolated
  // between the samples on either side (s).
  double start_s = 0.0;
  double end_s = 0.0;
  double peak_force_n = 0.0;  // Largest force sample of the shock (N).
  double peak_time_s = 0.0;   // Time of that sample, the first one if tied (s).
  // Trapezoidal rule over the samples of the shock plus the sample just before and just after it
  // when they exist (N s): the integral of the piecewise-linear force over the shock, so a
  // one-sample contact of force F between zero neighbours has impulse F dt.
  double impulse_n_s = 0.0;
  int n_contacts = 0;  // >= 1.
  // A contact is under way at the first sample or at the last sample considered: the shock is
  // cut by the record, so start/end, impulse and contact count are only bounds.
  bool truncated = false;

  int Rebounds() const { return n_contacts - 1; }
  double Duration() const { return end_s - start_s; }
};

// Shocks of `force` (N, compressive contact force counted positive) in time order, using the
// samples with time <= t_end_s (to rounding; +infinity means all). Empty when no sample exceeds
// the threshold or no sample is considered.
// Throws std::invalid_argument on invalid options, a NaN t_end_s, a signal with >= 2 samples and
// dt_s not finite and > 0, or a non-finite force among the samples considered.
std::vector<Shock> SegmentShocks(const UniformSignal& force,
                                 const ShockSegmentationOptions& options, double t_end_s);

}  // namespace shockmap

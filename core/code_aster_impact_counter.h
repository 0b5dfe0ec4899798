#pragma once
// Impact statistics of one zone in code_aster's convention: the counting of POST_DYNA_MODA_T's
// routines on the force's samples (docs/physics.md §6.2), streamed step by step.
//
// A sample is in contact when its force exceeds the threshold. A contact ends at the first
// sample at or below it. An impact starts at a sample in contact outside any impact, and ends
// at the first sample of a gap when none of the next n samples is in contact, n = max(1,
// round(rest / dt)); with n = 1 every gap ends it. Impacts and contacts are counted when they
// end inside the window; durations are differences of sample times. The force's mean, RMS and
// impulse sum the samples above the threshold only; the wear work rate is the trapezoid of
// F |v_t| over the window's pairs of samples whose first does not stick, over the window's
// span.

#include <cstdint>

#include "core/impact_statistics.h"

namespace shockmap {

class CodeAsterImpactCounter {
 public:
  // Samples are t_i = i dt_s from i = 0. The window's samples are those from
  // floor(window_start / dt) to floor(window_end / dt) (each to within 1e-9 of a step, as
  // POST_DYNA_MODA_T truncates INST_INIT and INST_FIN), the last sample given at most.
  // Precondition: counting.IsValid(), dt_s > 0.
  CodeAsterImpactCounter(const ImpactCounting& counting, double dt_s, bool friction, bool records);

  // The next sample.
  void Add(const ZoneSample& sample);

  // The statistics over the window's samples given.
  ImpactStatistics Finish() const;

 private:
  bool Above(double force_n) const { return force_n > counting_.force_threshold_n; }
  double Time(std::int64_t i) const { return static_cast<double>(i) * dt_s_; }
  void AddInWindow(const ZoneSample& sample);
  // The sample after the window: it may still end the impact whose gap began inside.
  void AddAfterWindow(const ZoneSample& sample);
  void EndImpact();

  ImpactCounting counting_;
  double dt_s_;
  bool friction_, records_;
  std::int64_t look_ahead_;    // n above.
  std::int64_t first_, last_;  // The window's sample indices (last_ may exceed the run's).
  std::int64_t next_ = 0;      // The index of the next sample.
  // Over the window: samples, and those in contact with their sums of F and F^2.
  std::int64_t samples_ = 0, above_ = 0;
  double force_sum_n_ = 0.0, squared_sum_n2_ = 0.0, max_force_n_ = 0.0;
  // The previous sample of the window, and the trapezoid sums of F |v_t| and |F_t| |v_t|.
  ZoneSample previous_;
  double wear_sum_w_ = 0.0, friction_sum_w_ = 0.0;
  bool wear_available_ = true;
  // Contacts: the running one's first sample; counts and total duration of the ended ones.
  bool in_contact_ = false;
  std::int64_t contact_start_ = 0;
  int contacts_ = 0;
  double contact_time_s_ = 0.0;
  // Impacts: the running one, and a gap that may end it (its first sample, samples so far).
  bool in_impact_ = false, gap_ = false;
  std::int64_t impact_start_ = 0, gap_start_ = 0, gap_samples_ = 0;
  ImpactRecord open_;
  int impacts_ = 0;
  double impact_time_s_ = 0.0, longest_impact_s_ = 0.0;
  bool started_in_contact_ = false;
  std::vector<ImpactRecord> impact_records_;
};

}  // namespace shockmap

#include "core/code_aster_impact_counter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shockmap {
namespace {

// floor(t / dt) to within 1e-9 of a step; a window's end beyond any run gives the largest index.
std::int64_t SampleIndex(double t_s, double dt_s) {
  const double steps = std::floor(t_s / dt_s + 1e-9);
  return steps >= 9e18 ? std::numeric_limits<std::int64_t>::max()
                       : static_cast<std::int64_t>(steps);
}

}  // namespace

CodeAsterImpactCounter::CodeAsterImpactCounter(const ImpactCounting& counting, double dt_s,
                                               bool friction, bool records)
    : counting_(counting),
      dt_s_(dt_s),
      friction_(friction),
      records_(records),
      // Capped far beyond any run's steps, so that the rounding stays defined.
      look_ahead_(
          std::max<std::int64_t>(1, std::llround(std::min(counting.rest_duration_s / dt_s, 1e15)))),
      first_(SampleIndex(counting.window_start_s, dt_s)),
      last_(SampleIndex(counting.window_end_s, dt_s)) {}

void CodeAsterImpactCounter::Add(const ZoneSample& sample) {
  const std::int64_t i = next_++;
  if (i < first_) return;
  if (i <= last_) {
    AddInWindow(sample);
  } else {
    AddAfterWindow(sample);
  }
}

void CodeAsterImpactCounter::AddInWindow(const ZoneSample& s) {
  const std::int64_t i = next_ - 1;
  // The force's statistics and the wear work rate's trapezoids.
  ++samples_;
  if (!std::isfinite(s.sliding_speed_m_s)) wear_available_ = false;
  if (i > first_ && !previous_.sticks) {
    wear_sum_w_ +=
        0.5 * dt_s_ *
        (previous_.force_n * previous_.sliding_speed_m_s + s.force_n * s.sliding_speed_m_s);
    friction_sum_w_ += 0.5 * dt_s_ *
                       (previous_.tangential_force_n * previous_.sliding_speed_m_s +
                        s.tangential_force_n * s.sliding_speed_m_s);
  }
  previous_ = s;
  if (!Above(s.force_n)) {
    if (in_contact_) {
      in_contact_ = false;
      ++contacts_;
      ++open_.contacts;
      contact_time_s_ += Time(i) - Time(contact_start_);
    }
    if (in_impact_ && !gap_) gap_ = true, gap_start_ = i, gap_samples_ = 0;
    if (gap_ && ++gap_samples_ > look_ahead_) EndImpact();
    if (gap_ && look_ahead_ == 1) EndImpact();
    return;
  }
  ++above_;
  force_sum_n_ += s.force_n;
  squared_sum_n2_ += s.force_n * s.force_n;
  max_force_n_ = std::max(max_force_n_, s.force_n);
  if (!in_impact_) {
    in_impact_ = true;
    impact_start_ = i;
    open_ = {};
    open_.start_s = Time(i);
    open_.impact_speed_m_s = s.penetration_rate_m_s;
    open_.truncated = i == first_;
    started_in_contact_ = started_in_contact_ || i == first_;
  }
  gap_ = false;
  if (!in_contact_) in_contact_ = true, contact_start_ = i;
  // The impact's peak is its last sample of largest force, its impulse the sum of F dt.
  if (s.force_n >= open_.peak_force_n) open_.peak_force_n = s.force_n, open_.peak_time_s = Time(i);
  open_.impulse_n_s += s.force_n * dt_s_;
}

void CodeAsterImpactCounter::AddAfterWindow(const ZoneSample& s) {
  if (!gap_) return;
  if (Above(s.force_n)) {
    gap_ = false;  // A rebound: the impact goes on past the window, uncounted.
  } else if (++gap_samples_ > look_ahead_) {
    EndImpact();
  }
}

void CodeAsterImpactCounter::EndImpact() {
  const double duration = Time(gap_start_) - Time(impact_start_);
  ++impacts_;
  impact_time_s_ += duration;
  longest_impact_s_ = std::max(longest_impact_s_, duration);
  if (records_) {
    open_.duration_s = duration;
    impact_records_.push_back(open_);
  }
  in_impact_ = gap_ = false;
}

ImpactStatistics CodeAsterImpactCounter::Finish() const {
  CodeAsterImpactCounter done = *this;
  // The run ended within a gap's look-ahead: nothing followed, the impact ended.
  if (done.gap_) done.EndImpact();
  ImpactStatistics s;
  s.convention = ImpactConvention::kCodeAster;
  const std::int64_t last = first_ + samples_ - 1;
  s.window_start_s = Time(first_);
  s.window_end_s = Time(std::max(first_, last));
  s.impacts = done.impacts_;
  s.contacts = done.contacts_;
  // The acquisition time counts every sample of the window for a full step.
  const double acquisition_s = static_cast<double>(samples_) * dt_s_;
  if (samples_ == 0) return s;
  s.impacts_per_s = std::floor(done.impacts_ / acquisition_s);
  if (done.impacts_ > 0) {
    s.rebounds_per_impact = done.contacts_ / done.impacts_;  // Integer division.
    s.mean_impact_duration_s = done.impact_time_s_ / done.impacts_;
    s.longest_impact_duration_s = done.longest_impact_s_;
  }
  if (done.contacts_ > 0) s.mean_contact_duration_s = done.contact_time_s_ / done.contacts_;
  s.contact_time_fraction = std::floor(100.0 * done.impact_time_s_ / acquisition_s) / 100.0;
  s.mean_force_n = force_sum_n_ / static_cast<double>(samples_);
  s.rms_force_n = std::sqrt(squared_sum_n2_ / static_cast<double>(samples_));
  if (above_ > 0) {
    s.mean_force_in_contact_n = force_sum_n_ / static_cast<double>(above_);
    s.rms_force_in_contact_n = std::sqrt(squared_sum_n2_ / static_cast<double>(above_));
  }
  s.max_force_n = max_force_n_;
  s.impulse_n_s = force_sum_n_ * dt_s_;
  s.wear_available = wear_available_;
  s.sliding_only = friction_;
  const double span_s = static_cast<double>(samples_ - 1) * dt_s_;
  if (wear_available_) {
    s.wear_work_rate_w = span_s > 0.0 ? wear_sum_w_ / span_s : 0.0;
    if (friction_) s.friction_power_w = span_s > 0.0 ? friction_sum_w_ / span_s : 0.0;
  }
  s.truncated = started_in_contact_ || in_contact_ || done.in_impact_;
  s.records = done.impact_records_;
  return s;
}

}  // namespace shockmap

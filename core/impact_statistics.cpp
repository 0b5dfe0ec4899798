#include "core/impact_statistics.h"

#include <algorithm>
#include <cmath>

#include "core/validity.h"

namespace shockmap {

bool ImpactCounting::IsValid(std::string* error) const {
  return RequireFinite("force_threshold_n", force_threshold_n, error) &&
         RequireNonNegative("force_threshold_n", force_threshold_n, error) &&
         RequireFinite("rest_duration_s", rest_duration_s, error) &&
         RequireNonNegative("rest_duration_s", rest_duration_s, error);
}

ImpactAccumulator::ImpactAccumulator(ImpactCounting counting, double initial_force_n,
                                     double initial_sliding_speed_m_s)
    : counting_(counting),
      last_{0.0, initial_force_n, initial_sliding_speed_m_s},
      max_force_n_(initial_force_n),
      wear_available_(std::isfinite(initial_sliding_speed_m_s)) {
  if (InContact(initial_force_n)) {
    started_in_contact_ = true;
    StartContact(0.0);
  }
}

void ImpactAccumulator::Add(double force_n, double sliding_speed_m_s, double dt_s) {
  const Sample next{last_.t_s + dt_s, force_n, sliding_speed_m_s};
  if (!std::isfinite(sliding_speed_m_s)) wear_available_ = false;
  max_force_n_ = std::max(max_force_n_, force_n);
  if (opening_pending_) ResolveOpening(&next);
  if (last_.force_n == 0.0 && force_n > 0.0) {
    opening_pending_ = true;
  } else if (last_.force_n > 0.0 && force_n == 0.0) {
    // Closing: the zero crossing continues the slope of the two samples before it.
    double zero_s = 0.5 * (last_.t_s + next.t_s);
    if (has_before_last_ && before_last_.force_n > last_.force_n) {
      const double slope = (before_last_.force_n - last_.force_n) / (last_.t_s - before_last_.t_s);
      zero_s = std::clamp(last_.t_s + last_.force_n / slope, last_.t_s, next.t_s);
    }
    Piece(last_, {zero_s, 0.0, sliding_speed_m_s});
  } else {
    Piece(last_, next);
  }
  before_last_ = last_;
  has_before_last_ = true;
  last_ = next;
}

void ImpactAccumulator::ResolveOpening(const Sample* next) {
  const Sample& zero = before_last_;
  const Sample& first = last_;
  double zero_s = 0.5 * (zero.t_s + first.t_s);
  if (next != nullptr && next->force_n > first.force_n) {
    const double slope = (next->force_n - first.force_n) / (next->t_s - first.t_s);
    zero_s = std::clamp(first.t_s - first.force_n / slope, zero.t_s, first.t_s);
  }
  Piece({zero_s, 0.0, zero.speed_m_s}, first);
  opening_pending_ = false;
}

void ImpactAccumulator::Piece(const Sample& a, const Sample& b) {
  const double length_s = b.t_s - a.t_s;
  impulse_n_s_ += 0.5 * length_s * (a.force_n + b.force_n);
  squared_n2_s_ += 0.5 * length_s * (a.force_n * a.force_n + b.force_n * b.force_n);
  if (wear_available_) {
    wear_work_j_ += 0.5 * length_s * (a.force_n * a.speed_m_s + b.force_n * b.speed_m_s);
  }
  const bool was = InContact(a.force_n), is = InContact(b.force_n);
  if (!was && !is) return;
  // The part of the piece above the threshold, its ends where the line crosses it.
  const double threshold = counting_.force_threshold_n;
  const double crossing = a.t_s + length_s * (threshold - a.force_n) / (b.force_n - a.force_n);
  const double from = was ? a.t_s : crossing, to = is ? b.t_s : crossing;
  const double f_from = was ? a.force_n : threshold, f_to = is ? b.force_n : threshold;
  if (!was) StartContact(from);
  contact_time_s_ += to - from;
  contact_impulse_n_s_ += 0.5 * (to - from) * (f_from + f_to);
  if (!is) {
    in_contact_ = false;
    last_contact_end_s_ = to;
  }
}

void ImpactAccumulator::StartContact(double t_s) {
  ++contacts_;
  in_contact_ = true;
  const bool rebound = impacts_ > 0 && t_s - last_contact_end_s_ < counting_.rest_duration_s;
  if (rebound) return;
  if (impacts_ > 0) CloseImpact();
  ++impacts_;
  impact_start_s_ = t_s;
}

void ImpactAccumulator::CloseImpact() {
  const double duration = last_contact_end_s_ - impact_start_s_;
  closed_duration_sum_s_ += duration;
  longest_closed_s_ = std::max(longest_closed_s_, duration);
}

ImpactStatistics ImpactAccumulator::Finish(double duration_s) const {
  if (!opening_pending_) return Statistics(duration_s);
  ImpactAccumulator done = *this;
  done.ResolveOpening(nullptr);
  return done.Statistics(duration_s);
}

ImpactStatistics ImpactAccumulator::Statistics(double duration_s) const {
  ImpactStatistics s;
  s.impacts = impacts_;
  s.contacts = contacts_;
  if (impacts_ > 0) {
    // The open impact ends with its last contact, or with the run while in contact.
    const double open = (in_contact_ ? last_.t_s : last_contact_end_s_) - impact_start_s_;
    s.rebounds_per_impact = static_cast<double>(contacts_ - impacts_) / impacts_;
    s.mean_impact_duration_s = (closed_duration_sum_s_ + open) / impacts_;
    s.longest_impact_duration_s = std::max(longest_closed_s_, open);
  }
  s.impacts_per_s = impacts_ / duration_s;
  s.contact_time_fraction = contact_time_s_ / duration_s;
  s.impulse_n_s = impulse_n_s_;
  s.mean_force_n = impulse_n_s_ / duration_s;
  s.mean_force_in_contact_n = contact_time_s_ > 0.0 ? contact_impulse_n_s_ / contact_time_s_ : 0.0;
  s.rms_force_n = std::sqrt(squared_n2_s_ / duration_s);
  s.max_force_n = max_force_n_;
  s.wear_available = wear_available_;
  if (wear_available_) s.wear_work_rate_w = wear_work_j_ / duration_s;
  s.truncated = started_in_contact_ || in_contact_;
  return s;
}

}  // namespace shockmap

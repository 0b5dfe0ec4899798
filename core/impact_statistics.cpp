#include "core/impact_statistics.h"

#include <algorithm>
#include <cmath>

#include "core/validity.h"

namespace shockmap {

std::string ToString(ImpactConvention convention) {
  return convention == ImpactConvention::kCodeAster ? "code_aster" : "shockmap";
}

bool ImpactCounting::IsValid(std::string* error) const {
  if (!(RequireFinite("force_threshold_n", force_threshold_n, error) &&
        RequireNonNegative("force_threshold_n", force_threshold_n, error) &&
        RequireFinite("rest_duration_s", rest_duration_s, error) &&
        RequireNonNegative("rest_duration_s", rest_duration_s, error) &&
        RequireFinite("window_start_s", window_start_s, error) &&
        RequireNonNegative("window_start_s", window_start_s, error))) {
    return false;
  }
  if (!(window_end_s > window_start_s)) {
    if (error != nullptr) *error = "window_end_s must lie after window_start_s";
    return false;
  }
  return true;
}

ImpactAccumulator::ImpactAccumulator(ImpactCounting counting, double initial_force_n,
                                     double initial_sliding_speed_m_s)
    : ImpactAccumulator(counting, ZoneSample{initial_force_n, initial_sliding_speed_m_s},
                        Options{}) {}

ImpactAccumulator::ImpactAccumulator(ImpactCounting counting, const ZoneSample& initial,
                                     Options options)
    : counting_(counting),
      options_(options),
      last_(Integrated(0.0, initial)),
      max_force_n_(initial.force_n),
      wear_available_(std::isfinite(initial.sliding_speed_m_s)) {
  if (InContact(initial.force_n)) {
    started_in_contact_ = true;
    closing_rate_m_s_ = initial.penetration_rate_m_s;
    StartContact(0.0);
  }
}

ImpactAccumulator::Sample ImpactAccumulator::Integrated(double t_s,
                                                        const ZoneSample& sample) const {
  const double speed = sample.sticks ? 0.0 : sample.sliding_speed_m_s;
  return {t_s, sample.force_n, speed, options_.friction ? sample.tangential_force_n * speed : 0.0};
}

void ImpactAccumulator::Add(double force_n, double sliding_speed_m_s, double dt_s) {
  Add(ZoneSample{force_n, sliding_speed_m_s}, dt_s);
}

void ImpactAccumulator::Add(const ZoneSample& sample, double dt_s) {
  const double force_n = sample.force_n;
  const Sample next = Integrated(last_.t_s + dt_s, sample);
  if (!std::isfinite(sample.sliding_speed_m_s)) wear_available_ = false;
  max_force_n_ = std::max(max_force_n_, force_n);
  if (opening_pending_) ResolveOpening(&next);
  if (last_.force_n == 0.0 && force_n > 0.0) {
    opening_pending_ = true;
    closing_rate_m_s_ = sample.penetration_rate_m_s;
  } else if (last_.force_n > 0.0 && force_n == 0.0) {
    // Closing: the zero crossing continues the slope of the two samples before it.
    double zero_s = 0.5 * (last_.t_s + next.t_s);
    if (has_before_last_ && before_last_.force_n > last_.force_n) {
      const double slope = (before_last_.force_n - last_.force_n) / (last_.t_s - before_last_.t_s);
      zero_s = std::clamp(last_.t_s + last_.force_n / slope, last_.t_s, next.t_s);
    }
    Piece(last_, {zero_s, 0.0, next.speed_m_s, next.friction_w});
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
  Piece({zero_s, 0.0, zero.speed_m_s, zero.friction_w}, first);
  opening_pending_ = false;
}

void ImpactAccumulator::Piece(const Sample& a, const Sample& b) {
  const double length_s = b.t_s - a.t_s;
  impulse_n_s_ += 0.5 * length_s * (a.force_n + b.force_n);
  squared_n2_s_ += 0.5 * length_s * (a.force_n * a.force_n + b.force_n * b.force_n);
  if (wear_available_) {
    wear_work_j_ += 0.5 * length_s * (a.force_n * a.speed_m_s + b.force_n * b.speed_m_s);
    friction_work_j_ += 0.5 * length_s * (a.friction_w + b.friction_w);
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
  const double impulse = 0.5 * (to - from) * (f_from + f_to);
  contact_impulse_n_s_ += impulse;
  contact_squared_n2_s_ += 0.5 * (to - from) * (f_from * f_from + f_to * f_to);
  open_.impulse_n_s += impulse;
  if (was) Peak(a);
  if (is) Peak(b);
  if (!is) {
    in_contact_ = false;
    last_contact_end_s_ = to;
  }
}

void ImpactAccumulator::StartContact(double t_s) {
  ++contacts_;
  in_contact_ = true;
  const bool rebound = impacts_ > 0 && t_s - last_contact_end_s_ < counting_.rest_duration_s;
  if (rebound) {
    ++open_.contacts;
    return;
  }
  if (impacts_ > 0) CloseImpact();
  ++impacts_;
  impact_start_s_ = t_s;
  open_ = {};
  open_.start_s = options_.origin_s + t_s;
  open_.impact_speed_m_s = closing_rate_m_s_;
  open_.contacts = 1;
  open_.truncated = started_in_contact_ && impacts_ == 1;
}

void ImpactAccumulator::CloseImpact() {
  const double duration = last_contact_end_s_ - impact_start_s_;
  closed_duration_sum_s_ += duration;
  longest_closed_s_ = std::max(longest_closed_s_, duration);
  if (options_.records) records_.push_back(OpenRecord(last_contact_end_s_, false));
}

void ImpactAccumulator::Peak(const Sample& s) {
  if (s.force_n > open_.peak_force_n) {
    open_.peak_force_n = s.force_n;
    open_.peak_time_s = options_.origin_s + s.t_s;
  }
}

ImpactRecord ImpactAccumulator::OpenRecord(double end_s, bool cut) const {
  ImpactRecord r = open_;
  r.duration_s = end_s - impact_start_s_;
  r.truncated = r.truncated || cut;
  return r;
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
  s.window_start_s = options_.origin_s;
  s.window_end_s = options_.origin_s + duration_s;
  if (contacts_ > 0) s.mean_contact_duration_s = contact_time_s_ / contacts_;
  if (contact_time_s_ > 0.0)
    s.rms_force_in_contact_n = std::sqrt(contact_squared_n2_s_ / contact_time_s_);
  s.sliding_only = options_.friction;
  if (options_.friction && wear_available_) s.friction_power_w = friction_work_j_ / duration_s;
  if (options_.records) {
    s.records = records_;
    if (impacts_ > 0) {
      s.records.push_back(OpenRecord(in_contact_ ? last_.t_s : last_contact_end_s_, in_contact_));
    }
  }
  return s;
}

}  // namespace shockmap

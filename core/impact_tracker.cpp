#include "core/impact_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shockmap {
namespace {

// The step at t_s: rounded up (first) or down (last), to within 1e-9 of a step.
std::int64_t StepAt(double t_s, double dt_s, bool up) {
  const double steps = up ? std::ceil(t_s / dt_s - 1e-9) : std::floor(t_s / dt_s + 1e-9);
  return steps >= 9e18 ? std::numeric_limits<std::int64_t>::max()
                       : static_cast<std::int64_t>(steps);
}

}  // namespace

ImpactTracker::ImpactTracker(const SecondOrderSystem& system, const ImpactCounting& counting,
                             const std::vector<int>& listed, const Eigen::VectorXd& v0, double dt_s)
    : system_(system),
      counting_(counting),
      dt_s_(dt_s),
      first_step_(StepAt(counting.window_start_s, dt_s, true)),
      last_step_(StepAt(counting.window_end_s, dt_s, false)) {
  const auto forces = system.LastContactForces();
  listed_.assign(forces.size(), false);
  for (int c : listed) listed_[static_cast<std::size_t>(c)] = true;
  for (std::size_t c = 0; c < forces.size(); ++c) {
    const int contact = static_cast<int>(c);
    slides_.push_back(std::isfinite(system.Tangential(contact, v0).sliding_speed_m_s));
    friction_.push_back(system.HasFriction(contact));
  }
  if (CodeAster()) {
    for (std::size_t c = 0; c < forces.size(); ++c) {
      counters_.emplace_back(counting, dt_s, friction_[c], listed_[c]);
      counters_.back().Add(SampleOf(c, forces[c], v0));
    }
  } else if (first_step_ == 0) {
    Start(v0);
  }
}

ZoneSample ImpactTracker::SampleOf(std::size_t c, double force, const Eigen::VectorXd& v) const {
  ZoneSample s;
  s.force_n = force;
  s.sliding_speed_m_s = Idle(c);
  if (force > 0.0 && slides_[c]) {
    const TangentialSample t = system_.Tangential(static_cast<int>(c), v);
    s.sliding_speed_m_s = t.sliding_speed_m_s;
    s.tangential_force_n = t.force_n;
    s.sticks = t.sticks;
  }
  if (force > 0.0 && listed_[c])
    s.penetration_rate_m_s = system_.PenetrationRate(static_cast<int>(c), v);
  return s;
}

void ImpactTracker::Start(const Eigen::VectorXd& v) {
  const auto forces = system_.LastContactForces();
  ImpactAccumulator::Options options;
  options.origin_s = static_cast<double>(step_) * dt_s_;
  for (std::size_t c = 0; c < forces.size(); ++c) {
    open_steps_.push_back(forces[c] == 0.0 ? 0 : -1);
    options.friction = friction_[c];
    options.records = listed_[c];
    accumulators_.emplace_back(counting_, SampleOf(c, forces[c], v), options);
  }
}

void ImpactTracker::Step(const Eigen::VectorXd& v) {
  ++step_;
  if (CodeAster()) {
    const auto forces = system_.LastContactForces();
    for (std::size_t c = 0; c < forces.size(); ++c) counters_[c].Add(SampleOf(c, forces[c], v));
  } else if (step_ == first_step_) {
    Start(v);
  } else if (step_ > first_step_ && step_ <= last_step_) {
    StepShockmap(v);
  }
}

void ImpactTracker::StepShockmap(const Eigen::VectorXd& v) {
  const auto forces = system_.LastContactForces();
  for (std::size_t c = 0; c < forces.size(); ++c) {
    const double force = forces[c];
    std::int64_t& open_steps = open_steps_[c];
    if (force == 0.0 && open_steps >= 0) {
      ++open_steps;
      continue;
    }
    if (open_steps > 0) {
      accumulators_[c].Add(0.0, Idle(c), static_cast<double>(open_steps) * dt_s_);
    }
    accumulators_[c].Add(SampleOf(c, force, v), dt_s_);
    open_steps = force == 0.0 ? 0 : -1;
  }
}

std::vector<ImpactStatistics> ImpactTracker::Finish(std::int64_t steps) const {
  std::vector<ImpactStatistics> statistics;
  if (CodeAster()) {
    for (const CodeAsterImpactCounter& counter : counters_) statistics.push_back(counter.Finish());
    return statistics;
  }
  const std::int64_t last = std::min(steps, last_step_);
  if (accumulators_.empty() || last <= first_step_) return statistics;
  const double duration_s = static_cast<double>(last - first_step_) * dt_s_;
  for (std::size_t c = 0; c < accumulators_.size(); ++c) {
    ImpactAccumulator accumulator = accumulators_[c];
    if (open_steps_[c] > 0) {
      accumulator.Add(0.0, Idle(c), static_cast<double>(open_steps_[c]) * dt_s_);
    }
    statistics.push_back(accumulator.Finish(duration_s));
  }
  return statistics;
}

double ImpactTracker::Idle(std::size_t c) const {
  return slides_[c] ? 0.0 : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace shockmap

#include "core/impact_tracker.h"

#include <cmath>
#include <limits>

namespace shockmap {

ImpactTracker::ImpactTracker(const SecondOrderSystem& system, const ImpactCounting& counting,
                             const Eigen::VectorXd& v0)
    : system_(system) {
  const auto forces = system.LastContactForces();
  for (std::size_t c = 0; c < forces.size(); ++c) {
    const double speed = system.SlidingSpeed(static_cast<int>(c), v0);
    slides_.push_back(std::isfinite(speed));
    open_steps_.push_back(forces[c] == 0.0 ? 0 : -1);
    accumulators_.emplace_back(counting, forces[c], forces[c] > 0.0 ? speed : Idle(c));
  }
}

void ImpactTracker::Step(const Eigen::VectorXd& v, double dt_s) {
  dt_s_ = dt_s;
  const auto forces = system_.LastContactForces();
  for (std::size_t c = 0; c < forces.size(); ++c) {
    const double force = forces[c];
    std::int64_t& open_steps = open_steps_[c];
    if (force == 0.0 && open_steps >= 0) {
      ++open_steps;
      continue;
    }
    if (open_steps > 0) {
      accumulators_[c].Add(0.0, Idle(c), static_cast<double>(open_steps) * dt_s);
    }
    const bool asks = force > 0.0 && slides_[c];
    accumulators_[c].Add(force, asks ? system_.SlidingSpeed(static_cast<int>(c), v) : Idle(c),
                         dt_s);
    open_steps = force == 0.0 ? 0 : -1;
  }
}

std::vector<ImpactStatistics> ImpactTracker::Finish(double duration_s) const {
  std::vector<ImpactStatistics> statistics;
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

#pragma once
// The impact statistics of every contact of a system through a run (RunTransient's
// track_impact_statistics): one ImpactAccumulator per contact, fed after every step.

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "core/impact_statistics.h"
#include "core/second_order_system.h"

namespace shockmap {

class ImpactTracker {
 public:
  // At the initial state (velocity v0), after the system's first solve. The system must
  // outlive the tracker.
  ImpactTracker(const SecondOrderSystem& system, const ImpactCounting& counting,
                const Eigen::VectorXd& v0);

  // After each step of dt_s (the same every step), at the new velocity v: each contact's force
  // from LastContactForces(). The sliding speed is asked of the system only while the contact
  // carries force (otherwise F v_t = 0), and never for contacts whose tangential motion the
  // system does not carry. A contact open at this step and the one before costs a counter
  // only: its run of zero forces is one piece of zero for its accumulator (most zones of a
  // bundle are open at most steps).
  void Step(const Eigen::VectorXd& v, double dt_s);

  // One per contact, over [0, duration_s].
  std::vector<ImpactStatistics> Finish(double duration_s) const;

 private:
  // The speed passed without asking the system: 0 where it slides (the force is 0), else NaN.
  double Idle(std::size_t c) const;

  const SecondOrderSystem& system_;
  double dt_s_ = 0.0;
  std::vector<bool> slides_;
  // Per contact: -1 while its latest force is positive; else the zero-force steps since the
  // last one passed to its accumulator.
  std::vector<std::int64_t> open_steps_;
  std::vector<ImpactAccumulator> accumulators_;
};

}  // namespace shockmap

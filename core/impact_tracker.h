#pragma once
// The impact statistics of every contact of a system through a run (RunTransient's
// track_impact_statistics), in the convention asked: one ImpactAccumulator (shockmap's) or one
// CodeAsterImpactCounter per contact, fed after every step.

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "core/code_aster_impact_counter.h"
#include "core/impact_statistics.h"
#include "core/second_order_system.h"

namespace shockmap {

class ImpactTracker {
 public:
  // At the initial state (velocity v0), after the system's first solve; steps of dt_s. The
  // contacts `listed` (indices) keep one record per impact. The system must outlive the
  // tracker. Precondition: counting.IsValid().
  ImpactTracker(const SecondOrderSystem& system, const ImpactCounting& counting,
                const std::vector<int>& listed, const Eigen::VectorXd& v0, double dt_s);

  // After each step, at the new velocity v: each contact's force from LastContactForces(). The
  // tangential side is asked of the system only while the contact carries force (otherwise
  // F v_t = 0), and never for contacts whose tangential motion the system does not carry; the
  // penetration rate only for listed contacts carrying force. In shockmap's convention a
  // contact open at this step and the one before costs a counter only: its run of zero forces
  // is one piece of zero for its accumulator (most zones of a bundle are open at most steps).
  void Step(const Eigen::VectorXd& v);

  // One per contact, over the window within the `steps` taken (empty when the window holds
  // no step of them).
  std::vector<ImpactStatistics> Finish(std::int64_t steps) const;

 private:
  bool CodeAster() const { return counting_.convention == ImpactConvention::kCodeAster; }
  // Contact c's sample at velocity v.
  ZoneSample SampleOf(std::size_t c, double force, const Eigen::VectorXd& v) const;
  // The speed passed without asking the system: 0 where it slides (the force is 0), else NaN.
  double Idle(std::size_t c) const;
  // shockmap's convention: the accumulators start at the window's first step.
  void Start(const Eigen::VectorXd& v);
  void StepShockmap(const Eigen::VectorXd& v);

  const SecondOrderSystem& system_;
  ImpactCounting counting_;
  double dt_s_ = 0.0;
  std::int64_t step_ = 0;
  // shockmap's window in steps [first_step_, last_step_].
  std::int64_t first_step_ = 0, last_step_ = 0;
  std::vector<bool> slides_, listed_, friction_;
  // Per contact (shockmap's convention): -1 while its latest force is positive; else the
  // zero-force steps since the last one passed to its accumulator.
  std::vector<std::int64_t> open_steps_;
  std::vector<ImpactAccumulator> accumulators_;
  std::vector<CodeAsterImpactCounter> counters_;
};

}  // namespace shockmap

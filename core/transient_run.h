#pragma once
// One time integration from an initial state to an end time, with the requested histories,
// energy balance, divergence detection and a summary.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/impact_statistics.h"
#include "core/newmark.h"
#include "core/run_status.h"
#include "core/uniform_signal.h"

namespace shockmap {

struct TransientOptions {
  double end_time_s = 0.0;  // Required, > 0.
  // Required, > 0; shortened so that the run ends exactly on end_time_s (at least one step).
  double dt_s = 0.0;
  // Every step: a contact lasts only a few steps near the stability bound.
  int record_stride = 1;
  // Energy costs O(n); growth past the limit is exponential once unstable, so checking every
  // 64 steps stops a diverging run within a few dozen extra steps.
  int divergence_check_stride = 64;
  // Diverged when total energy exceeds this multiple of the initial energy plus the work the
  // loads could have put in: far above the
  // bounded O((omega dt)^2) fluctuation of a stable run. Runs near the sharp bound can still
  // gain energy at contact switches and grow slowly; they cross it later or not at all within
  // the window, and their max_energy_ratio shows it.
  double energy_growth_limit = 1e3;
  // An undamped run that reaches its end with max_energy_ratio above this is kUnstable
  // (core/run_status.h, docs/physics.md §3.1).
  double unstable_energy_ratio = kUnstableEnergyRatio;
  // Called with the simulated time at every divergence check (every divergence_check_stride
  // steps): what a progress display needs, at no cost per step. Runs on the integrating thread.
  std::function<void(double t_s)> on_progress;
  // Refused above this: 1e8 steps of a few modes is minutes; more is a units mistake.
  std::int64_t max_steps = 100'000'000;
  bool record_energy = true;
  bool record_contact_forces = true;  // A force history per contact, or
  // only for these contacts (indices into the system's contacts) when not empty.
  std::vector<int> recorded_contacts;
  // The largest force of each contact over the run, from every step (cheap: no history kept).
  bool track_max_contact_force = false;
  // The impact statistics of each contact (docs/physics.md §6), from every step, streamed (no
  // history kept); contacts and impacts told apart by impact_counting (checked by IsValid), in
  // its convention and window; the contacts listed keep one record per impact.
  bool track_impact_statistics = false;
  ImpactCounting impact_counting;
  std::vector<int> listed_impact_contacts;
  // Displacement histories are recorded at each of these points (row . x), and velocity
  // histories (row . v) too when record_velocity.
  std::vector<Eigen::VectorXd> observed_rows;
  bool record_velocity = true;

  bool IsValid(std::string* error) const;
};

struct RunSummary {
  RunStatus status = RunStatus::kOk;
  std::string message;
  double dt_requested_s = 0.0;
  double dt_used_s = 0.0;
  std::int64_t steps_requested = 0;
  std::int64_t steps_taken = 0;
  double initial_energy_j = 0.0;
  // max over checks of (E + dissipated) / (E0 + integral of |external power|): ~1 or below
  // for a healthy run.
  double max_energy_ratio = 1.0;
  double wall_s = 0.0;
  double cpu_s = 0.0;
};

// kinetic + strain + contact + dissipated = initial + external work, to the scheme's order.
struct EnergyHistory {
  UniformSignal kinetic_j, strain_j, contact_j, dissipated_j, external_work_j;
};

struct TransientResult {
  RunSummary summary;
  std::vector<UniformSignal> displacement_m;  // One per observed row.
  std::vector<UniformSignal> velocity_m_s;    // One per observed row, when recorded.
  // One per contact (or per recorded_contacts entry), when recorded.
  std::vector<UniformSignal> contact_force_n;
  std::vector<double> max_contact_force_n;  // One per contact, when tracked.
  // One per contact, when tracked, over the window within the steps taken (empty if it held
  // none).
  std::vector<ImpactStatistics> impact_statistics;
  EnergyHistory energy;  // Empty unless record_energy.
};

// Precondition: options.IsValid(). Histories start with the initial state at t = 0 and hold
// every record_stride-th step until the run ends (early, if it diverges or fails).
TransientResult RunTransient(SecondOrderSystem& system, NewmarkParameters scheme,
                             const Eigen::VectorXd& x0, const Eigen::VectorXd& v0,
                             const TransientOptions& options);

}  // namespace shockmap

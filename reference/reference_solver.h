#pragma once
// Semi-analytical reference of the canonical problem (paper §2.2, eqs. 1-3; docs/physics.md §2):
// the response is a sequence of linear phases, free or on the spring, each solved exactly. Both
// live on the analytic clamped-free modes below f_ref; on the spring, the modes above f_ref
// act at the tip by their static flexibility, in series with the spring (the residual
// flexibility, or static correction), and the phase is solved on the eigenvectors of that
// rank-one update. A transition is an exact change of coordinates: nothing is projected away.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "core/cantilever_impact.h"
#include "core/uniform_signal.h"
#include "reference/reference_convergence.h"

namespace shockmap {

struct ReferenceOptions {
  // f_ref / f1: the clamped-free modes kept.
  double r_fref = 3000.0;
  double end_time_s = 0.0;  // Required, > 0.
  // Crossings are bracketed by sampling u(L, t) at this many points per shortest retained
  // period, then refined by Brent; only a contact shorter than one step can be missed.
  int crossing_samples_per_period = 16;
  // Guards against an endless run of grazing contacts.
  int max_transitions = 1'000'000;
  // When > 0, ComputeReferenceRun (compare/reference_run.h) raises r_fref threefold until the
  // estimated error (ReferenceConvergence::difference) is at most this, within the budget of
  // reference/reference_cost.h.
  double target_error = 0.0;
  // What ComputeReferenceRun checks the reference against (ReferenceCheck).
  ReferenceCheck check = ReferenceCheck::kFiner;

  bool IsValid(std::string* error) const;
};

// q_i(tau) = e^{-alpha tau / 2} (a_i cos(omega_d,i tau) + b_i sin(omega_d,i tau)) in the phase's
// modal coordinates, tau = t - start_s (paper eq. 2 with xi_i omega_i = alpha / 2 for
// mass-proportional damping C = alpha M).
struct ReferencePhase {
  double start_s = 0.0;
  bool in_contact = false;
  Eigen::VectorXd a, b;
};

struct ReferenceSummary {
  int n_modes_free = 0;
  int n_modes_contact = 0;  // The same coordinates, on the spring.
  // Static tip flexibility of the modes above f_ref (m / N), in series with the spring.
  double residual_flexibility_m_per_n = 0.0;
  int n_transitions = 0;
  double shortest_period_s = 0.0;
  double wall_s = 0.0;
};

// A contact phase of a reference: its interval and the integral of its force over it.
struct ReferenceContact {
  double start_s = 0.0;
  double end_s = 0.0;
  double impulse_n_s = 0.0;
};

// The sampled histories of a reference, on one grid.
struct ReferenceHistories {
  UniformSignal tip_m;
  UniformSignal force_n;  // ContactForce at the same samples.
};

class ReferenceSolution {
 public:
  struct Configuration;
  ReferenceSolution(const CantileverImpact& problem, std::vector<ReferencePhase> phases,
                    std::shared_ptr<const Configuration> free,
                    std::shared_ptr<const Configuration> contact, ReferenceSummary summary);

  // Exact evaluation at any t: the phase by binary search, a cosine and a sine per mode.
  double TipDisplacement(double t_s) const;
  // k_s (g - u(L, t)) during contact phases, 0 otherwise (N).
  double ContactForce(double t_s) const;
  // Samples at t = 0, dt, ... up to end_s inclusive, walking the phases in order with one
  // rotation per mode per sample (RotatingModalSum); within ~1e-13 of the amplitude of
  // TipDisplacement and ContactForce at the same times.
  UniformSignal SampleTipDisplacement(double dt_s, double end_s) const;
  ReferenceHistories SampleHistories(double dt_s, double end_s) const;
  // Output step fine enough for every retained mode: shortest period / 8.
  double OutputStep() const { return summary_.shortest_period_s / 8.0; }

  const std::vector<ReferencePhase>& Phases() const { return phases_; }
  // The contact phases that start before end_s, the last one cut at end_s, each impulse the
  // integral of k_s (g - u(L)) in closed form (no sampling; docs/physics.md §2).
  std::vector<ReferenceContact> Contacts(double end_s) const;
  // 1/2 sum_i omega_d,i^2 (a_i^2 + b_i^2) at the start of phase `index`: undamped and with
  // g = 0, the beam's kinetic and strain energy plus the spring's, the same in every phase
  // since a transition is an exact change of coordinates.
  double PhaseEnergy(std::size_t index) const;
  const ReferenceSummary& Summary() const { return summary_; }

 private:
  const ReferencePhase& PhaseAt(double t_s) const;
  // The tip, and the force unless null, in one pass.
  void Sample(double dt_s, double end_s, UniformSignal& tip, UniformSignal* force) const;
  const Configuration& ConfigurationOf(const ReferencePhase& p) const;

  double gap_m_;
  double stiffness_n_per_m_;
  std::vector<ReferencePhase> phases_;
  std::shared_ptr<const Configuration> free_, contact_;
  ReferenceSummary summary_;
};

// Throws InputError when the reference cannot represent the problem (contact
// damping, or a mode overdamped by the mass-proportional damping), naming the parameter.
// Preconditions: problem.IsValid(), options.IsValid().
ReferenceSolution SolveReference(const CantileverImpact& problem, const ReferenceOptions& options);

}  // namespace shockmap

#pragma once
// The paper's canonical problem (§2.1): a cantilever released from its first mode shape falls
// onto a unilateral spring at its free end.

#include <memory>
#include <string>

#include "core/beam_properties.h"
#include "core/scene.h"
#include "core/scheme.h"
#include "core/second_order_system.h"
#include "core/stability_bounds.h"

namespace shockmap {

struct CantileverImpact {
  BeamProperties beam;
  double r_k = 3000.0;  // k_s / K_bend; the paper's Fig. 3 case.
  double gap_m =
      0.0;  // The paper's value; with g = 0 the response is homogeneous in the amplitude.
  // Tip deflection of the initial first-mode shape, away from the spring (m). Err and SRf do
  // not depend on it when gap_m = 0.
  double initial_tip_m = 1e-3;
  double contact_damping_n_s_per_m = 0.0;
  // C = alpha M: the only damping that is the same operator with and without the spring, and so
  // the only one the reference can represent (docs/physics.md §2).
  double mass_damping_per_s = 0.0;

  double SpringStiffness() const { return r_k * beam.TipBendingStiffness(); }
  double F1Hz() const { return FirstClampedFreeFrequencyHz(beam); }
  bool IsValid(std::string* error) const;
};

// Elements such that every mode below r_ftrunc * f1 has its frequency within 1e-4 of the
// analytic one (at least 20 elements).
int DefaultElementCount(double r_ftrunc);

// The canonical problem as a scene (paper §2.1 in the terms of §3): one clamped-free beam of
// DefaultElementCount(r_ftrunc) elements (or n_elements), truncated at r_ftrunc times the
// analytic f1 (absolute, as the implicit model's bounds are computed), a stop at the tip
// with the problem's gap, stiffness and damping, the first mode scaled to initial_tip_m, and
// C = alpha M as modal damping (2 xi_i Omega_i = alpha for every mode). Outputs: the tip
// displacement, the contact force, the energies. Time step and end time are left to the
// caller. The scene declares no load, so its model does not refer back to it.
// Preconditions: problem.IsValid(), r_ftrunc >= 1, n_elements >= 0.
Scene CanonicalScene(const CantileverImpact& problem, double r_ftrunc, int n_elements = 0);

// A discretized problem ready to integrate.
struct ImpactModel {
  std::unique_ptr<SecondOrderSystem> system;
  Eigen::VectorXd x0, v0;
  Eigen::VectorXd tip_row;  // Generalized coordinates -> tip deflection (m).
  int n_modes = 0;          // Modes kept below f_trunc (the explicit model's size).
  int n_dofs = 0;           // Size of the integrated system.
  int n_elements = 0;
  // Of the modal model truncated at f_trunc, whatever the scheme; dt_paper from the higher of
  // f_trunc and the mode kept when none lies below it (r_ftrunc = 1), as for any scene.
  StabilityBounds bounds;
};

// The explicit modal scheme integrates the scene model of CanonicalScene (the paper's eq. 7);
// the implicit one the full FE model with the same mesh.
// Preconditions: problem.IsValid(), r_ftrunc >= 1, n_elements >= 1 (or 0 for the default).
ImpactModel BuildImpactModel(const CantileverImpact& problem, Scheme scheme, double r_ftrunc,
                             int n_elements = 0);

}  // namespace shockmap

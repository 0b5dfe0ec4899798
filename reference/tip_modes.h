#pragma once
// The clamped-free beam seen from its tip (docs/physics.md §2): its analytic modes below a
// truncation, their mass-normalized tip deflections, and the static tip flexibility of every
// mode above it (the residual flexibility, the classical static correction at a contact point).

#include <Eigen/Dense>

#include "core/beam_properties.h"

namespace shockmap {

struct TipModes {
  Eigen::VectorXd omega_rad_s;  // Ascending: every mode with f <= f_max (at least one).
  Eigen::VectorXd tip;          // phi_n(L) (1 / sqrt(kg)), phi_n mass-normalized.
  // sum over the modes above of phi_n(L)^2 / omega_n^2 (m / N).
  double residual_flexibility_m_per_n = 0.0;
};

TipModes ClampedFreeTipModes(const BeamProperties& beam, double f_max_hz);

// sum over n > n_kept of phi_n(L)^2 / omega_n^2: the roots up to mode 40 summed one by one, the
// rest from b_n = (n - 1/2) pi and phi_n(L)^2 = 4 / m (exact there to e^-b_n) as a Hurwitz zeta
// function. For n_kept = 0 it is the beam's static tip flexibility L^3 / (3 EI). n_kept >= 0.
double ResidualTipFlexibility(const BeamProperties& beam, int n_kept);

}  // namespace shockmap

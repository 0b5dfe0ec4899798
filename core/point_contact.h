#pragma once
// Penalty contact of one physical point against a stop (paper eq. 5).

#include <Eigen/Dense>

namespace shockmap {

// The stop lies below the point: contact when the point's displacement u < gap_m, and the
// stop then pushes in the +u direction. `row` maps the generalized coordinates of the system
// (modal or finite-element) to u, so the generalized force is row * F.
struct PointContact {
  Eigen::VectorXd row;
  double gap_m = 0.0;
  double stiffness_n_per_m = 0.0;
  double damping_n_s_per_m = 0.0;  // Viscous, acts only while in contact.
};

// F = k (g - u) - c v while u < g, clamped at zero so the stop never pulls; else 0 (N).
inline double PenaltyForce(const PointContact& c, double u_m, double v_m_s) {
  if (u_m >= c.gap_m) return 0.0;
  const double f = c.stiffness_n_per_m * (c.gap_m - u_m) - c.damping_n_s_per_m * v_m_s;
  return f > 0.0 ? f : 0.0;
}

// Elastic energy stored in the penalty spring (J).
inline double PenaltyEnergy(const PointContact& c, double u_m) {
  const double d = c.gap_m - u_m;
  return d > 0.0 ? 0.5 * c.stiffness_n_per_m * d * d : 0.0;
}

}  // namespace shockmap

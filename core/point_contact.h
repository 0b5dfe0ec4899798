#pragma once
// Penalty contact of one physical point against a stop (paper eq. 5), through its normal law
// (core/contact_law.h).

#include <Eigen/Dense>

#include "core/contact_law.h"

namespace shockmap {

// The stop lies below the point: contact when the point's displacement u < gap_m, the
// penetration then g - u, and the stop pushes in the +u direction. `row` maps the generalized
// coordinates of the system (modal or finite-element) to u, so the generalized force is row * F.
struct PointContact {
  Eigen::VectorXd row;
  double gap_m = 0.0;
  NormalLaw law;  // Its damping acts only while in contact.
};

// The law's force at displacement u and velocity v: F(g - u, -v) (N, >= 0).
inline double PenaltyForce(const PointContact& c, double u_m, double v_m_s) {
  return c.law.Force(c.gap_m - u_m, -v_m_s);
}

// Elastic energy stored in the contact (J).
inline double PenaltyEnergy(const PointContact& c, double u_m) {
  return c.law.Energy(c.gap_m - u_m);
}

}  // namespace shockmap

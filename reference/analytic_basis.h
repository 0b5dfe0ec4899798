#pragma once
// Mass-normalized analytic modal basis of one linear configuration of the impact problem, and
// the Galerkin projections between configurations (paper eqs. 1-3).

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "core/beam_properties.h"
#include "reference/analytic_modes.h"

namespace shockmap {

// The root b of a mode at frequency f_hz: omega = b^2 sqrt(EI / (rho A L^4)).
double RootOfFrequency(const BeamProperties& beam, double f_hz);

// Composite Gauss-Legendre rule on xi = x / L in [0, 1], fine enough to integrate products of
// two modes with b <= b_max to rounding.
struct BeamQuadrature {
  std::vector<double> xi;
  std::vector<double> weight;  // Sums to 1.
};
BeamQuadrature MakeBeamQuadrature(double b_max);
// The number of nodes MakeBeamQuadrature(b_max) has.
int BeamQuadratureNodes(double b_max);

struct AnalyticBasis {
  double kappa = 0.0;  // k_s L^3 / EI; 0 for clamped-free.
  std::vector<ModeShape> shapes;
  Eigen::VectorXd omega_rad_s;
  // phi_i(x) = scale_i W_i(b_i x / L) has integral of rho A phi_i^2 over the beam equal to 1.
  Eigen::VectorXd scale;  // 1 / sqrt(kg)
  Eigen::VectorXd tip;    // phi_i(L), 1 / sqrt(kg)
  // phi_j at node k of the quadrature the basis was made with (nodes x modes), sampled once
  // for its normalization and every projection.
  Eigen::MatrixXd on_nodes;

  int NumModes() const { return static_cast<int>(shapes.size()); }
  double Phi(int i, double xi) const { return scale[i] * shapes[i].Value(xi); }
};

// Every mode with frequency <= f_max_hz (at least one).
AnalyticBasis MakeAnalyticBasis(const BeamProperties& beam, double kappa, double f_max_hz,
                                const BeamQuadrature& quadrature);

// P_ij = integral of rho A phi^to_i phi^from_j: maps modal coordinates of `from` onto `to`.
// Both bases were made with `quadrature`.
Eigen::MatrixXd MassProjection(const BeamProperties& beam, const AnalyticBasis& to,
                               const AnalyticBasis& from, const BeamQuadrature& quadrature);

// c_i = integral of rho A phi_i(x) u(x) dx for a deflection u given as a function of xi = x / L;
// the basis was made with `quadrature`.
Eigen::VectorXd ProjectDeflection(const BeamProperties& beam, const AnalyticBasis& basis,
                                  const std::function<double(double)>& u_of_xi,
                                  const BeamQuadrature& quadrature);

}  // namespace shockmap

#include "reference/tip_modes.h"

#include <gsl/gsl_sf_zeta.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "reference/analytic_modes.h"

namespace shockmap {
namespace {

// Beyond this mode the roots are (n - 1/2) pi and |W_n(L)| = 2 to rounding.
constexpr int kAsymptoticFrom = 40;

// phi(L) of the mode of root b: W(1) / sqrt(rho A L), the classical shape having
// integral of W^2 over [0, 1] equal to 1 (checked against quadrature in the tests).
double TipOf(const BeamProperties& beam, double b) {
  return ModeShape(b).Value(1.0) / std::sqrt(beam.Mass());
}

}  // namespace

TipModes ClampedFreeTipModes(const BeamProperties& beam, double f_max_hz) {
  const double b_max = std::sqrt(2.0 * std::numbers::pi * f_max_hz / beam.OmegaOf(1.0));
  const std::vector<double> roots = CharacteristicRoots(0.0, b_max, 1);
  const int n = static_cast<int>(roots.size());
  TipModes m;
  m.omega_rad_s.resize(n);
  m.tip.resize(n);
  for (int i = 0; i < n; ++i) {
    m.omega_rad_s[i] = beam.OmegaOf(roots[i]);
    m.tip[i] = TipOf(beam, roots[i]);
  }
  m.residual_flexibility_m_per_n = ResidualTipFlexibility(beam, n);
  return m;
}

double ResidualTipFlexibility(const BeamProperties& beam, int n_kept) {
  const int explicit_to = std::max(n_kept, kAsymptoticFrom);
  // sum over n > explicit_to of (4 / m) / omega_n^2, omega_n = ((n - 1/2) pi)^2 OmegaOf(1).
  const double omega_unit = beam.OmegaOf(1.0);
  double sum = 4.0 / beam.Mass() / (omega_unit * omega_unit) *
               gsl_sf_hzeta(4.0, explicit_to + 0.5) / std::pow(std::numbers::pi, 4);
  if (n_kept < explicit_to) {
    const std::vector<double> roots = CharacteristicRoots(0.0, 0.0, explicit_to);
    for (int i = explicit_to - 1; i >= n_kept; --i) {  // Smallest terms first.
      const double omega = beam.OmegaOf(roots[i]);
      const double tip = TipOf(beam, roots[i]);
      sum += tip * tip / (omega * omega);
    }
  }
  return sum;
}

}  // namespace shockmap

#pragma once
// Euler-Bernoulli beam data and the paper's canonical values (paper §2.1).

#include <string>

namespace shockmap {

struct BeamProperties {
  double length_m = 1.0;          // The paper gives no length; frequencies do not depend on it.
  double ei_n_m2 = 1.5e5;         // K_bend = 3 EI / L^3 = 4.5e5 N/m with L = 1 m (paper §2.1).
  double rho_a_kg_per_m = 127.0;  // Total mass 127 kg over 1 m (paper §2.1).

  // Bending stiffness at the tip of the clamped-free beam, K_bend = 3 EI / L^3 (N/m).
  double TipBendingStiffness() const { return 3.0 * ei_n_m2 / (length_m * length_m * length_m); }
  double Mass() const { return rho_a_kg_per_m * length_m; }
  // Natural circular frequency of the dimensionless mode b = beta L: omega = b^2 sqrt(EI/(rho A
  // L^4)).
  double OmegaOf(double b) const;
  bool IsValid(std::string* error) const;
};

// First clamped-free root of 1 + cosh b cos b = 0.
inline constexpr double kClampedFreeB1 = 1.8751040687119611;

// f1 of the clamped-free beam (Hz), 19.23 Hz for the paper's beam.
double FirstClampedFreeFrequencyHz(const BeamProperties& beam);

}  // namespace shockmap

#pragma once
// Analytic bending modes of a beam clamped at x = 0 with a spring k_s at its free end x = L
// (paper §2.2; kappa = k_s L^3 / EI = 3 R_k, kappa = 0 is the clamped-free beam).

#include <vector>

namespace shockmap {

// The characteristic equation 1 + cosh b cos b + (kappa / b^3)(sin b cosh b - cos b sinh b) = 0
// divided by cosh b, so that it keeps its digits for large b = beta L.
double CharacteristicFunction(double b, double kappa);

// The first roots b_n in ascending order: every root up to b_max, and at least `min_count`.
// Brackets by scanning (roots are about pi apart), refines with GSL's Brent solver to 1e-15.
std::vector<double> CharacteristicRoots(double kappa, double b_max, int min_count = 1);

// Mode shape W(z) = cosh z - cos z - sigma (sinh z - sin z), z = b x / L, with
// sigma = (cosh b + cos b) / (sinh b + sin b) from the zero moment at the tip (same in both
// configurations). Evaluated without cancellation: the growing part (1 - sigma) e^z / 2 is
// formed analytically, so shapes stay exact to rounding for any b.
class ModeShape {
 public:
  explicit ModeShape(double b);
  double B() const { return b_; }
  // d^k W / dz^k at z = b xi, xi = x / L in [0, 1], k in 0..3.
  double Derivative(int k, double xi) const;
  double Value(double xi) const { return Derivative(0, xi); }

 private:
  double b_;
  double sigma_;
  double growing_;  // (sin b - cos b - e^-b) / (1 - e^-2b + 2 e^-b sin b): (1 - sigma) e^z / 2 =
                    // growing_ e^(z - b)
};

}  // namespace shockmap

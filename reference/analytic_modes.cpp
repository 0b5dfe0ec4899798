#include "reference/analytic_modes.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cassert>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace shockmap {

double CharacteristicFunction(double b, double kappa) {
  // (1 + cosh b cos b) / cosh b + (kappa / b^3)(sin b - cos b tanh b).
  return 1.0 / std::cosh(b) + std::cos(b) +
         kappa / (b * b * b) * (std::sin(b) - std::cos(b) * std::tanh(b));
}

namespace {

double BrentRoot(double kappa, double lo, double hi) {
  struct Params {
    double kappa;
  } params{kappa};
  gsl_function f;
  f.function = [](double b, void* p) {
    return CharacteristicFunction(b, static_cast<Params*>(p)->kappa);
  };
  f.params = &params;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &f, lo, hi);
  for (int iter = 0; iter < 200; ++iter) {
    gsl_root_fsolver_iterate(solver.get());
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
  }
  return gsl_root_fsolver_root(solver.get());
}

}  // namespace

std::vector<double> CharacteristicRoots(double kappa, double b_max, int min_count) {
  assert(kappa >= 0.0);
  // Consecutive roots are at least ~pi/2 apart for every kappa (they interlace the clamped-free
  // and clamped-pinned roots), so a scan step of 0.05 cannot step over a pair.
  constexpr double kScanStep = 0.05;
  std::vector<double> roots;
  double lo = 0.5;  // F(b) -> 2 + 2 kappa / 3 > 0 as b -> 0; the first root is above 1.8.
  double f_lo = CharacteristicFunction(lo, kappa);
  while (lo <= b_max || static_cast<int>(roots.size()) < min_count) {
    const double hi = lo + kScanStep;
    const double f_hi = CharacteristicFunction(hi, kappa);
    if (f_lo == 0.0) {
      roots.push_back(lo);
    } else if ((f_lo < 0.0) != (f_hi < 0.0)) {
      const double root = BrentRoot(kappa, lo, hi);
      if (root > b_max && static_cast<int>(roots.size()) >= min_count) break;
      roots.push_back(root);
    }
    lo = hi;
    f_lo = f_hi;
  }
  return roots;
}

ModeShape::ModeShape(double b) : b_(b) {
  const double e1 = std::exp(-b);
  const double e2 = e1 * e1;
  const double den = 1.0 - e2 + 2.0 * e1 * std::sin(b);
  sigma_ = (1.0 + e2 + 2.0 * e1 * std::cos(b)) / den;
  growing_ = (std::sin(b) - std::cos(b) - e1) / den;
}

double ModeShape::Derivative(int k, double xi) const {
  assert(k >= 0 && k <= 3);
  const double z = b_ * xi;
  const double grow = growing_ * std::exp(z - b_);           // (1 - sigma) e^z / 2
  const double decay = 0.5 * (1.0 + sigma_) * std::exp(-z);  // (1 + sigma) e^-z / 2
  const double c = std::cos(z);
  const double s = std::sin(z);
  switch (k) {
    case 0:
      return grow + decay - c + sigma_ * s;
    case 1:
      return grow - decay + s + sigma_ * c;
    case 2:
      return grow + decay + c - sigma_ * s;
    default:
      return grow - decay - s - sigma_ * c;
  }
}

}  // namespace shockmap

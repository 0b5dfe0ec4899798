#include "core/beam_properties.h"

#include <cmath>
#include <numbers>

#include "core/validity.h"

namespace shockmap {

double BeamProperties::OmegaOf(double b) const {
  const double l2 = length_m * length_m;
  return b * b * std::sqrt(ei_n_m2 / (rho_a_kg_per_m * l2 * l2));
}

bool BeamProperties::IsValid(std::string* error) const {
  return RequirePositive("length_m", length_m, error) &&
         RequirePositive("ei_n_m2", ei_n_m2, error) &&
         RequirePositive("rho_a_kg_per_m", rho_a_kg_per_m, error);
}

double FirstClampedFreeFrequencyHz(const BeamProperties& beam) {
  return beam.OmegaOf(kClampedFreeB1) / (2.0 * std::numbers::pi);
}

}  // namespace shockmap

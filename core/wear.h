#pragma once
// Archard's wear of a contact zone over the assembly's life, as code_aster's POST_USURE applies
// its ARCHARD law to a wear work rate (docs/physics.md §6.3).

namespace shockmap {

struct WearLaw {
  // K: worn volume per unit of normal force and sliding distance (m^3 / (N m) = m^2 / N).
  double coefficient_m2_per_n = 0.0;
  // The life the statistics of the simulated load are extended over (s).
  double life_s = 0.0;
};

// V = K P T: the volume worn over the life T at the wear work rate P (W = N m / s), the time
// average of the normal force times the sliding speed (ImpactStatistics::wear_work_rate_w).
inline double ArchardWearVolume(const WearLaw& law, double wear_work_rate_w) {
  return law.coefficient_m2_per_n * wear_work_rate_w * law.life_s;
}

}  // namespace shockmap

#include "validation/spectral_error.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace shockmap {

double SpectralError(const UniformSignal& numerical, const UniformSignal& reference,
                     double t_begin_s, double t_end_s, const PsdOptions& options) {
  return SpectralError(numerical, OneSidedPsd(reference, t_begin_s, t_end_s, options), t_begin_s,
                       t_end_s, options);
}

double SpectralError(const UniformSignal& numerical, const PowerSpectrum& g_ref, double t_begin_s,
                     double t_end_s, const PsdOptions& options) {
  const PowerSpectrum g_num = OneSidedPsd(numerical, t_begin_s, t_end_s, options);
  // Same options and window give the same bins; anything else is a bug in the caller.
  assert(g_num.density.size() == g_ref.density.size() && g_num.df_hz == g_ref.df_hz);

  double max_difference = 0.0;
  double max_num = 0.0;
  double max_ref = 0.0;
  for (std::size_t k = 0; k < g_num.density.size(); ++k) {
    max_difference = std::max(max_difference, std::abs(g_num.density[k] - g_ref.density[k]));
    max_num = std::max(max_num, g_num.density[k]);
    max_ref = std::max(max_ref, g_ref.density[k]);
  }
  const double normalization = std::max(max_num, max_ref);
  return normalization > 0.0 ? max_difference / normalization : 0.0;
}

}  // namespace shockmap

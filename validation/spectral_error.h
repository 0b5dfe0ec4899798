#pragma once
// Spectral error between a numerical and a reference history, paper eq. (8) (§2.4).

#include "core/uniform_signal.h"
#include "validation/psd.h"

namespace shockmap {

// Err = max_f |G_num(f) - G_ref(f)| / max(max_f G_num(f), max_f G_ref(f))   (paper eq. 8),
// with G the one-sided PSDs of both signals computed by OneSidedPsd with the same options over
// the same window [t_begin_s, t_end_s] (so the bins coincide). Dimensionless, in [0, 1]: 0 for
// identical spectra, 1 when one spectrum vanishes wherever the other has its maximum.
// Returns 0 when both spectra are identically zero. The two signals may have different t0_s
// and dt_s; the window must lie within both. Throws std::invalid_argument as OneSidedPsd does.
double SpectralError(const UniformSignal& numerical, const UniformSignal& reference,
                     double t_begin_s, double t_end_s, const PsdOptions& options);

// The same against the reference's spectrum, computed once by OneSidedPsd with these options
// over this window (a reference scored against many runs); equal to the above bit for bit.
double SpectralError(const UniformSignal& numerical, const PowerSpectrum& reference,
                     double t_begin_s, double t_end_s, const PsdOptions& options);

}  // namespace shockmap

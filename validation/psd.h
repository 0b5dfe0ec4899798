#pragma once
// One-sided power spectral density of a sampled history over an observation window: the G(f) of
// the paper's spectral error, eq. (8) (§2.4).
//
// Pipeline, identical for every signal so that two spectra are comparable bin by bin:
//   1. resample: n_samples points t_i = t_begin + i T / n_samples, i = 0 .. n_samples - 1,
//      T = t_end - t_begin, by linear interpolation of the input (UniformSignal::At). The end
//      point is excluded, so a signal with an integer number of periods over the window is
//      exactly periodic for the DFT. fs = n_samples / T. This is point resampling without an
//      anti-alias filter: content of the input above fs / 2 folds back; it folds identically for
//      the numerical and the reference signal, which is what eq. (8) compares.
//   2. the mean is NOT removed: the mean position of a bouncing beam is physical.
//   3. multiply by the window w_i (rectangular, or periodic Hann 0.5 (1 - cos(2 pi i / n))).
//   4. zero-pad to N = the next power of two >= n_samples * zero_padding_factor and take the
//      real-to-complex DFT X_k = sum_i w_i x_i exp(-2 pi j i k / N) (FFTW r2c).
//   5. scale: G_k = c_k |X_k|^2 / (fs sum_i w_i^2), c_k = 2 except c_0 = c_{N/2} = 1, at
//      f_k = k df, df = fs / N, k = 0 .. N/2. Units: (signal units)^2 / Hz. With
//      one_sided = false, c_k = 1 for every k: the positive-frequency half of the two-sided
//      density, whose DC bin weighs twice as much against the others.
// With this scaling sum_k G_k df = sum_i (w_i x_i)^2 / sum_i w_i^2, i.e. exactly the mean square
// of the resampled samples for the rectangular window (Parseval) and a window-weighted mean
// square for Hann.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/uniform_signal.h"

namespace shockmap {

enum class PsdWindow { kRectangular, kHann };

// "rectangular", "hann".
std::string ToString(PsdWindow window);
// Inverse of ToString; std::nullopt for any other string (case-sensitive).
std::optional<PsdWindow> PsdWindowFromString(std::string_view name);

// The one range of each PSD option, which PsdOptions::IsValid and a study file's "scoring.psd"
// both take: at least 16 points over the window, at most 2^22 (with the largest padding an FFT
// of 2^28 doubles, 2 GiB, within the int lengths FFTW takes).
inline constexpr int kMinPsdSamples = 16;
inline constexpr int kMaxPsdSamples = 1 << 22;
inline constexpr int kMaxZeroPaddingFactor = 64;

struct PsdOptions {
  // Resampled points over the window. Nyquist is n_samples / (2 T): over a 0.3 s window 4096
  // points reach 6.8 kHz ~ 350 f1, above the shock frequency sqrt(R_k) f1 for R_k <= 1e5.
  int n_samples = 4096;
  // The window rarely holds an integer number of periods; Hann's sidelobes decay as 1/f^3, so
  // leakage from the dominant low modes does not bury the high-frequency content Err compares.
  PsdWindow window = PsdWindow::kHann;
  // 4x padding interpolates the spectrum so the max in eq. (8) hardly depends on where a peak
  // falls between the bins of the unpadded DFT.
  int zero_padding_factor = 4;
  // One-sided scaling (c_k = 2 off DC and Nyquist), else two-sided (c_k = 1): eq. (8) divides
  // by the largest density, so only the weight of DC against the other bins changes.
  bool one_sided = true;

  // FFT length N: the next power of two >= n_samples * zero_padding_factor. Requires IsValid().
  int FftLength() const;
  // n_samples in [kMinPsdSamples, kMaxPsdSamples], zero_padding_factor in [1,
  // kMaxZeroPaddingFactor], a known window; else false, with what is allowed in `error`.
  bool IsValid(std::string* error) const;
  bool operator==(const PsdOptions&) const = default;
};

struct PowerSpectrum {
  double df_hz = 0.0;           // Bin spacing fs / N (Hz).
  std::vector<double> density;  // G_k at f_k = k df_hz, k = 0 .. N/2; units^2 / Hz.

  double FrequencyAt(std::size_t k) const { return static_cast<double>(k) * df_hz; }
};

// Step 1 of the pipeline above, exposed so callers and tests see exactly what is transformed:
// n_samples values at t_begin_s + i (t_end_s - t_begin_s) / n_samples.
// Throws std::invalid_argument unless t_begin_s < t_end_s are finite, the window lies within
// [s.t0_s, s.EndTime()] (to rounding), s has >= 2 samples with dt_s > 0, n_samples >= 2, and
// every input sample in the window is finite (a diverged run must be reported as such, not
// scored).
std::vector<double> ResampleForPsd(const UniformSignal& s, double t_begin_s, double t_end_s,
                                   int n_samples);

// One-sided periodogram of s over [t_begin_s, t_end_s] as described at the top of this file.
// Throws std::invalid_argument on invalid options or on the conditions of ResampleForPsd.
// Thread-safe: each thread plans a transform of a given length and window once and reuses it
// (its plan, arrays and window weights) for every later spectrum of that shape; FFTW plan
// creation and destruction are serialized by a process-wide mutex (the FFTW planner is not
// re-entrant); the transforms themselves run concurrently.
PowerSpectrum OneSidedPsd(const UniformSignal& s, double t_begin_s, double t_end_s,
                          const PsdOptions& options);

}  // namespace shockmap

#include "validation/psd.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include "core/exact_text.h"

namespace shockmap {
namespace {

// The FFTW planner keeps global state: every fftw_plan_* and fftw_destroy_plan call in the
// process must hold this lock. fftw_execute on distinct plans/arrays needs no lock.
std::mutex& FftwPlannerMutex() {
  static std::mutex mutex;
  return mutex;
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

struct FftwPlanDestroy {
  void operator()(fftw_plan_s* plan) const {
    const std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    fftw_destroy_plan(plan);
  }
};

std::int64_t NextPowerOfTwo(std::int64_t n) {
  std::int64_t p = 1;
  while (p < n) {
    p *= 2;
  }
  return p;
}

}  // namespace

std::string ToString(PsdWindow window) {
  switch (window) {
    case PsdWindow::kRectangular:
      return "rectangular";
    case PsdWindow::kHann:
      return "hann";
  }
  return "unknown";
}

std::optional<PsdWindow> PsdWindowFromString(std::string_view name) {
  for (const PsdWindow w : {PsdWindow::kRectangular, PsdWindow::kHann}) {
    if (name == ToString(w)) {
      return w;
    }
  }
  return std::nullopt;
}

int PsdOptions::FftLength() const {
  return static_cast<int>(NextPowerOfTwo(std::int64_t{n_samples} * zero_padding_factor));
}

bool PsdOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) {
      *error = message;
    }
    return false;
  };
  if (n_samples < kMinPsdSamples || n_samples > kMaxPsdSamples) {
    return fail("n_samples = " + std::to_string(n_samples) + ": must be a whole number from " +
                std::to_string(kMinPsdSamples) + " to " + std::to_string(kMaxPsdSamples));
  }
  if (zero_padding_factor < 1 || zero_padding_factor > kMaxZeroPaddingFactor) {
    return fail("zero_padding_factor = " + std::to_string(zero_padding_factor) +
                ": must be a whole number from 1 to " + std::to_string(kMaxZeroPaddingFactor));
  }
  if (window != PsdWindow::kRectangular && window != PsdWindow::kHann) {
    return fail("window = " + std::to_string(static_cast<int>(window)) +
                ": must be rectangular or hann");
  }
  return true;
}

std::vector<double> ResampleForPsd(const UniformSignal& s, double t_begin_s, double t_end_s,
                                   int n_samples) {
  if (!std::isfinite(t_begin_s) || !std::isfinite(t_end_s) || !(t_begin_s < t_end_s)) {
    throw std::invalid_argument("PSD observation window [" + ExactText(t_begin_s) + ", " +
                                ExactText(t_end_s) + "] s: must be finite with begin < end");
  }
  if (n_samples < 2) {
    throw std::invalid_argument("PSD n_samples = " + std::to_string(n_samples) + ": must be >= 2");
  }
  if (s.values.size() < 2 || !std::isfinite(s.dt_s) || !(s.dt_s > 0.0) || !std::isfinite(s.t0_s)) {
    throw std::invalid_argument("PSD input signal (" + std::to_string(s.values.size()) +
                                " samples, dt_s = " + ExactText(s.dt_s) +
                                "): must have >= 2 samples and a finite dt_s > 0");
  }
  // Rounding slack on the window bounds: a caller passing t_end = the nominal end of a run must
  // not be refused because t0 + (n - 1) dt rounded down by an ulp.
  const double magnitude =
      std::max({std::abs(t_begin_s), std::abs(t_end_s), std::abs(s.t0_s), std::abs(s.EndTime())});
  const double slack = 1e-6 * s.dt_s + 8.0 * std::numeric_limits<double>::epsilon() * magnitude;
  if (t_begin_s < s.t0_s - slack || t_end_s > s.EndTime() + slack) {
    throw std::invalid_argument("PSD observation window [" + ExactText(t_begin_s) + ", " +
                                ExactText(t_end_s) + "] s: must lie within the signal [" +
                                ExactText(s.t0_s) + ", " + ExactText(s.EndTime()) + "] s");
  }
  // Every input sample the window touches must be finite, not only those the resampling lands
  // next to: a NaN between two resampled points would otherwise pass unseen.
  const auto last = static_cast<double>(s.values.size() - 1);
  const auto i_lo =
      static_cast<std::size_t>(std::clamp(std::floor((t_begin_s - s.t0_s) / s.dt_s), 0.0, last));
  const auto i_hi =
      static_cast<std::size_t>(std::clamp(std::ceil((t_end_s - s.t0_s) / s.dt_s), 0.0, last));
  for (std::size_t i = i_lo; i <= i_hi; ++i) {
    if (!std::isfinite(s.values[i])) {
      throw std::invalid_argument("PSD input signal is not finite at t = " +
                                  ExactText(s.TimeAt(i)) + " s: a diverged run cannot be scored");
    }
  }
  const double step_s = (t_end_s - t_begin_s) / n_samples;
  std::vector<double> x(static_cast<std::size_t>(n_samples));
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = s.At(t_begin_s + static_cast<double>(i) * step_s);
  }
  return x;
}

namespace {

// One thread's transform of one length and window: its FFTW plan, its aligned arrays and its
// window weights, made on first use and reused by every later spectrum of that shape on the
// thread, so that planning (and the twiddle factors it computes) is paid once per thread.
struct Transform {
  int n_samples = 0;
  int n_fft = 0;
  PsdWindow window = PsdWindow::kHann;
  std::unique_ptr<double, FftwFree> in;
  std::unique_ptr<fftw_complex, FftwFree> out;
  std::unique_ptr<fftw_plan_s, FftwPlanDestroy> plan;
  std::vector<double> weights;
  double sum_w2 = 0.0;
};

std::unique_ptr<Transform> MakeTransform(int n_samples, int n_fft, PsdWindow window) {
  auto t = std::make_unique<Transform>();
  t->n_samples = n_samples;
  t->n_fft = n_fft;
  t->window = window;
  const auto n_bins = static_cast<std::size_t>(n_fft) / 2 + 1;
  t->in.reset(fftw_alloc_real(static_cast<std::size_t>(n_fft)));
  t->out.reset(fftw_alloc_complex(n_bins));
  if (!t->in || !t->out) throw std::bad_alloc();
  {
    const std::lock_guard<std::mutex> lock(FftwPlannerMutex());
    t->plan.reset(fftw_plan_dft_r2c_1d(n_fft, t->in.get(), t->out.get(), FFTW_ESTIMATE));
  }
  if (!t->plan) {
    throw std::runtime_error("FFTW could not plan an r2c transform of length " +
                             std::to_string(n_fft));
  }
  const auto n = static_cast<double>(n_samples);
  t->weights.resize(static_cast<std::size_t>(n_samples));
  for (std::size_t i = 0; i < t->weights.size(); ++i) {
    const double w =
        window == PsdWindow::kHann
            ? 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / n))
            : 1.0;
    t->weights[i] = w;
    t->sum_w2 += w * w;
  }
  return t;
}

// This thread's transform of that shape; the few most recently used shapes are kept.
Transform& TransformFor(int n_samples, int n_fft, PsdWindow window) {
  constexpr std::size_t kKept = 4;
  thread_local std::vector<std::unique_ptr<Transform>> kept;  // Most recently used last.
  for (auto it = kept.begin(); it != kept.end(); ++it) {
    const Transform& t = **it;
    if (t.n_samples == n_samples && t.n_fft == n_fft && t.window == window) {
      std::rotate(it, it + 1, kept.end());
      return *kept.back();
    }
  }
  if (kept.size() == kKept) kept.erase(kept.begin());
  kept.push_back(MakeTransform(n_samples, n_fft, window));
  return *kept.back();
}

}  // namespace

PowerSpectrum OneSidedPsd(const UniformSignal& s, double t_begin_s, double t_end_s,
                          const PsdOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) {
    throw std::invalid_argument("PsdOptions: " + error);
  }
  const std::vector<double> x = ResampleForPsd(s, t_begin_s, t_end_s, options.n_samples);
  const std::size_t n = x.size();
  const double fs_hz = static_cast<double>(n) / (t_end_s - t_begin_s);
  Transform& t = TransformFor(options.n_samples, options.FftLength(), options.window);
  const std::size_t n_bins = static_cast<std::size_t>(t.n_fft) / 2 + 1;
  double* in = t.in.get();
  for (std::size_t i = 0; i < n; ++i) in[i] = t.weights[i] * x[i];
  std::fill(in + n, in + t.n_fft, 0.0);
  fftw_execute(t.plan.get());

  PowerSpectrum psd;
  psd.df_hz = fs_hz / t.n_fft;
  psd.density.resize(n_bins);
  const double scale = 1.0 / (fs_hz * t.sum_w2);
  const fftw_complex* out = t.out.get();
  for (std::size_t k = 0; k < n_bins; ++k) {
    const double re = out[k][0];
    const double im = out[k][1];
    const bool unpaired = (k == 0 || k == n_bins - 1);  // DC and Nyquist have no mirror bin.
    psd.density[k] = (unpaired || !options.one_sided ? 1.0 : 2.0) * (re * re + im * im) * scale;
  }
  return psd;
}

}  // namespace shockmap

// Verification of the scores (paper §2.4): PSD scaling against Parseval and analytic peaks, the
// spectral error eq. (8) against its analytic value for scaled copies, the impulse ratio eq. (9),
// and shock segmentation against half-sine contacts of known impulse 2 F T / pi.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/uniform_signal.h"
#include "validation/impulse_ratio.h"
#include "validation/psd.h"
#include "validation/scores.h"
#include "validation/shock_segmentation.h"
#include "validation/spectral_error.h"

namespace shockmap {
namespace {

constexpr double kPi = std::numbers::pi;

// Samples g(t0 + i dt), i = 0 .. n - 1.
template <typename F>
UniformSignal Sample(double t0_s, double dt_s, std::size_t n, F g) {
  UniformSignal s{.t0_s = t0_s, .dt_s = dt_s, .values = std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    s.values[i] = g(s.TimeAt(i));
  }
  return s;
}

double MeanSquare(const std::vector<double>& x) {
  double sum = 0.0;
  for (const double v : x) {
    sum += v * v;
  }
  return sum / static_cast<double>(x.size());
}

double Integral(const PowerSpectrum& psd) {
  double sum = 0.0;
  for (const double g : psd.density) {
    sum += g;
  }
  return sum * psd.df_hz;
}

std::size_t ArgMax(const std::vector<double>& x) {
  return static_cast<std::size_t>(std::max_element(x.begin(), x.end()) - x.begin());
}

// A damped two-mode "bouncing" history with a nonzero mean, on a grid unrelated to the PSD's.
UniformSignal GenericDisplacement() {
  return Sample(0.0, 1.3e-5, 40000, [](double t) {
    return 2e-3 + 1e-3 * std::exp(-3.0 * t) * std::cos(2.0 * kPi * 19.23 * t) +
           2e-4 * std::sin(2.0 * kPi * 120.7 * t + 0.3);
  });
}

// ---------------------------------------------------------------------------------------------
// PsdWindow / PsdOptions

TEST(PsdWindowTest, RoundTripsThroughStrings) {
  for (const PsdWindow w : {PsdWindow::kRectangular, PsdWindow::kHann}) {
    const std::optional<PsdWindow> back = PsdWindowFromString(ToString(w));
    ASSERT_TRUE(back.has_value()) << ToString(w);
    EXPECT_EQ(*back, w);
  }
  EXPECT_EQ(ToString(PsdWindow::kRectangular), "rectangular");
  EXPECT_EQ(ToString(PsdWindow::kHann), "hann");
}

TEST(PsdWindowTest, UnknownNameIsRejected) {
  EXPECT_FALSE(PsdWindowFromString("hanning").has_value());
  EXPECT_FALSE(PsdWindowFromString("Hann").has_value());
  EXPECT_FALSE(PsdWindowFromString("").has_value());
}

TEST(PsdOptionsTest, DefaultsAreValidAndAsDocumented) {
  const PsdOptions options;
  std::string error;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  EXPECT_EQ(options.n_samples, 4096);
  EXPECT_EQ(options.window, PsdWindow::kHann);
  EXPECT_EQ(options.zero_padding_factor, 4);
  EXPECT_EQ(options.FftLength(), 16384);
}

TEST(PsdOptionsTest, BadOptionsAreRejectedNamingTheField) {
  std::string error;
  PsdOptions options;
  options.n_samples = 1;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("n_samples"), std::string::npos) << error;

  options = PsdOptions{};
  options.zero_padding_factor = 0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("zero_padding_factor"), std::string::npos) << error;

  options = PsdOptions{};
  options.window = static_cast<PsdWindow>(7);
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("window"), std::string::npos) << error;

  options = PsdOptions{};
  options.n_samples = kMaxPsdSamples + 1;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("n_samples = 4194305: must be a whole number from 16 to 4194304"),
            std::string::npos)
      << error;

  options = PsdOptions{};
  options.zero_padding_factor = kMaxZeroPaddingFactor + 1;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("zero_padding_factor = 65: must be a whole number from 1 to 64"),
            std::string::npos)
      << error;

  EXPECT_FALSE(options.IsValid(nullptr));  // A null error sink is allowed.
}

// ---------------------------------------------------------------------------------------------
// OneSidedPsd

TEST(OneSidedPsdTest, FftLengthIsNextPowerOfTwoOfThePaddedLength) {
  const UniformSignal s = GenericDisplacement();
  PsdOptions options;
  options.n_samples = 1000;
  options.zero_padding_factor = 3;  // 3000 -> 4096.
  const double t0 = 0.05;
  const double t1 = 0.45;
  const PowerSpectrum psd = OneSidedPsd(s, t0, t1, options);
  EXPECT_EQ(options.FftLength(), 4096);
  EXPECT_EQ(psd.density.size(), 4096u / 2 + 1);
  const double fs = 1000.0 / (t1 - t0);
  EXPECT_NEAR(psd.df_hz, fs / 4096.0, 1e-12 * fs);
  EXPECT_NEAR(psd.FrequencyAt(psd.density.size() - 1), fs / 2.0, 1e-9 * fs);
}

// A sin(2 pi f t) with 10 whole periods over the window, sampled on the PSD's own grid, so the
// resampling is exact. Rectangular window: all the power sits in the bin at f (the zero-padded
// DFT equals the unpadded one at every 4th bin, where the other bins of a whole-period sinusoid
// vanish), with the analytic height G(f) = A^2 T / 2.
TEST(OneSidedPsdTest, RectangularSinusoidPeaksAtItsFrequencyWithAnalyticHeight) {
  const double amplitude = 0.7;
  const double f_hz = 50.0;
  const double t_begin = 0.1;
  const double t_end = 0.3;  // 10 periods.
  PsdOptions options;
  options.window = PsdWindow::kRectangular;
  const double step = (t_end - t_begin) / options.n_samples;
  const UniformSignal s = Sample(t_begin, step, options.n_samples + 1, [&](double t) {
    return amplitude * std::sin(2.0 * kPi * f_hz * t);
  });

  const PowerSpectrum psd = OneSidedPsd(s, t_begin, t_end, options);
  const std::size_t peak = ArgMax(psd.density);
  EXPECT_NEAR(psd.FrequencyAt(peak), f_hz, 1e-9 * f_hz);
  EXPECT_NEAR(psd.density[peak], amplitude * amplitude * (t_end - t_begin) / 2.0,
              1e-9 * amplitude * amplitude);
  // Orthogonality at the unpadded bins: nothing at f +- 1/T.
  const std::size_t bins_per_harmonic = options.FftLength() / options.n_samples;
  EXPECT_LT(psd.density[peak + bins_per_harmonic], 1e-20 * psd.density[peak]);
  EXPECT_LT(psd.density[peak - bins_per_harmonic], 1e-20 * psd.density[peak]);
}

TEST(OneSidedPsdTest, RectangularWindowSatisfiesParseval) {
  const double amplitude = 0.7;
  const double f_hz = 50.0;
  const double t_begin = 0.1;
  const double t_end = 0.3;
  PsdOptions options;
  options.window = PsdWindow::kRectangular;
  const double step = (t_end - t_begin) / options.n_samples;
  const UniformSignal sine = Sample(t_begin, step, options.n_samples + 1, [&](double t) {
    return amplitude * std::sin(2.0 * kPi * f_hz * t);
  });
  const std::vector<double> x = ResampleForPsd(sine, t_begin, t_end, options.n_samples);
  EXPECT_NEAR(MeanSquare(x), amplitude * amplitude / 2.0, 1e-12);
  EXPECT_NEAR(Integral(OneSidedPsd(sine, t_begin, t_end, options)), MeanSquare(x),
              1e-10 * MeanSquare(x));

  // Any signal, any grid: the identity concerns the resampled samples, mean included.
  const UniformSignal generic = GenericDisplacement();
  for (const int padding : {1, 3, 4}) {
    options.zero_padding_factor = padding;
    const std::vector<double> y = ResampleForPsd(generic, 0.02, 0.37, options.n_samples);
    EXPECT_NEAR(Integral(OneSidedPsd(generic, 0.02, 0.37, options)), MeanSquare(y),
                1e-10 * MeanSquare(y))
        << "zero_padding_factor = " << padding;
  }
}

// Hann: sum G df = sum (w x)^2 / sum w^2, a window-weighted mean square; for a sinusoid with a
// non-integer number of periods it is within about a percent of the plain mean square.
TEST(OneSidedPsdTest, HannWindowApproximatelySatisfiesParseval) {
  const double amplitude = 1.3;
  const double t_begin = 0.0;
  const double t_end = 0.25;
  const double f_hz = 10.37 / (t_end - t_begin);  // 10.37 periods.
  const UniformSignal s = Sample(
      0.0, 1e-5, 30000, [&](double t) { return amplitude * std::sin(2.0 * kPi * f_hz * t + 0.4); });
  const PsdOptions options;  // Hann.
  const std::vector<double> x = ResampleForPsd(s, t_begin, t_end, options.n_samples);
  const PowerSpectrum psd = OneSidedPsd(s, t_begin, t_end, options);
  EXPECT_NEAR(Integral(psd), MeanSquare(x), 0.03 * MeanSquare(x));
  EXPECT_NEAR(psd.FrequencyAt(ArgMax(psd.density)), f_hz, psd.df_hz);
}

// The mean is kept: a constant c over a window of length T has G(0) = c^2 (sum w)^2 / (fs sum w^2),
// i.e. c^2 T for the rectangular window and (2/3) c^2 T for Hann (sum w = n/2, sum w^2 = 3n/8),
// and sum G df = c^2 with either.
TEST(OneSidedPsdTest, MeanIsNotRemoved) {
  const double c = 3e-3;
  const double t_window = 0.5;
  const UniformSignal s = Sample(0.0, 1e-3, 1001, [&](double) { return c; });
  for (const auto& [window, dc_fraction] :
       {std::pair{PsdWindow::kRectangular, 1.0}, std::pair{PsdWindow::kHann, 2.0 / 3.0}}) {
    PsdOptions options;
    options.window = window;
    const PowerSpectrum psd = OneSidedPsd(s, 0.2, 0.2 + t_window, options);
    EXPECT_NEAR(psd.density[0], dc_fraction * c * c * t_window, 1e-10 * c * c) << ToString(window);
    EXPECT_NEAR(Integral(psd), c * c, 1e-10 * c * c) << ToString(window);
  }
}

TEST(OneSidedPsdTest, RejectsBadWindowsAndSignals) {
  const UniformSignal s = GenericDisplacement();  // [0, 0.519987] s.
  const PsdOptions options;
  EXPECT_THROW(OneSidedPsd(s, 0.3, 0.3, options), std::invalid_argument);
  EXPECT_THROW(OneSidedPsd(s, 0.3, 0.1, options), std::invalid_argument);
  EXPECT_THROW(OneSidedPsd(s, -0.1, 0.3, options), std::invalid_argument);
  EXPECT_THROW(OneSidedPsd(s, 0.1, 0.6, options), std::invalid_argument);
  EXPECT_THROW(OneSidedPsd(s, 0.1, std::numeric_limits<double>::infinity(), options),
               std::invalid_argument);
  EXPECT_NO_THROW(OneSidedPsd(s, s.t0_s, s.EndTime(), options));

  PsdOptions bad;
  bad.n_samples = 0;
  EXPECT_THROW(OneSidedPsd(s, 0.1, 0.3, bad), std::invalid_argument);

  UniformSignal diverged = s;
  diverged.values[20000] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(OneSidedPsd(diverged, 0.1, 0.4, options), std::invalid_argument);

  const UniformSignal one_sample{.t0_s = 0.0, .dt_s = 1e-3, .values = {1.0}};
  EXPECT_THROW(OneSidedPsd(one_sample, 0.0, 1e-3, options), std::invalid_argument);
}

// Workers will score runs in parallel: concurrent calls (planning under the library's mutex,
// transforms unlocked) give bit-identical spectra to a serial call.
TEST(OneSidedPsdTest, ConcurrentCallsMatchSerialResult) {
  const UniformSignal s = GenericDisplacement();
  const PsdOptions options;
  const std::vector<double> serial = OneSidedPsd(s, 0.01, 0.5, options).density;
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> workers;
  for (std::size_t w = 0; w < mismatches.size(); ++w) {
    workers.emplace_back([&, w] {
      for (int repeat = 0; repeat < 10; ++repeat) {
        mismatches[w] += OneSidedPsd(s, 0.01, 0.5, options).density != serial ? 1 : 0;
      }
    });
  }
  for (std::thread& worker : workers) {
    worker.join();
  }
  EXPECT_EQ(std::count(mismatches.begin(), mismatches.end(), 0), 4);
}

// ---------------------------------------------------------------------------------------------
// SpectralError, paper eq. (8)

// A reference scored against many runs passes its spectrum once: the same Err bit for bit as
// passing its signal, with either window.
TEST(SpectralErrorTest, AgainstAStoredSpectrumEqualsAgainstTheSignal) {
  const UniformSignal s = GenericDisplacement();
  UniformSignal other = s;
  for (std::size_t i = 0; i < other.values.size(); ++i) other.values[i] *= 1.0 + 1e-3 * (i % 7);
  for (const PsdWindow window : {PsdWindow::kRectangular, PsdWindow::kHann}) {
    PsdOptions options;
    options.window = window;
    const PowerSpectrum stored = OneSidedPsd(s, 0.01, 0.5, options);
    const double err = SpectralError(other, s, 0.01, 0.5, options);
    EXPECT_GT(err, 0.0);
    EXPECT_EQ(SpectralError(other, stored, 0.01, 0.5, options), err) << ToString(window);
  }
}

TEST(SpectralErrorTest, SignalAgainstItselfIsExactlyZero) {
  const UniformSignal s = GenericDisplacement();
  for (const PsdWindow window : {PsdWindow::kRectangular, PsdWindow::kHann}) {
    PsdOptions options;
    options.window = window;
    EXPECT_EQ(SpectralError(s, s, 0.01, 0.5, options), 0.0) << ToString(window);
  }
}

// Scaling a signal by c scales its PSD by c^2, so eq. (8) gives |c^2 - 1| / max(c^2, 1).
class SpectralErrorOfScaledCopyTest : public testing::TestWithParam<double> {};

TEST_P(SpectralErrorOfScaledCopyTest, MatchesAnalyticValue) {
  const double c = GetParam();
  const UniformSignal s = GenericDisplacement();
  UniformSignal scaled = s;
  for (double& v : scaled.values) {
    v *= c;
  }
  const double expected = std::abs(c * c - 1.0) / std::max(c * c, 1.0);
  const PsdOptions options;
  EXPECT_NEAR(SpectralError(scaled, s, 0.01, 0.5, options), expected, 1e-12);
  EXPECT_NEAR(SpectralError(s, scaled, 0.01, 0.5, options), expected, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(ScaleFactors, SpectralErrorOfScaledCopyTest,
                         testing::Values(2.0, 0.5, 1.1),
                         [](const testing::TestParamInfo<double>& info) {
                           std::ostringstream name;
                           name << "c_" << info.param;  // 2 -> c_2, 0.5 -> c_0p5.
                           std::string s = name.str();
                           std::replace(s.begin(), s.end(), '.', 'p');
                           return s;
                         });

TEST(SpectralErrorTest, BothSilentIsZero) {
  const UniformSignal zero = Sample(0.0, 1e-4, 5000, [](double) { return 0.0; });
  EXPECT_EQ(SpectralError(zero, zero, 0.0, 0.4, PsdOptions{}), 0.0);
}

TEST(SpectralErrorTest, AgainstSilenceIsOne) {
  const UniformSignal s = GenericDisplacement();
  const UniformSignal zero = Sample(0.0, 1e-4, 5000, [](double) { return 0.0; });
  EXPECT_EQ(SpectralError(s, zero, 0.0, 0.4, PsdOptions{}), 1.0);
  EXPECT_EQ(SpectralError(zero, s, 0.0, 0.4, PsdOptions{}), 1.0);
}

// Two whole-period sinusoids of equal amplitude at different frequencies, rectangular window:
// each spectrum is zero at the other's peak, so Err = 1 although both have the same power.
TEST(SpectralErrorTest, DisjointSpectraGiveOne) {
  PsdOptions options;
  options.window = PsdWindow::kRectangular;
  const double t_end = 0.2;
  const double step = t_end / options.n_samples;
  const UniformSignal a = Sample(0.0, step, options.n_samples + 1,
                                 [](double t) { return std::sin(2.0 * kPi * 50.0 * t); });
  const UniformSignal b = Sample(0.0, step, options.n_samples + 1,
                                 [](double t) { return std::sin(2.0 * kPi * 150.0 * t); });
  EXPECT_NEAR(SpectralError(a, b, 0.0, t_end, options), 1.0, 1e-12);
}

TEST(PsdTest, TwoSidedScalingHalvesEveryBinButDcAndNyquist) {
  PsdOptions one;
  one.n_samples = 256;
  PsdOptions two = one;
  two.one_sided = false;
  const UniformSignal s = Sample(0.0, 1e-3, 1001, [](double t) {
    return 0.3 + std::sin(2.0 * kPi * 40.0 * t) + 0.1 * std::sin(2.0 * kPi * 130.0 * t);
  });
  const PowerSpectrum a = OneSidedPsd(s, 0.0, 1.0, one);
  const PowerSpectrum b = OneSidedPsd(s, 0.0, 1.0, two);
  ASSERT_EQ(a.density.size(), b.density.size());
  EXPECT_EQ(b.density.front(), a.density.front());
  EXPECT_EQ(b.density.back(), a.density.back());
  for (std::size_t k = 1; k + 1 < a.density.size(); ++k) {
    EXPECT_DOUBLE_EQ(b.density[k], 0.5 * a.density[k]) << k;
  }
}

// ---------------------------------------------------------------------------------------------
// ImpulseRatio, paper eq. (9)

TEST(ImpulseRatioTest, IsMinOverMaxAndSymmetric) {
  EXPECT_EQ(ImpulseRatio(2.0, 8.0), 0.25);
  EXPECT_EQ(ImpulseRatio(8.0, 2.0), 0.25);
  EXPECT_EQ(ImpulseRatio(3.5, 3.5), 1.0);
  EXPECT_EQ(ImpulseRatio(0.0, 3.5), 0.0);
  EXPECT_EQ(ImpulseRatio(0.0, 0.0), 1.0);
}

TEST(ImpulseRatioTest, RejectsNegativeOrNonFiniteImpulse) {
  EXPECT_THROW(ImpulseRatio(-1.0, 2.0), std::invalid_argument);
  EXPECT_THROW(ImpulseRatio(1.0, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(ImpulseRatio(std::numeric_limits<double>::infinity(), 1.0), std::invalid_argument);
}

// The SRf definitions on a hand-made pair (dt = 1 ms, exact zeros between contacts, rest
// duration 5 ms so that each pair of contacts 1-3 ms apart is one shock):
// reference: contact 1 at samples 10-12 = (1, 3, 1), impulse 5e-3 N s; rebound at 15 = 2,
//   impulse 2e-3; first shock 7e-3 over [9 ms, 16 ms]; a second shock at 50 ms.
// numerical: contact 1 at 11-12 = (3, 3), impulse 6e-3; rebounds at 15 = 1 (1e-3) and at
//   18 = 2 (2e-3); first shock 9e-3, of which 7e-3 lie in [9 ms, 16 ms].
UniformSignal ForceFromSamples(const std::map<int, double>& samples) {
  UniformSignal s;
  s.t0_s = 0.0;
  s.dt_s = 1e-3;
  s.values.assign(60, 0.0);
  for (const auto& [i, f] : samples) s.values[static_cast<std::size_t>(i)] = f;
  return s;
}

struct SrfPair {
  UniformSignal numerical = ForceFromSamples({{11, 3.0}, {12, 3.0}, {15, 1.0}, {18, 2.0}});
  UniformSignal reference =
      ForceFromSamples({{10, 1.0}, {11, 3.0}, {12, 1.0}, {15, 2.0}, {50, 10.0}});
  ShockSegmentationOptions options{0.0, 5e-3};
  double t_end_s = 0.059;

  double Srf(SrfDefinition d) const {
    return DefinedImpulseRatio(d, numerical, SegmentShocks(numerical, options, t_end_s), reference,
                               SegmentShocks(reference, options, t_end_s), options, t_end_s)
        .value();
  }
};

TEST(SrfDefinitionTest, FirstShockComparesGroupedContacts) {
  const SrfPair pair;
  EXPECT_NEAR(pair.Srf(SrfDefinition::kFirstShock), 7.0 / 9.0, 1e-12);
}

TEST(SrfDefinitionTest, FirstContactStopsAtTheFirstSeparation) {
  const SrfPair pair;
  EXPECT_NEAR(pair.Srf(SrfDefinition::kFirstContact), 5.0 / 6.0, 1e-12);
}

TEST(SrfDefinitionTest, FirstContactSeparatesContactsOneZeroSampleApart) {
  SrfPair pair;
  pair.numerical = ForceFromSamples({{11, 3.0}, {12, 3.0}, {14, 1.0}});  // Zero at 13 only.
  EXPECT_NEAR(pair.Srf(SrfDefinition::kFirstContact), 5.0 / 6.0, 1e-12);
}

TEST(SrfDefinitionTest, ReferenceWindowIntegratesBothOverTheReferenceShock) {
  const SrfPair pair;
  EXPECT_NEAR(pair.Srf(SrfDefinition::kReferenceWindow), 1.0, 1e-12);
  SrfPair later = pair;  // The numerical rebound at 15 ms moved out of the window: 6 / 7.
  later.numerical = ForceFromSamples({{11, 3.0}, {12, 3.0}, {17, 1.0}});
  EXPECT_NEAR(later.Srf(SrfDefinition::kReferenceWindow), 6.0 / 7.0, 1e-12);
}

TEST(SrfDefinitionTest, NoContactOnOneSideScoresZeroAndOnNeitherNothing) {
  SrfPair pair;
  pair.numerical = ForceFromSamples({});
  for (const auto d : {SrfDefinition::kFirstShock, SrfDefinition::kFirstContact,
                       SrfDefinition::kReferenceWindow}) {
    EXPECT_EQ(pair.Srf(d), 0.0) << ToString(d);
  }
  pair.reference = ForceFromSamples({});
  for (const auto d : {SrfDefinition::kFirstShock, SrfDefinition::kFirstContact,
                       SrfDefinition::kReferenceWindow}) {
    EXPECT_FALSE(
        DefinedImpulseRatio(d, pair.numerical, {}, pair.reference, {}, pair.options, pair.t_end_s)
            .has_value())
        << ToString(d);
  }
}

TEST(SrfDefinitionTest, NamesRoundTrip) {
  for (const auto d : {SrfDefinition::kFirstShock, SrfDefinition::kFirstContact,
                       SrfDefinition::kReferenceWindow}) {
    EXPECT_EQ(SrfDefinitionFromString(ToString(d)), d);
  }
  EXPECT_FALSE(SrfDefinitionFromString("First_Shock").has_value());
}

TEST(ImpulseOverTest, IntegratesThePiecewiseLinearForceOverAnyInterval) {
  UniformSignal ramp;
  ramp.dt_s = 0.5;
  ramp.values = {0.0, 1.0, 2.0, 3.0, 4.0};  // f(t) = 2 t on [0, 2].
  EXPECT_NEAR(ImpulseOver(ramp, 0.3, 1.7), 1.7 * 1.7 - 0.3 * 0.3, 1e-12);
  EXPECT_NEAR(ImpulseOver(ramp, 0.1, 0.2), 0.04 - 0.01, 1e-12);  // Inside one segment.
  EXPECT_NEAR(ImpulseOver(ramp, -1.0, 5.0), 4.0, 1e-12);         // Clipped to the record.
  EXPECT_EQ(ImpulseOver(ramp, 3.0, 4.0), 0.0);
  EXPECT_THROW(ImpulseOver(ramp, 1.0, 0.5), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Shock segmentation

struct HalfSine {
  double start_s;
  double duration_s;
  double peak_n;
  double End() const { return start_s + duration_s; }
  double Impulse() const { return 2.0 * peak_n * duration_s / kPi; }
};

// Sum of half-sine pulses, exactly zero outside them, sampled at dt.
UniformSignal HalfSineForce(const std::vector<HalfSine>& pulses, double dt_s, double t_end_s) {
  return Sample(0.0, dt_s, static_cast<std::size_t>(std::llround(t_end_s / dt_s)) + 1,
                [&](double t) {
                  double f = 0.0;
                  for (const HalfSine& p : pulses) {
                    if (t > p.start_s && t < p.End()) {
                      f += p.peak_n * std::sin(kPi * (t - p.start_s) / p.duration_s);
                    }
                  }
                  return f;
                });
}

// Trapezoidal-rule error bound for one sampled half-sine (peak F, duration T, step h): the
// interior intervals contribute at most T h^2 max|F''| / 12 = F pi^2 h^2 / (12 T); each of the
// two intervals holding an end of the pulse, where the slope jumps from 0 to F pi / T, at most
// (F pi / T) h^2 / 8. Padded by 10% for the higher-order terms. (A bound: over 800 pulse phases
// and durations the observed error stays below 30% of it.)
double ImpulseTolerance(const HalfSine& p, double h) {
  return 1.1 * p.peak_n * h * h / p.duration_s * (kPi * kPi / 12.0 + kPi / 4.0);
}

ShockSegmentationOptions OptionsWithRest(double rest_duration_s) {
  ShockSegmentationOptions options;
  options.rest_duration_s = rest_duration_s;
  return options;
}

TEST(ShockSegmentationOptionsTest, RestDurationIsRequired) {
  std::string error;
  EXPECT_FALSE(ShockSegmentationOptions{}.IsValid(&error));
  EXPECT_NE(error.find("rest_duration_s"), std::string::npos) << error;
  EXPECT_TRUE(OptionsWithRest(2e-3).IsValid(&error)) << error;
}

TEST(ShockSegmentationOptionsTest, BadOptionsAreRejectedNamingTheField) {
  for (const double rest : {-1e-3, 0.0, std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::infinity()}) {
    std::string error;
    EXPECT_FALSE(OptionsWithRest(rest).IsValid(&error)) << rest;
    EXPECT_NE(error.find("rest_duration_s"), std::string::npos) << error;
  }
  for (const double threshold : {-1.0, std::numeric_limits<double>::quiet_NaN()}) {
    ShockSegmentationOptions options = OptionsWithRest(2e-3);
    options.force_threshold_n = threshold;
    std::string error;
    EXPECT_FALSE(options.IsValid(&error)) << threshold;
    EXPECT_NE(error.find("force_threshold_n"), std::string::npos) << error;
  }
}

// Six half-sine contacts with rest duration 2 ms. Gaps of 1.9 ms and 0.5 ms join contacts into
// one shock; 2.1 ms and 5 ms separate shocks. The measured gaps are off by at most 2 dt = 20 us,
// far below the 100 us margins. Expected: 3 shocks of 3, 1 and 2 contacts.
TEST(SegmentShocksTest, HalfSineContactsAreGroupedByRestDuration) {
  const double dt = 1e-5;
  const double rest = 2e-3;
  const HalfSine c1{0.0101234, 1.0e-3, 800.0};
  const HalfSine c2{c1.End() + 1.9e-3, 0.6e-3, 300.0};
  const HalfSine c3{c2.End() + 0.5e-3, 0.4e-3, 1000.0};  // The peak of shock 1 is a rebound.
  const HalfSine c4{c3.End() + 2.1e-3, 0.9e-3, 650.0};
  const HalfSine c5{c4.End() + 5.0e-3, 0.7e-3, 400.0};
  const HalfSine c6{c5.End() + 0.3e-3, 0.5e-3, 200.0};
  const std::vector<std::vector<HalfSine>> groups = {{c1, c2, c3}, {c4}, {c5, c6}};
  const UniformSignal force = HalfSineForce({c1, c2, c3, c4, c5, c6}, dt, 0.05);

  const std::vector<Shock> shocks = SegmentShocks(force, OptionsWithRest(rest), 0.05);
  ASSERT_EQ(shocks.size(), groups.size());
  for (std::size_t s = 0; s < groups.size(); ++s) {
    SCOPED_TRACE("shock " + std::to_string(s));
    const std::vector<HalfSine>& g = groups[s];
    const Shock& shock = shocks[s];
    EXPECT_EQ(shock.n_contacts, static_cast<int>(g.size()));
    EXPECT_EQ(shock.Rebounds(), static_cast<int>(g.size()) - 1);
    EXPECT_FALSE(shock.truncated);

    // Threshold 0: the interpolated crossing is the last zero sample before the pulse and the
    // first after it, so start is in (t_s - dt, t_s] and end in [t_e, t_e + dt).
    EXPECT_LE(shock.start_s, g.front().start_s);
    EXPECT_GT(shock.start_s, g.front().start_s - dt);
    EXPECT_GE(shock.end_s, g.back().End());
    EXPECT_LT(shock.end_s, g.back().End() + dt);
    EXPECT_NEAR(shock.Duration(), g.back().End() - g.front().start_s, 2 * dt);

    // The sampled peak is the sample nearest the crest, within dt / 2 of it.
    const HalfSine& crest =
        *std::max_element(g.begin(), g.end(),
                          [](const HalfSine& a, const HalfSine& b) { return a.peak_n < b.peak_n; });
    EXPECT_LE(shock.peak_force_n, crest.peak_n);
    EXPECT_GE(shock.peak_force_n, crest.peak_n * std::cos(kPi * 0.5 * dt / crest.duration_s));
    EXPECT_NEAR(shock.peak_time_s, crest.start_s + crest.duration_s / 2.0, 0.5 * dt + 1e-12);

    double impulse = 0.0;
    double tolerance = 0.0;
    for (const HalfSine& p : g) {
      impulse += p.Impulse();
      tolerance += ImpulseTolerance(p, dt);
    }
    EXPECT_NEAR(shock.impulse_n_s, impulse, tolerance);
  }
}

// The grouping is decided by the rest duration alone: at 1.8 ms the 1.9 ms gap splits shock 1.
TEST(SegmentShocksTest, ShorterRestDurationSplitsRebounds) {
  const double dt = 1e-5;
  const HalfSine c1{0.0101234, 1.0e-3, 800.0};
  const HalfSine c2{c1.End() + 1.9e-3, 0.6e-3, 300.0};
  const UniformSignal force = HalfSineForce({c1, c2}, dt, 0.02);
  EXPECT_EQ(SegmentShocks(force, OptionsWithRest(2.0e-3), 0.02).size(), 1u);
  const std::vector<Shock> split = SegmentShocks(force, OptionsWithRest(1.8e-3), 0.02);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_NEAR(split[0].impulse_n_s, c1.Impulse(), ImpulseTolerance(c1, dt));
  EXPECT_NEAR(split[1].impulse_n_s, c2.Impulse(), ImpulseTolerance(c2, dt));
}

TEST(SegmentShocksTest, OneSampleContactHasImpulseForceTimesDt) {
  const double dt = 1e-3;
  UniformSignal force{.t0_s = 0.5, .dt_s = dt, .values = std::vector<double>(201, 0.0)};
  force.values[100] = 5.0;
  const std::vector<Shock> shocks = SegmentShocks(force, OptionsWithRest(1e-2), 1.0);
  ASSERT_EQ(shocks.size(), 1u);
  EXPECT_EQ(shocks[0].n_contacts, 1);
  EXPECT_EQ(shocks[0].Rebounds(), 0);
  EXPECT_DOUBLE_EQ(shocks[0].impulse_n_s, 5.0 * dt);
  EXPECT_EQ(shocks[0].peak_force_n, 5.0);
  EXPECT_DOUBLE_EQ(shocks[0].peak_time_s, force.TimeAt(100));
  EXPECT_DOUBLE_EQ(shocks[0].start_s, force.TimeAt(99));
  EXPECT_DOUBLE_EQ(shocks[0].end_s, force.TimeAt(101));
  EXPECT_NEAR(shocks[0].Duration(), 2.0 * dt, 1e-12);
  EXPECT_FALSE(shocks[0].truncated);
}

TEST(SegmentShocksTest, NoContactGivesNoShock) {
  const UniformSignal zero{.t0_s = 0.0, .dt_s = 1e-4, .values = std::vector<double>(1000, 0.0)};
  EXPECT_TRUE(SegmentShocks(zero, OptionsWithRest(1e-3), 1.0).empty());
  const UniformSignal empty{.t0_s = 0.0, .dt_s = 1e-4, .values = {}};
  EXPECT_TRUE(SegmentShocks(empty, OptionsWithRest(1e-3), 1.0).empty());
  // Force at or below a positive threshold is no contact either.
  UniformSignal small = zero;
  small.values[500] = 2.0;
  ShockSegmentationOptions options = OptionsWithRest(1e-3);
  options.force_threshold_n = 2.0;
  EXPECT_TRUE(SegmentShocks(small, options, 1.0).empty());
}

// With a positive threshold the contact limits are the interpolated crossings: for a force
// ramping linearly at 1000 N/s they are exact.
TEST(SegmentShocksTest, ThresholdCrossingsAreInterpolated) {
  const double dt = 1e-3;
  // Triangle 0 -> 1 N over [0.1, 0.2] s and back to 0 at 0.3 s; threshold 0.255 N is crossed
  // at 0.1255 s and 0.2745 s, between samples.
  const UniformSignal force =
      Sample(0.0, dt, 401, [](double t) { return std::max(0.0, 1.0 - std::abs(t - 0.2) / 0.1); });
  ShockSegmentationOptions options = OptionsWithRest(1e-2);
  options.force_threshold_n = 0.255;
  const std::vector<Shock> shocks = SegmentShocks(force, options, 0.4);
  ASSERT_EQ(shocks.size(), 1u);
  EXPECT_NEAR(shocks[0].start_s, 0.1255, 1e-12);
  EXPECT_NEAR(shocks[0].end_s, 0.2745, 1e-12);
  EXPECT_NEAR(shocks[0].peak_force_n, 1.0, 1e-12);
  EXPECT_NEAR(shocks[0].peak_time_s, 0.2, 1e-12);
  // The impulse runs from the sample before the first contact sample to the one after the last,
  // [0.125, 0.275] s, where the force is 0.25 N: the triangle's area 0.1 N s minus two corners.
  const double corners = 2.0 * 0.5 * 0.025 * 0.25;
  EXPECT_NEAR(shocks[0].impulse_n_s, 0.1 - corners, 1e-12);
}

TEST(SegmentShocksTest, IgnoresSamplesAfterEndTimeAndFlagsCutShocks) {
  const double dt = 1e-5;
  const HalfSine c1{0.0101234, 1.0e-3, 800.0};
  const HalfSine c2{0.0301234, 1.0e-3, 800.0};
  const UniformSignal force = HalfSineForce({c1, c2}, dt, 0.05);
  const ShockSegmentationOptions options = OptionsWithRest(2e-3);

  const std::vector<Shock> before_second = SegmentShocks(force, options, 0.02);
  ASSERT_EQ(before_second.size(), 1u);
  EXPECT_FALSE(before_second[0].truncated);

  const std::vector<Shock> cut = SegmentShocks(force, options, c2.start_s + 0.4e-3);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_TRUE(cut[1].truncated);
  EXPECT_LT(cut[1].impulse_n_s, c2.Impulse());
  EXPECT_LE(cut[1].end_s, c2.start_s + 0.4e-3);

  EXPECT_EQ(SegmentShocks(force, options, std::numeric_limits<double>::infinity()).size(), 2u);
  EXPECT_TRUE(SegmentShocks(force, options, -1.0).empty());

  // A contact under way at the first sample.
  UniformSignal late = force;
  late.t0_s = 0.0;
  late.values.erase(late.values.begin(), late.values.begin() + 1050);  // Starts mid-pulse c1.
  const std::vector<Shock> first_cut = SegmentShocks(late, options, 1.0);
  ASSERT_EQ(first_cut.size(), 2u);
  EXPECT_TRUE(first_cut[0].truncated);
  EXPECT_EQ(first_cut[0].start_s, 0.0);
  EXPECT_FALSE(first_cut[1].truncated);
}

TEST(SegmentShocksTest, RejectsBadInput) {
  UniformSignal force{.t0_s = 0.0, .dt_s = 1e-3, .values = std::vector<double>(10, 0.0)};
  EXPECT_THROW(SegmentShocks(force, ShockSegmentationOptions{}, 1.0), std::invalid_argument);
  EXPECT_THROW(
      SegmentShocks(force, OptionsWithRest(1e-2), std::numeric_limits<double>::quiet_NaN()),
      std::invalid_argument);
  force.values[3] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(SegmentShocks(force, OptionsWithRest(1e-2), 1.0), std::invalid_argument);
  // A non-finite force after t_end_s is not considered.
  EXPECT_NO_THROW(SegmentShocks(force, OptionsWithRest(1e-2), 2e-3));
  force.values[3] = 0.0;
  force.dt_s = 0.0;
  EXPECT_THROW(SegmentShocks(force, OptionsWithRest(1e-2), 1.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// FirstShockImpulseRatio (SRf of the first shock, paper eq. 9)

TEST(FirstShockImpulseRatioTest, NeitherHasAShockIsNullopt) {
  EXPECT_FALSE(FirstShockImpulseRatio({}, {}).has_value());
}

TEST(FirstShockImpulseRatioTest, ExactlyOneHasAShockIsZero) {
  const std::vector<Shock> one = {Shock{.impulse_n_s = 0.3, .n_contacts = 1}};
  EXPECT_EQ(FirstShockImpulseRatio(one, {}), std::optional<double>(0.0));
  EXPECT_EQ(FirstShockImpulseRatio({}, one), std::optional<double>(0.0));
}

TEST(FirstShockImpulseRatioTest, UsesOnlyTheFirstShock) {
  const std::vector<Shock> a = {Shock{.impulse_n_s = 0.2, .n_contacts = 1},
                                Shock{.impulse_n_s = 9.0, .n_contacts = 1}};
  const std::vector<Shock> b = {Shock{.impulse_n_s = 0.8, .n_contacts = 2}};
  EXPECT_EQ(FirstShockImpulseRatio(a, b), std::optional<double>(0.25));
}

TEST(FirstShockImpulseRatioTest, IdenticalForcesGiveOne) {
  const HalfSine c1{0.0101234, 1.0e-3, 800.0};
  const HalfSine c2{c1.End() + 0.5e-3, 0.6e-3, 300.0};
  const UniformSignal force = HalfSineForce({c1, c2}, 1e-5, 0.03);
  const std::vector<Shock> shocks = SegmentShocks(force, OptionsWithRest(2e-3), 0.03);
  ASSERT_EQ(shocks.size(), 1u);
  EXPECT_EQ(FirstShockImpulseRatio(shocks, shocks), std::optional<double>(1.0));
}

// Threshold 0 makes segmentation scale-invariant, so a force scaled by 0.25 has the same shocks
// with a quarter of the impulse: SRf = 0.25.
TEST(FirstShockImpulseRatioTest, ForceScaledByAQuarterGivesAQuarter) {
  const HalfSine c1{0.0101234, 1.0e-3, 800.0};
  const HalfSine c2{c1.End() + 0.5e-3, 0.6e-3, 300.0};
  const UniformSignal force = HalfSineForce({c1, c2}, 1e-5, 0.03);
  UniformSignal quarter = force;
  for (double& v : quarter.values) {
    v *= 0.25;
  }
  const ShockSegmentationOptions options = OptionsWithRest(2e-3);
  const std::optional<double> ratio = FirstShockImpulseRatio(SegmentShocks(quarter, options, 0.03),
                                                             SegmentShocks(force, options, 0.03));
  ASSERT_TRUE(ratio.has_value());
  EXPECT_NEAR(*ratio, 0.25, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// The registry of scores (validation/scores.h)

// Two runs of one problem: displacements and contact forces differing in amplitude and timing.
struct TwoRuns {
  UniformSignal displacement = GenericDisplacement();
  UniformSignal reference_displacement = Sample(0.0, 1.1e-5, 45000, [](double t) {
    return 2e-3 + 0.9e-3 * std::exp(-3.0 * t) * std::cos(2.0 * kPi * 19.5 * t);
  });
  UniformSignal force =
      HalfSineForce({{0.0101234, 1.0e-3, 800.0}, {0.013, 0.6e-3, 300.0}}, 1e-5, 0.03);
  UniformSignal reference_force = HalfSineForce({{0.0102, 1.2e-3, 600.0}}, 1e-5, 0.03);
  ShockSegmentationOptions segmentation = OptionsWithRest(2e-3);
  std::vector<Shock> shocks = SegmentShocks(force, segmentation, 0.03);
  std::vector<Shock> reference_shocks = SegmentShocks(reference_force, segmentation, 0.03);

  ScoringInput Input(SrfDefinition definition) const {
    return {.displacement = displacement,
            .reference_displacement = reference_displacement,
            .psd = PsdOptions{},
            .end_s = 0.3,
            .force = force,
            .shocks = shocks,
            .reference_force = reference_force,
            .reference_shocks = reference_shocks,
            .srf_definition = definition,
            .segmentation = segmentation};
  }
};

TEST(ScoreRegistryTest, ErrAndSrfAreEquations8And9UnderEachReading) {
  const TwoRuns runs;
  for (const SrfDefinition d : {SrfDefinition::kFirstShock, SrfDefinition::kFirstContact,
                                SrfDefinition::kReferenceWindow}) {
    const ScoreValues scores = ComputeScores(runs.Input(d));
    EXPECT_EQ(scores["err"], SpectralError(runs.displacement, runs.reference_displacement, 0.0, 0.3,
                                           PsdOptions{}));
    EXPECT_EQ(scores["srf"], DefinedImpulseRatio(d, runs.force, runs.shocks, runs.reference_force,
                                                 runs.reference_shocks, runs.segmentation, 0.3))
        << ToString(d);
    EXPECT_GT(*scores["err"], 0.0);
    EXPECT_LT(*scores["srf"], 1.0);
  }
  EXPECT_FALSE(ComputeScores(runs.Input(SrfDefinition::kFirstShock))["no_such_score"]);
}

TEST(ScoreRegistryTest, ThresholdsJudgeInTheScoresDirection) {
  const ScoreDefinition& err = *FindScore("err");
  const ScoreDefinition& srf = *FindScore("srf");
  EXPECT_EQ(err.ThresholdKey(), "err_max");
  EXPECT_EQ(srf.ThresholdKey(), "srf_min");
  EXPECT_TRUE(err.Meets(0.1, 0.1));
  EXPECT_FALSE(err.Meets(0.11, 0.1));
  EXPECT_TRUE(srf.Meets(0.8, 0.8));
  EXPECT_FALSE(srf.Meets(0.79, 0.8));
  EXPECT_EQ(FindScore("none"), nullptr);
  // The paper's thresholds judge by default; a score without a default does not.
  const auto defaults = DefaultThresholds();
  EXPECT_EQ(defaults.at("err"), 0.10);
  EXPECT_EQ(defaults.at("srf"), 0.80);
  for (const ScoreDefinition& score : Scores()) {
    EXPECT_EQ(defaults.contains(score.name), score.default_threshold.has_value()) << score.name;
  }
}

// PFr: min / max of the first shocks' peak forces, whatever the later shocks and the impulses.
TEST(ScoreRegistryTest, PfrIsTheRatioOfTheFirstShocksPeakForces) {
  const TwoRuns runs;
  ASSERT_EQ(runs.shocks.size(), 1u);  // Both pulses within the rest duration: one shock.
  ASSERT_EQ(runs.reference_shocks.size(), 1u);
  const ScoreValues scores = ComputeScores(runs.Input(SrfDefinition::kFirstShock));
  ASSERT_TRUE(scores["pfr"].has_value());
  EXPECT_NEAR(*scores["pfr"], 600.0 / 800.0, 1e-4);  // The half-sines' peaks, as sampled.
  EXPECT_EQ(*scores["pfr"], runs.reference_shocks[0].peak_force_n / runs.shocks[0].peak_force_n);
  const ScoreDefinition& pfr = *FindScore("pfr");
  EXPECT_EQ(pfr.ThresholdKey(), "pfr_min");
  EXPECT_FALSE(pfr.default_threshold.has_value());
  // Nothing to compare without a shock on either side; 0 when one side has none.
  const std::vector<Shock> none;
  const UniformSignal quiet{0.0, 1e-5, std::vector<double>(3001, 0.0)};
  EXPECT_EQ(pfr.compute(ScoringInput{.displacement = runs.displacement,
                                     .reference_displacement = runs.reference_displacement,
                                     .force = quiet,
                                     .shocks = none,
                                     .reference_force = quiet,
                                     .reference_shocks = none}),
            std::nullopt);
  EXPECT_EQ(pfr.compute(ScoringInput{.displacement = runs.displacement,
                                     .reference_displacement = runs.reference_displacement,
                                     .force = quiet,
                                     .shocks = none,
                                     .reference_force = runs.reference_force,
                                     .reference_shocks = runs.reference_shocks}),
            std::optional<double>(0.0));
}

TEST(ScoreRegistryTest, ScoreValuesHoldAValueOrNone) {
  ScoreValues values;
  EXPECT_FALSE(values["err"].has_value());
  values.Set("err", 0.25);
  EXPECT_EQ(values["err"], std::optional<double>(0.25));
  values.Set("err", std::nullopt);
  EXPECT_FALSE(values["err"].has_value());
}

}  // namespace
}  // namespace shockmap

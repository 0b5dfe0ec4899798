#include "specs/ensemble_draws.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shockmap {
namespace {

// A uniform deviate in (0, 1): the high 53 bits of one output, centred in their cell.
double UniformDeviate(std::mt19937_64& rng) {
  return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
}

double StandardNormal(std::mt19937_64& rng) {
  const double u1 = UniformDeviate(rng);
  const double u2 = UniformDeviate(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

std::uint64_t Fnv1a64(std::string_view text) {
  std::uint64_t h = 0xCBF29CE484222325ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001B3ULL;
  }
  return h;
}

std::uint64_t MemberSeed(std::uint64_t study_seed, std::string_view state, std::int64_t member) {
  const std::uint64_t of_state = SplitMix64(SplitMix64(study_seed) ^ Fnv1a64(state));
  return SplitMix64(of_state ^ static_cast<std::uint64_t>(member));
}

int GapSeed(std::uint64_t member_seed, int stream) {
  return static_cast<int>(SplitMix64(member_seed ^ static_cast<std::uint64_t>(stream)) >> 33);
}

std::string ToString(ScatterLaw law) {
  switch (law) {
    case ScatterLaw::kNormal:
      return "normal";
    case ScatterLaw::kLognormal:
      return "lognormal";
    case ScatterLaw::kUniform:
      return "uniform";
  }
  return "normal";
}

double Draw(const ParameterScatter& s, std::mt19937_64& rng) {
  double v = 0.0;
  switch (s.law) {
    case ScatterLaw::kNormal:
      v = s.centre + s.spread * StandardNormal(rng);
      break;
    case ScatterLaw::kLognormal:
      v = s.centre * std::exp(s.spread * StandardNormal(rng));
      break;
    case ScatterLaw::kUniform:
      v = s.min + (s.max - s.min) * UniformDeviate(rng);
      break;
  }
  return std::clamp(v, s.min, s.max);
}

std::vector<double> DrawParameters(const std::vector<ParameterScatter>& scatters,
                                   std::uint64_t member_seed) {
  std::mt19937_64 rng(member_seed);
  std::vector<double> values;
  values.reserve(scatters.size());
  for (const ParameterScatter& s : scatters) values.push_back(Draw(s, rng));
  return values;
}

}  // namespace shockmap

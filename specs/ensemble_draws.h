#pragma once
// What a member of an ensemble study draws (docs/ensembles.md, "Seeding"): its seed from the
// study's seed, its clearance state and its index, and from that seed the scattered scene
// parameters and the seeds of its gap draws. The same (study seed, state, index) gives the same
// member on every platform: the generator is std::mt19937_64, whose sequence the C++ standard
// fixes, and the laws are computed here rather than by <random>'s distributions, which it does
// not fix.

#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace shockmap {

// SplitMix64's output function (Steele, Lea and Flood 2014; the seeding generator of
// java.util.SplittableRandom and of the xoshiro family): a bijection of 64-bit words whose
// outputs for neighbouring inputs are statistically independent.
std::uint64_t SplitMix64(std::uint64_t x);

// FNV-1a, 64 bits, of the bytes of `text`: a state's name as a word for the seed.
std::uint64_t Fnv1a64(std::string_view text);

// SplitMix64(SplitMix64(SplitMix64(study_seed) ^ Fnv1a64(state)) ^ member). The numerical
// setting does not enter: every setting runs the same members (common random numbers), so that
// settings are compared on the same draws.
std::uint64_t MemberSeed(std::uint64_t study_seed, std::string_view state, std::int64_t member);

// The seed a member hands to its scene's gap law (bundle.wire.gap_m or bundle.wrapper.gap_m,
// formats/scene_file.h): stream 1 for the pins, 2 for the wrapper; the high 31 bits of
// SplitMix64(member_seed ^ stream), as a scene file's seed is a non-negative 32-bit integer.
int GapSeed(std::uint64_t member_seed, int stream);

enum class ScatterLaw { kNormal, kLognormal, kUniform };
std::string ToString(ScatterLaw law);

// The scatter of one numeric scene parameter. normal: centre = mean, spread = standard
// deviation; lognormal: centre = median, spread = standard deviation of its logarithm;
// uniform: between min and max (centre their midpoint, spread unused). Every draw is clipped
// to [min, max].
struct ParameterScatter {
  std::string path;
  ScatterLaw law = ScatterLaw::kNormal;
  double centre = 0.0, spread = 0.0;
  double min = 0.0, max = 0.0;
};

// One value of the law from `rng`: Box-Muller on two uniform deviates of 53 bits for the
// normal and lognormal laws, one uniform deviate for the uniform law; clipped.
double Draw(const ParameterScatter& scatter, std::mt19937_64& rng);

// The member's values of `scatters`, in their order, from a generator seeded with
// member_seed.
std::vector<double> DrawParameters(const std::vector<ParameterScatter>& scatters,
                                   std::uint64_t member_seed);

}  // namespace shockmap

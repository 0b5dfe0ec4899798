#include "validation/scores.h"

#include <algorithm>

#include "validation/spectral_error.h"

namespace shockmap {
namespace {

// Err, paper eq. 8: the spectral error of the displacement, against the reference's spectrum
// when it was computed once.
std::optional<double> Err(const ScoringInput& in) {
  return in.reference_spectrum != nullptr
             ? SpectralError(in.displacement, *in.reference_spectrum, 0.0, in.end_s, in.psd)
             : SpectralError(in.displacement, in.reference_displacement, 0.0, in.end_s, in.psd);
}

// SRf, paper eq. 9: the impulse ratio of the first shocks, under the study's reading of eq. 9.
std::optional<double> Srf(const ScoringInput& in) {
  return DefinedImpulseRatio(in.srf_definition, in.force, in.shocks, in.reference_force,
                             in.reference_shocks, in.segmentation, in.end_s);
}

// PFr: the ratio of the first shocks' peak forces, the force a pin is sized with, read as SRf
// reads impulses (paper eq. 9): min / max, nothing when neither run has a shock, 0 when one has.
std::optional<double> Pfr(const ScoringInput& in) {
  if (in.shocks.empty() && in.reference_shocks.empty()) return std::nullopt;
  if (in.shocks.empty() || in.reference_shocks.empty()) return 0.0;
  const double a = in.shocks.front().peak_force_n, b = in.reference_shocks.front().peak_force_n;
  return std::max(a, b) > 0.0 ? std::min(a, b) / std::max(a, b) : 1.0;
}

constexpr ScoreDefinition kScores[] = {
    {.name = "err",
     .label = "Err",
     .source = "paper eq. 8",
     .meaning = "spectral error of the scored displacement",
     .better = Better::kSmaller,
     // The paper's Fig. 3b: Err ~ 3 % is a match; 10 % is the limit used.
     .default_threshold = 0.10,
     .threshold_low = 1e-9,
     .threshold_high = 1.0,
     .required = true,
     .map_low = 0.0,
     .map_high = 0.6,
     .reads = ReferencePart::kWindowTip,
     .compute = Err},
    {.name = "srf",
     .label = "SRf",
     .source = "paper eq. 9",
     .meaning = "impulse ratio of the first shock",
     .better = Better::kLarger,
     // The paper (§2.4): SRf > 0.8 is an acceptable contact force.
     .default_threshold = 0.80,
     .threshold_low = 0.0,
     .threshold_high = 1.0,
     .required = false,
     .map_low = 0.5,
     .map_high = 1.0,
     .reads = ReferencePart::kFirstShock,
     .compute = Srf},
    {.name = "pfr",
     .label = "PFr",
     .source = "eq. 9 on peak forces",
     .meaning = "peak-force ratio of the first shock, the sizing force",
     .better = Better::kLarger,
     .default_threshold = std::nullopt,  // Judges only when a threshold is given.
     .threshold_low = 0.0,
     .threshold_high = 1.0,
     .required = false,
     .map_low = 0.5,
     .map_high = 1.0,
     // Its peak is the first shock's: judged by the first shock's estimate, its impulse's.
     .reads = ReferencePart::kFirstShock,
     .compute = Pfr},
};

}  // namespace

std::string_view ToString(ReferencePart part) {
  return part == ReferencePart::kWindowTip ? "the window's tip" : "the first shock";
}

std::string ScoreDefinition::ThresholdKey() const {
  return std::string(name) + (better == Better::kSmaller ? "_max" : "_min");
}

std::string ScoreDefinition::ThresholdMeaning() const {
  return std::string(better == Better::kSmaller ? "largest" : "smallest") + " acceptable " +
         std::string(label);
}

bool ScoreDefinition::Meets(double value, double threshold) const {
  return better == Better::kSmaller ? value <= threshold : value >= threshold;
}

std::span<const ScoreDefinition> Scores() { return kScores; }

const ScoreDefinition* FindScore(std::string_view name) {
  const auto found = std::ranges::find(kScores, name, &ScoreDefinition::name);
  return found == std::end(kScores) ? nullptr : &*found;
}

std::optional<double> ScoreValues::operator[](std::string_view name) const {
  const auto found = values_.find(name);
  if (found == values_.end()) return std::nullopt;
  return found->second;
}

void ScoreValues::Set(std::string_view name, std::optional<double> value) {
  if (value) {
    values_.insert_or_assign(std::string(name), *value);
  } else if (const auto found = values_.find(name); found != values_.end()) {
    values_.erase(found);
  }
}

ScoreValues ComputeScores(const ScoringInput& input) {
  ScoreValues values;
  for (const ScoreDefinition& score : kScores) values.Set(score.name, score.compute(input));
  return values;
}

std::map<std::string, double, std::less<>> DefaultThresholds() {
  std::map<std::string, double, std::less<>> thresholds;
  for (const ScoreDefinition& score : kScores) {
    if (score.default_threshold) thresholds.emplace(score.name, *score.default_threshold);
  }
  return thresholds;
}

}  // namespace shockmap

#pragma once
// The registry of scores: each measure of how well a numerical run reproduces its reference is
// declared once, in validation/scores.cpp: its name, label and meaning, which direction is
// better, its default threshold, its map colours, and how it is computed from a run and its
// reference. Everything else finds it there: the kinds' scoring (compare/), the criteria
// (validation/validity_criteria.h), the study files' and the command line's thresholds, the
// validity maps, the report's tables and the exports. A kind's stored score row (records/)
// carries a score as an optional real column of the score's name (docs/architecture.md, "Add a
// score").

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/uniform_signal.h"
#include "validation/impulse_ratio.h"
#include "validation/psd.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

// What a score is computed from: a numerical run and its reference over [0, end_s], each with
// its scored displacement and its scored contact force segmented into shocks.
struct ScoringInput {
  const UniformSignal& displacement;
  const UniformSignal& reference_displacement;
  // The reference displacement's spectrum with `psd` over [0, end_s] when it was computed once
  // for every run scored against it (compare/reference_run.h), or null.
  const PowerSpectrum* reference_spectrum = nullptr;
  PsdOptions psd{};
  double end_s = 0.0;
  const UniformSignal& force;
  const std::vector<Shock>& shocks;
  const UniformSignal& reference_force;
  const std::vector<Shock>& reference_shocks;
  SrfDefinition srf_definition = SrfDefinition::kFirstShock;
  ShockSegmentationOptions segmentation{};
};

// The part of the reference a score reads, by whose estimate the reference decides it
// (compare/reference_decision.h): the tip over the whole window, or the first shock alone.
enum class ReferencePart { kWindowTip, kFirstShock };

// "the window's tip", "the first shock".
std::string_view ToString(ReferencePart part);

// Which values of a score are better: smaller ones (its threshold is the largest acceptable
// value, key <name>_max) or larger ones (the smallest acceptable, key <name>_min).
enum class Better { kSmaller, kLarger };

struct ScoreDefinition {
  // The stored column, the map metric (`map --metric err`), the thresholds' key (err_max) and
  // flag (--err-max).
  std::string_view name;
  std::string_view label;    // As plots and tables show it: "Err".
  std::string_view source;   // Where it is defined: "paper eq. 8".
  std::string_view meaning;  // One line.
  Better better = Better::kSmaller;
  // The threshold the criteria judge with unless another is given; none: the score is reported
  // and drawn, and judges only when a threshold is given.
  std::optional<double> default_threshold;
  double threshold_low = 0.0, threshold_high = 1.0;  // What a threshold may be.
  // True when a scored point without a value fails a threshold (Err is computed whenever a run
  // is scored); false when a missing value passes it (SRf when neither run has a shock).
  bool required = false;
  double map_low = 0.0, map_high = 1.0;  // The colour range of validity maps.
  ReferencePart reads = ReferencePart::kWindowTip;
  // Nothing when there is nothing to compare. May throw std::invalid_argument (as the signal
  // functions of validation/ do).
  std::optional<double> (*compute)(const ScoringInput& input) = nullptr;

  // "err_max", "srf_min".
  std::string ThresholdKey() const;
  // "largest acceptable Err", "smallest acceptable SRf".
  std::string ThresholdMeaning() const;
  // Whether `value` meets `threshold` (<= for a smaller-is-better score, >= otherwise).
  bool Meets(double value, double threshold) const;
};

// Every score, in the order tables and reports show them.
std::span<const ScoreDefinition> Scores();
// The score named `name`, or null.
const ScoreDefinition* FindScore(std::string_view name);

// The values of the registered scores of one run, by score name; a score without a value (not
// scored, or nothing to compare) has none.
class ScoreValues {
 public:
  std::optional<double> operator[](std::string_view name) const;
  void Set(std::string_view name, std::optional<double> value);

 private:
  std::map<std::string, double, std::less<>> values_;
};

// Every registered score of the input, in registry order.
ScoreValues ComputeScores(const ScoringInput& input);

// The default threshold of every score that has one, by name.
std::map<std::string, double, std::less<>> DefaultThresholds();

}  // namespace shockmap

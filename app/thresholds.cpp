#include "app/thresholds.h"

#include <fmt/format.h>

#include <algorithm>

#include "analysis/study_thresholds.h"
#include "app/flag_checks.h"

namespace shockmap {

void AddThresholdFlags(CLI::App* command, ThresholdFlags& flags) {
  for (const ScoreDefinition& score : Scores()) {
    std::string key = score.ThresholdKey();
    std::ranges::replace(key, '_', '-');
    const std::string name(score.name);
    const std::string fallback =
        score.default_threshold ? fmt::format("{:g}", *score.default_threshold) : "none";
    command
        ->add_option_function<double>(
            "--" + key, [&flags, name](double v) { flags.given[name] = v; },
            fmt::format("{} ({}); default: the study file's {}, else {}", score.ThresholdMeaning(),
                        score.source, score.ThresholdKey(), fallback))
        ->check(FiniteIn(score.threshold_low, false, score.threshold_high));
  }
}

CriteriaOptions ThresholdsFor(const ThresholdFlags& flags, const std::string& database_path,
                              const std::string& study) {
  return StudyCriteriaOptions(database_path, study, flags.given);
}

}  // namespace shockmap

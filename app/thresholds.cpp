#include "app/thresholds.h"

#include <fmt/format.h>

#include <algorithm>

#include "app/flag_checks.h"
#include "db/report_queries.h"
#include "formats/json_reader.h"
#include "formats/study_file.h"

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
  CriteriaOptions options;
  if (const auto stored = StoredStudySpec(database_path, study)) {
    const std::string file = database_path + ": stored study " + study;
    options.thresholds = StudyThresholds(ParseJsonText(*stored, file), file);
  }
  for (const auto& [name, threshold] : flags.given) options.thresholds[name] = threshold;
  return options;
}

}  // namespace shockmap

#pragma once
// The thresholds a command judges validity with: the study's own (the `thresholds` of its
// stored study file over the registry's defaults, specs/study_file.h StudyThresholds), each
// replaced by its flag when one is given (--err-max, --srf-min, ...: one per score of the
// registry, validation/scores.h).

#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <string>

#include "validation/validity_criteria.h"

namespace shockmap {

struct ThresholdFlags {
  std::map<std::string, double, std::less<>> given;  // By score name.
};

// One flag per score of the registry: --NAME-max for a score whose smaller values are better,
// --NAME-min otherwise.
void AddThresholdFlags(CLI::App* command, ThresholdFlags& flags);

// The criteria options of the stored `study` with the flags given over its own thresholds
// (analysis/study_thresholds.h).
CriteriaOptions ThresholdsFor(const ThresholdFlags& flags, const std::string& database_path,
                              const std::string& study);

}  // namespace shockmap

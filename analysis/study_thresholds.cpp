#include "analysis/study_thresholds.h"

#include "core/input_error.h"
#include "db/report_queries.h"
#include "specs/study_file.h"

namespace shockmap {

CriteriaOptions StudyCriteriaOptions(const std::string& database_path, const std::string& study,
                                     const std::map<std::string, double, std::less<>>& given) {
  CriteriaOptions options;
  if (const auto stored = StoredStudyJson(database_path, study)) {
    options.thresholds = StudyThresholds(*stored, database_path + ": stored study " + study);
  }
  for (const auto& [name, threshold] : given) options.thresholds[name] = threshold;
  std::string error;
  if (!options.IsValid(&error)) throw InputError(error);
  return options;
}

}  // namespace shockmap

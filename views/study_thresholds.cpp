#include "views/study_thresholds.h"

#include "db/report_queries.h"
#include "formats/json_reader.h"
#include "formats/study_file.h"

namespace shockmap {

CriteriaOptions StudyCriteriaOptions(const std::string& database_path, const std::string& study,
                                     const std::map<std::string, double, std::less<>>& given) {
  CriteriaOptions options;
  if (const auto stored = StoredStudySpec(database_path, study)) {
    const std::string file = database_path + ": stored study " + study;
    options.thresholds = StudyThresholds(ParseJsonText(*stored, file), file);
  }
  for (const auto& [name, threshold] : given) options.thresholds[name] = threshold;
  return options;
}

}  // namespace shockmap

#pragma once
// The thresholds a stored study is judged with: the `thresholds` of its stored study file over
// the registry's defaults (specs/study_file.h StudyThresholds, validation/scores.h), and the
// caller's over them (a command's flags, a Python keyword).

#include <map>
#include <string>

#include "validation/validity_criteria.h"

namespace shockmap {

// The criteria options of `study` in the database, with `given` (by score name) over its own
// thresholds. Throws InputError when the stored study file's thresholds are unreadable or the
// options are not valid (CriteriaOptions::IsValid's message: an unknown score, a threshold out
// of its range), DbError as the read-only queries do.
CriteriaOptions StudyCriteriaOptions(const std::string& database_path, const std::string& study,
                                     const std::map<std::string, double, std::less<>>& given = {});

}  // namespace shockmap

#pragma once
// The stored points of one study, read from the database for criteria, maps and reports.

#include <string>
#include <vector>

#include "validation/validity_criteria.h"

namespace shockmap {

// The study to read: `study` when given, else the database's only study. Throws InputError
// when the database holds no such study, or several and none was named.
std::string ResolveStudyName(const std::string& database_path, const std::string& study);

// `study` among the studies of the paper's problem (kind "canonical"), the one maps, criteria,
// Fig. 4, cost and advice read: when given, it must be one (InputError naming its kind and the
// commands for that kind otherwise); else the database's only one, or InputError listing them.
// `command` names the asking command in the message.
std::string ResolveCanonicalStudy(const std::string& database_path, const std::string& study,
                                  const std::string& command);

// Points of `study` run with `scheme` that have a score row (every status but pending/running).
std::vector<ScoredPoint> LoadScoredPoints(const std::string& database_path,
                                          const std::string& study, const std::string& scheme);

// The explicit modal points of `study` validity criteria are derived from. Throws InputError
// when there is none (a study of scenes or an ensemble, or one not run yet), rather than let
// criteria of nothing be printed.
std::vector<ScoredPoint> LoadCriteriaPoints(const std::string& database_path,
                                            const std::string& study);

}  // namespace shockmap

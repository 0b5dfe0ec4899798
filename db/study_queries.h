#pragma once
// The read-only queries behind `study status`, criteria, maps and reports: all on read-only
// connections (db/read_only_query.h), so they work on a database another run is writing.

#include <optional>
#include <string>
#include <vector>

#include "db/point_tables.h"
#include "db/read_only_query.h"

namespace shockmap {

// One row per study of any kind: points, counts by status (running ones are held by a run),
// last update.
Table StudyProgress(const std::string& database_path);

// The points of a kind whose PointTable lists progress_by columns (ensemble members by clearance
// state and setting), counted by status as StudyProgress counts them: one row per study and
// value of those columns.
struct StudyBreakdown {
  const PointTable* table = nullptr;
  Table progress;
};
std::vector<StudyBreakdown> StudyProgressBreakdowns(const std::string& database_path);

// Where the stored points were computed: one row per study, host and rank (0 in a local run;
// 1..N-1 the worker ranks of an MPI job) with its count of points and their point_id range.
Table StudyOrigins(const std::string& database_path);

// The names of the stored studies, sorted.
std::vector<std::string> StudyNames(const std::string& database_path);

// The run holding the database ("run 7 (host h, pid 42), last heartbeat 3 s ago"), if one's
// heartbeat is younger than kLeaseGraceS.
std::optional<std::string> LiveWriter(const std::string& database_path);

// Every column of the view `results` (the parameters, status and scores of canonical points)
// of the points of `study` run with `scheme` that have a score row, by point_id.
Table ScoredPointRows(const std::string& database_path, const std::string& study,
                      const std::string& scheme);

}  // namespace shockmap

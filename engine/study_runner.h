#pragma once
// Runs a study into a database: computes what is missing, one transaction per finished point,
// references computed once per database and shared by every point that needs them.

#include <cstddef>
#include <string>

#include "db/study_database.h"
#include "formats/study_spec.h"

namespace shockmap {

struct StudyRunOptions {
  std::string database_path = kDefaultDatabasePath;
  int jobs = 0;  // 0: one worker per hardware thread.
  bool retry_failed = false;
  bool progress = true;  // On stderr.
};

struct StudyRunSummary {
  std::size_t points_in_study = 0;
  std::size_t points_computed = 0;
  long ok = 0, diverged = 0, failed = 0, reference_unconverged = 0;
  int references_computed = 0, references_reused = 0;
  int points_reclaimed = 0;  // Left 'running' by a dead process, taken up again.
  int jobs = 0;
  double wall_s = 0.0;
  double reference_wall_s = 0.0;  // Wall time of the reference phase.
  double point_wall_s = 0.0;      // Wall time of the point phase.
};

// The workers a run uses: options.jobs, or one per hardware thread.
int WorkerCount(const StudyRunOptions& options);

// Counts one finished point in the summary by its stored status.
void CountOutcome(const std::string& status, StudyRunSummary& summary);

// Throws InputError when the study exists in the database with other problem or scoring
// settings (its stored scores would no longer match its spec), and DbError on database faults.
StudyRunSummary RunStudy(const StudySpec& spec, const StudyRunOptions& options);

}  // namespace shockmap

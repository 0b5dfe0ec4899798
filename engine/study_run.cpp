#include "engine/study_run.h"

#include <fmt/format.h>

#include <thread>

namespace shockmap {

int WorkerCount(const StudyRunOptions& options) {
  return options.jobs > 0 ? options.jobs
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void CountOutcome(RunStatus status, StudyRunSummary& summary) {
  ++summary.points_computed;
  switch (status) {
    case RunStatus::kOk:
      ++summary.ok;
      break;
    case RunStatus::kDiverged:
      ++summary.diverged;
      break;
    case RunStatus::kUnstable:
      ++summary.unstable;
      break;
    case RunStatus::kFailed:
      ++summary.failed;
      break;
    case RunStatus::kReferenceUnconverged:
      ++summary.reference_unconverged;
      break;
  }
}

std::string OutcomeCounts(const StudyRunSummary& s) {
  return fmt::format("ok {}, diverged {}, unstable {}, failed {}, reference_unconverged {}", s.ok,
                     s.diverged, s.unstable, s.failed, s.reference_unconverged);
}

StudyRunSummary RunStudy(const StudyFile& study, const StudyRunOptions& options) {
  return WithStudyKind(study, [&](const auto& kind) { return RunStudyKind(kind, options); });
}

void ServeStudy(const StudyFile& study, RemoteWorkers& remote) {
  WithStudyKind(study, [&](const auto& kind) { ServeStudyKind(kind, remote); });
}

}  // namespace shockmap

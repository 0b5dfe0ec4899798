#include "engine/study_run.h"

#include <thread>

#include "engine/canonical_study.h"
#include "engine/scene_study.h"

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
    case RunStatus::kFailed:
      ++summary.failed;
      break;
    case RunStatus::kReferenceUnconverged:
      ++summary.reference_unconverged;
      break;
  }
}

StudyRunSummary RunStudy(const StudyFile& study, const StudyRunOptions& options) {
  return std::visit(
      [&](const auto& spec) {
        using Spec = std::decay_t<decltype(spec)>;
        if constexpr (std::is_same_v<Spec, StudySpec>) {
          return RunStudyKind(CanonicalStudy(spec), options);
        } else {
          return RunStudyKind(SceneStudy(spec), options);
        }
      },
      study);
}

}  // namespace shockmap

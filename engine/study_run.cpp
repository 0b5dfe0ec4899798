#include "engine/study_run.h"

#include <thread>

#include "engine/canonical_study.h"
#include "engine/scene_study.h"

namespace shockmap {

int WorkerCount(const StudyRunOptions& options) {
  return options.jobs > 0 ? options.jobs
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void CountOutcome(const std::string& status, StudyRunSummary& summary) {
  ++summary.points_computed;
  if (status == "ok") ++summary.ok;
  if (status == "diverged") ++summary.diverged;
  if (status == "failed") ++summary.failed;
  if (status == "reference_unconverged") ++summary.reference_unconverged;
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

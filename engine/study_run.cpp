#include "engine/study_run.h"

#include <fmt/format.h>

#include <thread>

#include "engine/canonical_study.h"
#include "engine/ensemble_study.h"
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

namespace {

// Calls f with the study kind of the file.
template <typename F>
auto WithKind(const StudyFile& study, F f) {
  return std::visit(
      [&](const auto& spec) {
        using Spec = std::decay_t<decltype(spec)>;
        if constexpr (std::is_same_v<Spec, StudySpec>) {
          return f(CanonicalStudy(spec));
        } else if constexpr (std::is_same_v<Spec, SceneStudySpec>) {
          return f(SceneStudy(spec));
        } else {
          return f(EnsembleStudy(spec));
        }
      },
      study);
}

}  // namespace

StudyRunSummary RunStudy(const StudyFile& study, const StudyRunOptions& options) {
  return WithKind(study, [&](const auto& kind) { return RunStudyKind(kind, options); });
}

void ServeStudy(const StudyFile& study, RemoteWorkers& remote) {
  WithKind(study, [&](const auto& kind) { ServeStudyKind(kind, remote); });
}

}  // namespace shockmap

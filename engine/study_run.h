#pragma once
// Runs a study file of any kind through the one study engine (engine/study_engine.h).

#include <type_traits>
#include <variant>

#include "engine/canonical_study.h"
#include "engine/ensemble_study.h"
#include "engine/scene_study.h"
#include "engine/study_engine.h"
#include "specs/study_file.h"

namespace shockmap {

// Returns f(kind) with the study kind of the file (CanonicalStudy, SceneStudy or EnsembleStudy).
template <typename F>
auto WithStudyKind(const StudyFile& study, F f) {
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

// Throws InputError when the study is stored with other settings, DbError on database faults,
// NoWorkerRankLeft when every worker rank fell silent. With options.remote, this is rank 0 of an
// MPI job: the worker ranks compute, it writes.
StudyRunSummary RunStudy(const StudyFile& study, const StudyRunOptions& options);

// On ranks 1..N-1 of an MPI job: computes what rank 0's RunStudy of the same file hands out.
void ServeStudy(const StudyFile& study, RemoteWorkers& remote);

}  // namespace shockmap

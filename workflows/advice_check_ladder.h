#pragma once
// The advice for an ensemble study's scene checked on its members (docs/ensembles.md, "Advice
// checked on the bundle"): the ensemble run at the advised settings, one rung coarser and finer
// rungs until the sizing statistics stop moving, and the verdict per state and zone family.
// `shockmap check-advice` and Python's shockmap.check_advice() both run it.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/advice_check.h"
#include "analysis/ensemble_sizing.h"
#include "db/study_database.h"
#include "formats/scene_file.h"
#include "specs/advice_check_outcomes.h"
#include "validation/scene_advice.h"
#include "workflows/workflow_log.h"

namespace shockmap {

// The first ladder: 1/3, 1 and 3 times the advised truncations (the advice holds where the
// rung above it agrees; finer rungs are added only while a family has not converged).
inline constexpr int kFirstLadderRungs = 3;
// The largest values of a request's options (each front end refuses more): rungs, members per
// state and rung, simulated seconds of a member.
inline constexpr int kMaxLadderRungs = 12;
inline constexpr int kMaxLadderMembers = 100000;
inline constexpr double kMaxLadderWindowS = 1e4;

// The criteria a scene's zones are advised and checked with (`advise SCENE.json`,
// `check-advice`): the mode-resolution study's boundary with the first shock's peak force within
// 10 % (PFr >= 0.9), the statistic a zone is sized on (docs/physics.md §5.1). A path from the
// repository's top; installed as shared data (app/shared_data.h).
inline constexpr const char* kSceneCriteria = "studies/baselines/modes_fig4_peak_force.json";

struct AdviceCheckRequest {
  std::string study_file;  // An ensemble study ("kind": "scene_ensemble").
  // Criteria as `criteria derive --out` writes them.
  std::string criteria_file = kSceneCriteria;
  std::string database_path = kDefaultDatabasePath;
  int members = 0;                  // Per clearance state and rung; 0: the study file's.
  double window_s = 0.0;            // Simulated seconds of every member; 0: the study file's.
  std::vector<std::string> states;  // The clearance states to check; empty: every one.
  std::string_view states_name = "--states";  // How the caller's user spells `states`.
  int jobs = 0;                               // Worker threads; 0: the number of cores.
  int max_rungs = 6;  // Rungs at most (1/3, 1, 3, 9, ... times the advice), >= kFirstLadderRungs.
  SizingOptions sizing;     // The sizing quantile, and how closely two rungs agree.
  std::string write_study;  // Non-empty: write the first ladder's study here instead of running it.
  // Non-empty: the outcomes file RecordAdviceCheck adds a decided check to, read before the
  // ladder runs (a bad one stops nothing computed).
  std::string record;
  bool progress_lines = false;  // The study engine's progress lines on stderr.
  SceneFileAccess access;
};

struct AdviceCheckLadder {
  SceneAdvice advice;
  // The last ladder's check; none when its study was written or the run was stopped.
  std::optional<AdviceCheck> check;
  // A stop signal that ended the run (engine/stop_request.h), with the members of the ladder
  // stored and still to compute then; 0 when not stopped.
  int stop_signal = 0;
  int members_computed = 0, members_to_compute = 0;
  // What a recorded outcome names: the study, the scene and criteria files with their digests,
  // and the last ladder's states, members and window.
  AdviceCheckOutcome outcome;
};

// Runs the ladder, only the members the database does not hold yet. Throws InputError for a
// study that is not an ensemble, a state it does not have (naming `states`), bad criteria or a
// bad outcomes file (read before anything runs), and a lowest rung beyond the budget.
AdviceCheckLadder CheckAdviceOnMembers(const AdviceCheckRequest& request, const WorkflowLog& log);

// Adds a decided check's outcome to the outcomes file request.record (created when absent),
// which `advise --checks` reads; an undecided or unconverged check is only told of.
void RecordAdviceCheck(const AdviceCheckRequest& request, const AdviceCheckLadder& ladder,
                       const WorkflowLog& log);

}  // namespace shockmap

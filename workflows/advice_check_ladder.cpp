#include "workflows/advice_check_ladder.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "db/ensemble_members.h"
#include "db/schema.h"
#include "db/sqlite_handle.h"
#include "engine/study_run.h"
#include "formats/criteria_json.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "specs/advice_check_outcomes.h"
#include "specs/advice_check_study.h"
#include "specs/ensemble_study_spec.h"
#include "specs/study_file.h"
#include "views/advice_check_text.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// The rung at factor 1 in LadderFactors' order (1/3 first).
constexpr int kAdvisedRung = 1;

// The ensemble study file's JSON, refused unless it is an ensemble.
Json ReadEnsembleJson(const std::string& file) {
  const Json json = ReadJsonFile(file);
  if (StudyKindOf(json, file) != StudyFileKind::kSceneEnsemble) {
    throw InputError(file + ": kind \"" + ToString(StudyKindOf(json, file)) +
                     "\": check-advice needs an ensemble study (\"kind\": \"scene_ensemble\"), "
                     "whose draws and clearance states the advice is checked on");
  }
  return json;
}

// The ensemble with only the clearance states `names` (every one when empty), in its order.
// Throws InputError naming `option`, the name and the study's states when one is not there. A
// state whose entry is malformed has no name here; the study file's parser names its fault.
Json WithStates(Json ensemble, const std::vector<std::string>& names, std::string_view option,
                const std::string& file) {
  if (names.empty()) return ensemble;
  const auto name_of = [](const Json& state) {
    return state.is_object() && state.contains("name") && state["name"].is_string()
               ? state["name"].get<std::string>()
               : std::string();
  };
  const Json all = ensemble.value("clearance_states", Json::array());
  std::vector<std::string> known;
  for (const Json& state : all) known.push_back(name_of(state));
  for (const std::string& name : names) {
    if (std::ranges::find(known, name) == known.end()) {
      throw InputError(
          fmt::format("{}: \"{}\" is not a clearance state of {} (it has: {})", option, name, file,
                      known.empty() ? "none" : fmt::format("{}", fmt::join(known, ", "))));
    }
  }
  Json kept = Json::array();
  for (const Json& state : all) {
    if (std::ranges::find(names, name_of(state)) != names.end()) kept.push_back(state);
  }
  ensemble["clearance_states"] = kept;
  return ensemble;
}

// Each advised truncation with the beams that take it: "224.1 (wrapper), 1254 (17 beams)".
std::string AdvisedTruncations(const SceneAdvice& advice) {
  std::map<double, std::vector<std::string>> beams;
  for (const BeamAdvice& b : advice.beams) beams[b.r_ftrunc].push_back(b.name);
  std::string text;
  for (const auto& [r_ftrunc, names] : beams) {
    text += fmt::format("{}{:.4g} ({})", text.empty() ? "" : ", ", r_ftrunc,
                        names.size() == 1 ? names.front() : fmt::format("{} beams", names.size()));
  }
  return text;
}

// A ladder's run, and its sizing statistics unless a signal stopped it.
struct LadderRun {
  StudyRunSummary summary;
  EnsembleSizing sizing;
};

// Runs the ladder's study (only the members not stored yet) and, unless a signal stopped it,
// reads its sizing statistics and sets what `outcome` says of its members: their clearance
// states, their number per state and rung, their window.
LadderRun RunLadder(const AdviceCheckRequest& r, const Json& study, const WorkflowLog& log,
                    AdviceCheckOutcome& outcome) {
  const StudyFile parsed = ParseStudyFile(study, r.study_file, r.access);
  StudyRunOptions options;
  options.database_path = r.database_path;
  options.jobs = r.jobs;
  options.progress = r.progress_lines;
  options.on_progress = log.progress;
  LadderRun run;
  run.summary = RunStudy(parsed, options);
  if (run.summary.stop_signal != 0) return run;
  log.Say(fmt::format("  {} members in the ladder, {} computed now", run.summary.points_in_study,
                      run.summary.points_computed));
  Connection db(r.database_path, Connection::Mode::kReadOnly);
  CheckSchema(db);
  const std::string name = study.at("name");
  const auto& spec = std::get<EnsembleStudySpec>(parsed);
  run.sizing = SizeEnsemble(CurrentMembers(ReadEnsemble(db, name)), name, r.sizing);
  outcome.members = spec.members;
  outcome.window_s = spec.window_s;
  outcome.states.clear();
  for (const ClearanceState& state : spec.states) outcome.states.push_back(state.name);
  return run;
}

// What an outcome names: the study, and the scene and criteria files with their digests (the
// rest is the check's). The study's name is checked by the ladder's parser.
AdviceCheckOutcome NamedOutcome(const Json& ensemble, const std::string& scene_file,
                                const std::string& scene_digest, const std::string& criteria_file,
                                const Json& criteria_json) {
  AdviceCheckOutcome outcome;
  const Json name = ensemble.value("name", Json());
  if (name.is_string()) outcome.study = name.get<std::string>();
  outcome.scene = scene_file;
  outcome.scene_digest = scene_digest;
  outcome.criteria = criteria_file;
  outcome.criteria_digest = JsonDigest(criteria_json);
  return outcome;
}

}  // namespace

AdviceCheckLadder CheckAdviceOnMembers(const AdviceCheckRequest& r, const WorkflowLog& log) {
  const Json ensemble =
      WithStates(ReadEnsembleJson(r.study_file), r.states, r.states_name, r.study_file);
  const std::filesystem::path scene_file =
      (std::filesystem::path(r.study_file).parent_path() / ensemble.at("scene").get<std::string>())
          .lexically_normal();
  const Json scene_json = ReadJsonFile(scene_file);
  const Scene scene = ParseScene(scene_json, scene_file, r.access);
  const Json criteria_json = ReadJsonFile(r.criteria_file);
  CriteriaTolerances tolerances;
  AdviceCheckLadder ladder;
  ladder.advice = AdviseScene(scene, CriteriaFromJson(criteria_json, r.criteria_file, &tolerances));
  const SceneAdvice& advice = ladder.advice;
  // A file `record` names is read before the ladder runs: a bad one stops nothing computed.
  if (!r.record.empty() && std::filesystem::exists(r.record))
    ParseAdviceCheckOutcomes(ReadJsonFile(r.record), r.record);
  ladder.outcome = NamedOutcome(ensemble, scene_file.string(), SceneDigest(scene_json, scene),
                                r.criteria_file, criteria_json);
  CheckLowestRung(advice, LadderFactors(kFirstLadderRungs).front(), r.criteria_file, criteria_json);
  log.Say(fmt::format("advice for scene {} from {}: dt = {:g} dt_sharp, R_ftrunc {}", scene.name,
                      r.criteria_file, advice.dt_ratio, AdvisedTruncations(advice)));
  for (const std::string& w : advice.warnings) log.Say("  warning  " + w);
  for (int rungs = kFirstLadderRungs;; ++rungs) {
    const std::vector<double> factors = LadderFactors(rungs);
    const AdviceCheckRecord record{factors, kAdvisedRung, r.sizing.quantile, r.sizing.tolerance};
    const Json study = AdviceCheckStudy(ensemble, r.study_file, scene_json, scene, advice, record,
                                        r.members, r.window_s);
    if (!r.write_study.empty()) {
      WriteFileAtomically(r.write_study, study.dump(2) + "\n");
      log.Say(fmt::format(
          "ladder study written to {} ({} rungs): run it (e.g. mpirun -np N shockmap study run "
          "{} --db {}), then check-advice again with the same flags",
          r.write_study, rungs, r.write_study, r.database_path));
      return ladder;
    }
    log.Say(fmt::format("ladder: x {:.4g} of the advised truncations", fmt::join(factors, ", x ")));
    const LadderRun run = RunLadder(r, study, log, ladder.outcome);
    if (run.summary.stop_signal != 0) {
      ladder.stop_signal = run.summary.stop_signal;
      ladder.members_computed = run.summary.points_computed;
      ladder.members_to_compute = run.summary.points_to_compute;
      return ladder;
    }
    AdviceCheck check = CheckAdvice(run.sizing, study.at("settings"), factors, kAdvisedRung);
    const bool may_refine =
        rungs < r.max_rungs && RungFits(advice, LadderFactors(rungs + 1).back());
    if (check.converged || check.undecided || !may_refine) {
      ladder.check = std::move(check);
      return ladder;
    }
  }
}

void RecordAdviceCheck(const AdviceCheckRequest& r, const AdviceCheckLadder& ladder,
                       const WorkflowLog& log) {
  const AdviceCheck& check = *ladder.check;
  if (!check.converged || check.undecided) {
    log.Say(fmt::format("  not recorded in {}: the check is {}", r.record,
                        check.undecided ? "undecided" : "not converged"));
    return;
  }
  AdviceCheckOutcome outcome = ladder.outcome;
  outcome.quantile = r.sizing.quantile;
  outcome.tolerance = r.sizing.tolerance;
  outcome.pairs = static_cast<int>(check.families.size());
  outcome.held = static_cast<int>(std::ranges::count_if(check.families, [&](const auto& family) {
    return AdviceHolds(check, family).value_or(false);
  }));
  outcome.verdict = AdviceVerdict(check, r.sizing.quantile);
  // Read again: another check may have recorded its outcome while this ladder ran.
  std::vector<AdviceCheckOutcome> outcomes;
  if (std::filesystem::exists(r.record))
    outcomes = ParseAdviceCheckOutcomes(ReadJsonFile(r.record), r.record);
  log.Say(fmt::format("  outcome recorded in {}: the advice held at {} of {} pairs", r.record,
                      outcome.held, outcome.pairs));
  RecordOutcome(outcomes, std::move(outcome));
  WriteFileAtomically(r.record, AdviceCheckOutcomesJson(outcomes).dump(2) + "\n");
}

}  // namespace shockmap

#include "app/check_advice_command.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/exit_codes.h"
#include "app/flag_checks.h"
#include "app/shared_data.h"
#include "core/input_error.h"
#include "db/ensemble_members.h"
#include "db/schema.h"
#include "db/study_database.h"
#include "engine/stop_request.h"
#include "engine/study_run.h"
#include "formats/advice_check_outcomes.h"
#include "formats/advice_check_study.h"
#include "formats/ensemble_study_spec.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/scene_file.h"
#include "formats/study_file.h"
#include "formats/table_output.h"
#include "validation/scene_advice.h"
#include "views/advice_check.h"
#include "views/criteria_report.h"
#include "views/ensemble_sizing.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

struct CheckAdviceFlags {
  std::string study_file;
  std::string criteria = kSceneCriteria;
  std::string database_path = kDefaultDatabasePath;
  int members = 0;                  // 0: the study file's.
  double window_s = 0.0;            // 0: the study file's.
  std::vector<std::string> states;  // Empty: every clearance state of the study file.
  int jobs = 0;
  int max_rungs = 6;
  SizingOptions options;
  std::string write_study;
  std::string record;
  bool quiet = false;
  SceneFileAccess access;
};

// The rung at factor 1 in LadderFactors' order (1/3 first).
constexpr int kAdvisedRung = 1;
// The first ladder: 1/3, 1 and 3 times the advised truncations (the advice holds where the
// rung above it agrees; finer rungs are added only while a family has not converged).
constexpr int kFirstRungs = 3;

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
// Throws InputError naming --states, the name and the study's states when one is not there.
// A state whose entry is malformed has no name here; the study file's parser names its fault.
Json WithStates(Json ensemble, const std::vector<std::string>& names, const std::string& file) {
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
          fmt::format("--states: \"{}\" is not a clearance state of {} (it has: {})", name, file,
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

// A ladder's sizing statistics and what its members were: their number per state and rung,
// their window and the clearance states.
struct LadderRun {
  EnsembleSizing sizing;
  int members = 0;
  double window_s = 0.0;
  std::vector<std::string> states;
};

// Runs the ladder's study (only the members not stored yet) and reads its sizing statistics.
LadderRun RunLadder(const CheckAdviceFlags& f, const Json& study) {
  const StudyFile parsed = ParseStudyFile(study, f.study_file, f.access);
  StudyRunOptions options;
  options.database_path = f.database_path;
  options.jobs = f.jobs;
  options.progress = !f.quiet;
  const StudyRunSummary s = RunStudy(parsed, options);
  if (s.stop_signal != 0) {
    fmt::print(stderr,
               "shockmap: {} received: {} of the {} members to compute are stored; run "
               "check-advice again to resume\n",
               SignalName(s.stop_signal), s.points_computed, s.points_to_compute);
    throw CLI::RuntimeError(kExitSignalBase + s.stop_signal);
  }
  fmt::print("  {} members in the ladder, {} computed now\n", s.points_in_study, s.points_computed);
  Connection db(f.database_path, Connection::Mode::kReadOnly);
  CheckSchema(db);
  const std::string name = study.at("name");
  const auto& spec = std::get<EnsembleStudySpec>(parsed);
  LadderRun run{SizeEnsemble(CurrentMembers(ReadEnsemble(db, name)), name, f.options),
                spec.members,
                spec.window_s,
                {}};
  for (const ClearanceState& state : spec.states) run.states.push_back(state.name);
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

// Adds the check's outcome to the file --record names (created when absent), for `advise`:
// only a decided check is recorded.
void Record(const CheckAdviceFlags& f, const AdviceCheck& check, const LadderRun& run,
            AdviceCheckOutcome outcome) {
  if (!check.converged || check.undecided) {
    fmt::print("  not recorded in {}: the check is {}\n", f.record,
               check.undecided ? "undecided" : "not converged");
    return;
  }
  outcome.states = run.states;
  outcome.members = run.members;
  outcome.window_s = run.window_s;
  outcome.quantile = f.options.quantile;
  outcome.tolerance = f.options.tolerance;
  outcome.pairs = static_cast<int>(check.families.size());
  outcome.held = static_cast<int>(std::ranges::count_if(check.families, [&](const auto& family) {
    return AdviceHolds(check, family).value_or(false);
  }));
  outcome.verdict = AdviceVerdict(check, f.options.quantile);
  // Read again: another check may have recorded its outcome while this ladder ran.
  std::vector<AdviceCheckOutcome> outcomes;
  if (std::filesystem::exists(f.record))
    outcomes = ParseAdviceCheckOutcomes(ReadJsonFile(f.record), f.record);
  fmt::print("  outcome recorded in {}: the advice held at {} of {} pairs\n", f.record,
             outcome.held, outcome.pairs);
  RecordOutcome(outcomes, std::move(outcome));
  WriteFileAtomically(f.record, AdviceCheckOutcomesJson(outcomes).dump(2) + "\n");
}

void PrintCheck(const AdviceCheck& check, const SizingOptions& options) {
  fmt::print("\n{}\n\n", AdviceVerdict(check, options.quantile));
  WriteTable(AdviceCheckTable(check), TableFormat::kTable, std::cout);
  std::string cpu;
  for (std::size_t k = 0; k < check.factors.size(); ++k) {
    cpu += fmt::format("{}x {:.4g}: {:.3g} s", k ? ", " : "", check.factors[k],
                       check.cpu_s_per_member[k]);
  }
  fmt::print("  CPU per member by rung: {}\n", cpu);
}

void Check(const CheckAdviceFlags& f, const std::string& criteria_file) {
  const Json ensemble = WithStates(ReadEnsembleJson(f.study_file), f.states, f.study_file);
  const std::filesystem::path scene_file =
      (std::filesystem::path(f.study_file).parent_path() / ensemble.at("scene").get<std::string>())
          .lexically_normal();
  const Json scene_json = ReadJsonFile(scene_file);
  const Scene scene = ParseScene(scene_json, scene_file, f.access);
  const Json criteria_json = ReadJsonFile(criteria_file);
  CriteriaTolerances tolerances;
  const SceneAdvice advice =
      AdviseScene(scene, CriteriaFromJson(criteria_json, criteria_file, &tolerances));
  // A file --record names is read before the ladder runs: a bad one stops nothing computed.
  if (!f.record.empty() && std::filesystem::exists(f.record))
    ParseAdviceCheckOutcomes(ReadJsonFile(f.record), f.record);
  const AdviceCheckOutcome outcome = NamedOutcome(
      ensemble, scene_file.string(), SceneDigest(scene_json, scene), criteria_file, criteria_json);
  CheckLowestRung(advice, LadderFactors(kFirstRungs).front(), criteria_file, criteria_json);
  fmt::print("advice for scene {} from {}: dt = {:g} dt_sharp, R_ftrunc {}\n", scene.name,
             criteria_file, advice.dt_ratio, AdvisedTruncations(advice));
  for (const std::string& w : advice.warnings) fmt::print("  warning  {}\n", w);
  InstallStopHandlers();
  for (int rungs = kFirstRungs;; ++rungs) {
    const std::vector<double> factors = LadderFactors(rungs);
    const AdviceCheckRecord record{factors, kAdvisedRung, f.options.quantile, f.options.tolerance};
    const Json study = AdviceCheckStudy(ensemble, f.study_file, scene_json, scene, advice, record,
                                        f.members, f.window_s);
    if (!f.write_study.empty()) {
      WriteFileAtomically(f.write_study, study.dump(2) + "\n");
      fmt::print(
          "ladder study written to {} ({} rungs): run it (e.g. mpirun -np N shockmap study run "
          "{} --db {}), then check-advice again with the same flags\n",
          f.write_study, rungs, f.write_study, f.database_path);
      return;
    }
    fmt::print("ladder: x {:.4g} of the advised truncations\n", fmt::join(factors, ", x "));
    const LadderRun run = RunLadder(f, study);
    const AdviceCheck check = CheckAdvice(run.sizing, study.at("settings"), factors, kAdvisedRung);
    const bool may_refine =
        rungs < f.max_rungs && RungFits(advice, LadderFactors(rungs + 1).back());
    if (check.converged || check.undecided || !may_refine) {
      PrintCheck(check, f.options);
      if (!f.record.empty()) Record(f, check, run, outcome);
      return;
    }
  }
}

}  // namespace

void AddCheckAdviceCommand(CLI::App& app) {
  auto flags = std::make_shared<CheckAdviceFlags>();
  CLI::App* cmd = app.add_subcommand(
      "check-advice",
      "Check the advice for an ensemble study's scene on its members: the ensemble run at the "
      "advised truncations and dt, at a third of them and at 3, 9, ... times until each zone "
      "family's sizing quantile stops moving, and the verdict per clearance state and family");
  cmd->add_option("STUDY", flags->study_file, "ensemble study file (\"kind\": \"scene_ensemble\")")
      ->required()
      ->type_name("FILE");
  AddDatabaseFlag(cmd, flags->database_path);
  CLI::Option* criteria =
      cmd->add_option("--criteria", flags->criteria,
                      "criteria JSON written by `criteria derive --out` (looked up in the working "
                      "folder, then in the shared data installed with shockmap)")
          ->capture_default_str();
  cmd->add_option("--members", flags->members,
                  "members per clearance state and rung (default: the study file's)")
      ->check(WholeNumberIn(1, 100000));
  cmd->add_option("--window-s", flags->window_s,
                  "simulated seconds of every member, from the start (default: the study file's "
                  "window): the largest forces of the shock's first impacts at a fraction of the "
                  "cost")
      ->check(FiniteIn(0.0, true, 1e4));
  cmd->add_option("--states", flags->states,
                  "the clearance states to check, by name (default: every state of the study)")
      ->delimiter(',');
  cmd->add_option("--jobs", flags->jobs, "worker threads (default: number of cores)")
      ->check(WholeNumberIn(1, 1024));
  cmd->add_option("--quantile", flags->options.quantile, "the sizing quantile, in (0, 1)")
      ->capture_default_str()
      ->check(StrictlyBetween(0.0, 1.0));
  cmd->add_option("--tolerance", flags->options.tolerance,
                  "two rungs agree where their intervals of the sizing quantile, widened by this "
                  "fraction of the finer estimate, overlap")
      ->capture_default_str()
      ->check(FiniteIn(0.0, false, 1.0));
  cmd->add_option("--max-rungs", flags->max_rungs,
                  "rungs at most (1/3, 1, 3, 9, ... times the advised truncations)")
      ->capture_default_str()
      ->check(WholeNumberIn(kFirstRungs, 12));
  cmd->add_option("--write-study", flags->write_study,
                  "write the ladder's study file here instead of running it (to run it under "
                  "MPI with `study run`)");
  cmd->add_option("--record", flags->record,
                  "add the check's outcome to this outcomes file (created when absent), which "
                  "`advise --checks` reads for this scene and criteria")
      ->type_name("FILE");
  cmd->add_flag("--quiet", flags->quiet, "no progress on stderr");
  AddAllowPathFlag(cmd, flags->access);
  cmd->callback([flags, criteria] {
    Check(*flags,
          criteria->count() > 0 ? flags->criteria : DefaultDataFile(flags->criteria, "--criteria"));
  });
}

}  // namespace shockmap

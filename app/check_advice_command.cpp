#include "app/check_advice_command.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>

#include "app/exit_codes.h"
#include "app/flag_checks.h"
#include "app/shared_data.h"
#include "db/study_database.h"
#include "engine/stop_request.h"
#include "formats/table_output.h"
#include "views/advice_check_text.h"
#include "workflows/advice_check_ladder.h"

namespace shockmap {
namespace {

struct CheckAdviceFlags {
  AdviceCheckRequest request;
  bool quiet = false;
};

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

void Check(CheckAdviceFlags& f) {
  f.request.progress_lines = !f.quiet;
  WorkflowLog log;
  log.say = [](const std::string& line) { fmt::print("{}\n", line); };
  InstallStopHandlers();
  const AdviceCheckLadder ladder = CheckAdviceOnMembers(f.request, log);
  if (ladder.stop_signal != 0) {
    fmt::print(stderr,
               "shockmap: {} received: {} of the {} members to compute are stored; run "
               "check-advice again to resume\n",
               SignalName(ladder.stop_signal), ladder.members_computed, ladder.members_to_compute);
    throw CLI::RuntimeError(kExitSignalBase + ladder.stop_signal);
  }
  if (!ladder.check) return;  // The ladder's study was written.
  PrintCheck(*ladder.check, f.request.sizing);
  if (!f.request.record.empty()) RecordAdviceCheck(f.request, ladder, log);
}

}  // namespace

void AddCheckAdviceCommand(CLI::App& app) {
  auto flags = std::make_shared<CheckAdviceFlags>();
  CLI::App* cmd = app.add_subcommand(
      "check-advice",
      "Check the advice for an ensemble study's scene on its members: the ensemble run at the "
      "advised truncations and dt, at a third of them and at 3, 9, ... times until each zone "
      "family's sizing quantile stops moving, and the verdict per clearance state and family");
  cmd->add_option("STUDY", flags->request.study_file,
                  "ensemble study file (\"kind\": \"scene_ensemble\")")
      ->required()
      ->type_name("FILE");
  AddDatabaseFlag(cmd, flags->request.database_path);
  CLI::Option* criteria =
      cmd->add_option("--criteria", flags->request.criteria_file,
                      "criteria JSON written by `criteria derive --out` (looked up in the working "
                      "folder, then in the shared data installed with shockmap)")
          ->capture_default_str();
  cmd->add_option("--members", flags->request.members,
                  "members per clearance state and rung (default: the study file's)")
      ->check(WholeNumberIn(1, kMaxLadderMembers));
  cmd->add_option("--window-s", flags->request.window_s,
                  "simulated seconds of every member, from the start (default: the study file's "
                  "window): the largest forces of the shock's first impacts at a fraction of the "
                  "cost")
      ->check(FiniteIn(0.0, true, kMaxLadderWindowS));
  cmd->add_option("--states", flags->request.states,
                  "the clearance states to check, by name (default: every state of the study)")
      ->delimiter(',');
  cmd->add_option("--jobs", flags->request.jobs, "worker threads (default: number of cores)")
      ->check(WholeNumberIn(1, 1024));
  cmd->add_option("--quantile", flags->request.sizing.quantile, "the sizing quantile, in (0, 1)")
      ->capture_default_str()
      ->check(StrictlyBetween(0.0, 1.0));
  cmd->add_option("--tolerance", flags->request.sizing.tolerance,
                  "two rungs agree where their intervals of the sizing quantile, widened by this "
                  "fraction of the finer estimate, overlap")
      ->capture_default_str()
      ->check(FiniteIn(0.0, false, 1.0));
  cmd->add_option("--max-rungs", flags->request.max_rungs,
                  "rungs at most (1/3, 1, 3, 9, ... times the advised truncations)")
      ->capture_default_str()
      ->check(WholeNumberIn(kFirstLadderRungs, kMaxLadderRungs));
  cmd->add_option("--write-study", flags->request.write_study,
                  "write the ladder's study file here instead of running it (to run it under "
                  "MPI with `study run`)");
  cmd->add_option("--record", flags->request.record,
                  "add the check's outcome to this outcomes file (created when absent), which "
                  "`advise --checks` reads for this scene and criteria")
      ->type_name("FILE");
  cmd->add_flag("--quiet", flags->quiet, "no progress on stderr");
  AddAllowPathFlag(cmd, flags->request.access);
  cmd->callback([flags, criteria] {
    if (criteria->count() == 0)
      flags->request.criteria_file = DefaultDataFile(flags->request.criteria_file, "--criteria");
    Check(*flags);
  });
}

}  // namespace shockmap

// shockmap: maps where a truncated modal basis with explicit integration gives contact forces
// that can be trusted. Exit codes: app/exit_codes.h.

#include <CLI/CLI.hpp>

#include "app/check_advice_command.h"
#include "app/compare_command.h"
#include "app/completion_command.h"
#include "app/criteria_command.h"
#include "app/diff_command.h"
#include "app/error_report.h"
#include "app/exit_codes.h"
#include "app/export_command.h"
#include "app/map_command.h"
#include "app/report_command.h"
#include "app/simulate_command.h"
#include "app/sizing_command.h"
#include "app/structure_command.h"
#include "app/study_command.h"
#include "app/view_commands.h"
#include "engine/provenance.h"
#include "formats/output_file.h"
#include "formats/signal_cleanup.h"

int main(int argc, char** argv) {
  shockmap::InstallSignalCleanup();
  CLI::App app{
      "shockmap: validity maps of modal reduction with explicit integration for "
      "structures with clearances"};
  app.require_subcommand(1);
  app.set_version_flag("--version", shockmap::VersionLine(),
                       "Print the release, code version, compiler and build type, and exit");
  shockmap::AddCompareCommand(app);
  shockmap::AddStudyCommand(app);
  shockmap::AddQueryCommand(app);
  shockmap::AddCriteriaCommand(app);
  shockmap::AddMapCommand(app);
  shockmap::AddDiffCommand(app);
  shockmap::AddSimulateCommand(app);
  shockmap::AddSizingCommand(app);
  shockmap::AddViewCommands(app);
  shockmap::AddCheckAdviceCommand(app);
  shockmap::AddReportCommand(app);
  shockmap::AddExportCommand(app);
  shockmap::AddStructureCommand(app);
  shockmap::AddCompletionCommand(app);
  try {
    app.parse(argc, argv);
    shockmap::CheckStandardOutput(true);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // A verdict already printed (criteria check, a signal).
  } catch (const CLI::ParseError& e) {
    return shockmap::ReportParseError(app, e);
  } catch (...) {
    return shockmap::ReportFailure(std::current_exception());
  }
  return shockmap::kExitSuccess;
}

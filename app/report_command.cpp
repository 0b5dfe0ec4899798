#include "app/report_command.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>

#include "app/flag_checks.h"
#include "app/thresholds.h"
#include "db/study_database.h"
#include "workflows/study_report.h"

namespace shockmap {
namespace {

struct ReportFlags {
  std::string database_path = kDefaultDatabasePath;
  std::string study;
  ThresholdFlags thresholds;
  std::string out;
};

// Lines on stdout, warnings on stderr, the Fig. 3 counter redrawn in place on a terminal.
WorkflowLog PrintedLog() {
  WorkflowLog log;
  log.say = [](const std::string& line) {
    fmt::print("{}\n", line);
    std::fflush(stdout);
  };
  log.warn = [](const std::string& line) { std::cerr << "shockmap: warning: " << line << '\n'; };
  if (::isatty(STDOUT_FILENO) != 0) {
    log.progress = [](std::string_view phase, double done, double total) {
      fmt::print("  {} ({}/{})\r", phase, static_cast<long long>(done),
                 static_cast<long long>(total));
      std::fflush(stdout);
    };
  }
  return log;
}

void Run(const ReportFlags& f) {
  const std::filesystem::path page = WriteStudyReport(
      {f.database_path, f.study, f.thresholds.given, f.out, "--out"}, PrintedLog());
  std::cout << "report written to " << page.string() << '\n';
}

}  // namespace

void AddReportCommand(CLI::App& app) {
  auto flags = std::make_shared<ReportFlags>();
  CLI::App* report = app.add_subcommand(
      "report",
      "HTML report of a stored study (index.html): sortable tables, interactive validity maps, "
      "a page per point with its Fig. 3, Fig. 4, criteria, cost front, contact-force maps of "
      "scene studies, sizing tables and pictures of ensemble studies, provenance");
  report->add_option("STUDY", flags->study, "study name (default: the database's only study)");
  AddDatabaseFlag(report, flags->database_path);
  AddThresholdFlags(report, flags->thresholds);
  report->add_option("--out", flags->out, "directory for index.html, its figures and point pages")
      ->required();
  report->callback([flags] { Run(*flags); });
}

}  // namespace shockmap

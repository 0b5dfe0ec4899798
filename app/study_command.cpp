#include "app/study_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <variant>

#include "app/error_report.h"
#include "app/exit_codes.h"
#include "app/flag_checks.h"
#include "db/study_queries.h"
#include "engine/mpi_job.h"
#include "engine/stop_request.h"
#include "engine/study_run.h"
#include "formats/counted.h"
#include "formats/output_file.h"
#include "formats/table_output.h"
#include "specs/study_file.h"
#include "views/setting_legend.h"

namespace shockmap {
namespace {

// Bounds of `shockmap query` unless the user lifts them (0) or sets others.
constexpr std::int64_t kDefaultMaxRows = 1'000'000;
constexpr double kDefaultTimeout_s = 60.0;

// The query writer, with standard output checked after every row so that a failed write
// stops the statement.
class CheckedStdoutSink : public TableSink {
 public:
  explicit CheckedStdoutSink(TableWriter& writer) : writer_(writer) {}
  void Columns(const std::vector<std::string>& names) override {
    writer_.Columns(names);
    CheckStandardOutput(false);
  }
  void Row(const std::vector<TableCell>& row) override {
    writer_.Row(row);
    CheckStandardOutput(false);
  }

 private:
  TableWriter& writer_;
};

struct StudyFlags {
  std::string spec_path;
  std::string study;
  StudyRunOptions run;
  double rank_timeout_s = kDefaultRankTimeoutS;
  bool quiet = false;
  std::string sql;
  std::string format = "table";
  QueryLimits limits{kDefaultMaxRows, kDefaultTimeout_s};
  SceneFileAccess access;
};

// A rerun with nothing left to compute says so, and how to compute the failed points again.
void PrintEveryPointStored(const StudyRunSummary& s, const StudyRunOptions& options) {
  fmt::print("study {}: all {} already stored in {}; nothing to compute\n", s.study,
             Counted(static_cast<long long>(s.points_in_study), "point"), options.database_path);
  if (!options.retry_failed) {
    fmt::print(
        "  `shockmap study status {}` shows their outcomes; --retry-failed computes the "
        "failed ones again\n",
        s.study);
  }
}

void PrintSummary(const StudyRunSummary& s, const StudyRunOptions& options) {
  if (s.points_to_compute == 0 && s.stop_signal == 0) return PrintEveryPointStored(s, options);
  const double rate = s.point_wall_s > 0 ? s.points_computed / s.point_wall_s : 0.0;
  const std::string workers = s.worker_ranks > 0
                                  ? fmt::format("{} x {}", Counted(s.worker_ranks, "worker rank"),
                                                Counted(s.jobs / s.worker_ranks, "thread"))
                                  : Counted(s.jobs, "job");
  fmt::print("study {}: {} in the study, {} computed now ({})\n", s.study,
             Counted(static_cast<long long>(s.points_in_study), "point"), s.points_computed,
             workers);
  fmt::print("  outcomes     {}\n", OutcomeCounts(s));
  fmt::print(
      "  references   {} computed, {} reused from the database ({} unconverged, {} failed "
      "of those computed)\n",
      s.references_computed, s.references_reused, s.references_unconverged, s.references_failed);
  if (!s.previous_run.empty()) fmt::print("  previous     {}\n", s.previous_run);
  if (s.points_reclaimed > 0) {
    fmt::print("  resumed      {} left running by a stopped run\n",
               Counted(s.points_reclaimed, "point"));
  }
  fmt::print(
      "  wall time    {:.2f} s: references {:.2f} s ({:.0f} %), points {:.2f} s ({:.1f} "
      "points/s)\n",
      s.wall_s, s.reference_wall_s, s.wall_s > 0 ? 100.0 * s.reference_wall_s / s.wall_s : 0.0,
      s.point_wall_s, rate);
  if (s.worker_ranks > 0) {
    const MessageTotals& m = s.messages;
    fmt::print(
        "  messages     {} tasks {:.3f} MB (largest {:.0f} B), {} results {:.3f} MB (largest "
        "{:.0f} "
        "B)\n",
        m.tasks, m.task_bytes / 1e6, m.largest_task, m.results, m.result_bytes / 1e6,
        m.largest_result);
  }
  fmt::print("  database     {}\n", options.database_path);
}

// Exit code of a run stopped by a signal: 128 + the signal, as a shell reports it.
struct Interrupted : CLI::RuntimeError {
  explicit Interrupted(int signal) : CLI::RuntimeError(kExitSignalBase + signal) {}
};

// A worker rank of an MPI job computes what rank 0 hands out. When it cannot read the study
// file, the first task it is given ends the job with the reason (rank 0 usually fails alike).
void Serve(const StudyFlags& f, RemoteWorkers& job) {
  try {
    ServeStudy(ReadStudyFile(f.spec_path), job);
  } catch (const std::exception& e) {
    const std::string why = f.spec_path + ": " + e.what();
    job.Serve([why](std::string_view) -> std::string { throw std::runtime_error(why); });
  }
}

// Rank 0's run (or the only process's): the study, its summary, and what a signal left.
void RunOnRankZero(const StudyFlags& f, StudyRunOptions options) {
  // The whole file, and every point's scene, is checked before the database is touched.
  const StudyFile study = ReadStudyFile(f.spec_path, f.access);
  if (const auto* canonical = std::get_if<StudySpec>(&study)) {
    if (const auto warning = WindowWarning(*canonical)) {
      fmt::print(stderr, "shockmap: warning: {}\n", *warning);
    }
  }
  InstallStopHandlers();
  StudyRunSummary s;
  try {
    s = RunStudy(study, options);
  } catch (const NoWorkerRankLeft& e) {
    fmt::print(stderr,
               "shockmap: {}; the run is interrupted, the points stored are kept and the others "
               "are pending: run the study again to resume\n",
               e.what());
    throw CLI::RuntimeError(kExitFailure);
  }
  PrintSummary(s, options);
  if (s.stop_signal != 0) {
    for (const std::string& task : s.abandoned) {
      fmt::print(stderr, "shockmap: no answer for {}; it is pending again\n", task);
    }
    fmt::print(stderr,
               "shockmap: {} received: {} of the {} points to compute are stored, the rest are "
               "pending; run the study again to resume\n",
               SignalName(s.stop_signal), s.points_computed, s.points_to_compute);
    std::fflush(stdout);
    throw Interrupted(s.stop_signal);
  }
}

void Run(const StudyFlags& f) {
  StudyRunOptions options = f.run;
  options.progress = !f.quiet;
  // Under MPI, --jobs is the threads of each worker rank.
  const std::unique_ptr<RemoteWorkers> job =
      JoinMpiJob(f.run.jobs > 0 ? f.run.jobs : 1, f.rank_timeout_s);
  if (!job) return RunOnRankZero(f, options);
  if (job->Rank() != 0) return Serve(f, *job);
  options.jobs = std::max(1, f.run.jobs);
  if (job->WorkerRanks() > 0) options.remote = job.get();
  try {
    RunOnRankZero(f, options);
  } catch (...) {
    // Reported now, with its exit code for the job: a job that lost a rank ends in MPI_Abort
    // when `job` is destroyed, before main could report it.
    const int exit_code = ReportFailure(std::current_exception());
    job->SetExitCode(exit_code);
    throw CLI::RuntimeError(exit_code);
  }
}

// Keeps the rows of `table` whose column `study` is `study` (all when `study` is empty).
void KeepStudy(Table& table, const std::string& study) {
  if (study.empty()) return;
  std::vector<std::vector<TableCell>> kept;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    if (NamedRow(table, i)["study"] == TableCell(study)) kept.push_back(std::move(table.rows[i]));
  }
  table.rows = std::move(kept);
}

// Every study's points by status, then the points of each kind that breaks them down (ensemble
// members by clearance state and setting, each setting numbered and listed beneath), then where
// they were computed.
void Status(const StudyFlags& f) {
  Table r = StudyProgress(f.run.database_path);
  KeepStudy(r, f.study);
  if (!f.study.empty() && r.rows.empty()) {
    throw InputError("no study named \"" + f.study + "\" in " + f.run.database_path);
  }
  WriteTable(r, TableFormat::kTable, std::cout);
  for (StudyBreakdown& b : StudyProgressBreakdowns(f.run.database_path)) {
    KeepStudy(b.progress, f.study);
    if (b.progress.rows.empty()) continue;
    const LabelledSettings labelled = LabelSettings(std::move(b.progress));
    std::string by;  // The columns after "study".
    for (std::size_t i = 1; i <= b.table->progress_by.size(); ++i) {
      by += (by.empty() ? "" : " and ") + labelled.table.columns[i];
    }
    std::cout << "\n" << b.table->name << " by " << by << ":\n";
    WriteTable(labelled.table, TableFormat::kTable, std::cout);
    if (!labelled.legend.empty()) std::cout << "\n" << labelled.legend;
  }
  Table origins = StudyOrigins(f.run.database_path);
  KeepStudy(origins, f.study);
  std::cout << "\ncomputed on (host, rank; each point's in the results views):\n";
  WriteTable(origins, TableFormat::kTable, std::cout);
  if (const auto writer = LiveWriter(f.run.database_path)) {
    std::cout << "being written by " << *writer << "; its running points are held by it\n";
  }
}

// Rows are printed as SQLite produces them; a limit reached closes the output, then fails.
void Query(const StudyFlags& f) {
  TableWriter writer(*TableFormatFromString(f.format), std::cout);
  CheckedStdoutSink sink(writer);
  try {
    StreamReadOnlyQuery(f.run.database_path, f.sql, {}, f.limits, sink);
  } catch (const QueryLimitReached& e) {
    writer.Finish();  // The rows printed stay a whole table, CSV or JSON array.
    throw InputError(std::string(e.what()) +
                     "; --max-rows N and --timeout-s S raise the limits, 0 lifts them");
  }
  writer.Finish();
}

}  // namespace

void AddStudyCommand(CLI::App& app) {
  auto flags = std::make_shared<StudyFlags>();
  CLI::App* study = app.add_subcommand("study", "Run studies into the database and follow them");
  study->require_subcommand(1);

  CLI::App* run = study->add_subcommand(
      "run", "Run every missing point of a study file into the database (resumable)");
  run->add_option("STUDY", flags->spec_path, "study file (JSON)")->type_name("FILE")->required();
  AddDatabaseFlag(run, flags->run.database_path);
  run->add_option("--jobs", flags->run.jobs,
                  "worker threads (default: number of cores; under MPI: per worker rank, "
                  "default 1)")
      ->check(WholeNumberIn(1, 1024));
  run->add_flag("--retry-failed", flags->run.retry_failed, "compute failed points again");
  run->add_option("--rank-timeout-s", flags->rank_timeout_s,
                  "under MPI: seconds a worker rank may send nothing (not even its heartbeat, "
                  "every 0.5 s) before rank 0 gives its tasks to the other ranks")
      ->capture_default_str()
      ->check(FiniteAbove(2.0, false));
  run->add_flag("--quiet", flags->quiet, "no progress on stderr");
  AddAllowPathFlag(run, flags->access);
  run->callback([flags] { Run(*flags); });

  CLI::App* status = study->add_subcommand("status", "Progress and outcomes of the studies");
  status->add_option("STUDY", flags->study, "one study's name (default: all)");
  AddDatabaseFlag(status, flags->run.database_path);
  status->callback([flags] { Status(*flags); });
}

void AddQueryCommand(CLI::App& app) {
  auto flags = std::make_shared<StudyFlags>();
  CLI::App* query =
      app.add_subcommand("query",
                         "Run one read-only SQL statement on the database (the views `results` and "
                         "`scene_results` join parameters, scores and references)");
  query->add_option("SQL", flags->sql, "one SELECT (or other read-only) statement")->required();
  AddDatabaseFlag(query, flags->run.database_path);
  query->add_option("--format", flags->format, "output format")
      ->capture_default_str()
      ->check(CLI::IsMember({"table", "csv", "json"}));
  query
      ->add_option("--max-rows", flags->limits.max_rows,
                   "stop with an error when the result has more rows (0: no limit)")
      ->capture_default_str()
      ->check(FiniteAbove(0.0, false));
  query
      ->add_option("--timeout-s", flags->limits.timeout_s,
                   "stop with an error when the statement runs longer, in seconds of wall time "
                   "(0: no limit)")
      ->capture_default_str()
      ->check(FiniteAbove(0.0, false));
  query->callback([flags] { Query(*flags); });
}

}  // namespace shockmap

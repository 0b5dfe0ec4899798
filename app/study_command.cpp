#include "app/study_command.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "app/flag_checks.h"
#include "db/read_only_query.h"
#include "db/study_database.h"
#include "engine/scene_study_runner.h"
#include "engine/study_runner.h"
#include "formats/json_reader.h"
#include "views/query_output.h"

namespace shockmap {
namespace {

struct StudyFlags {
  std::string spec_path;
  std::string study;
  StudyRunOptions run;
  bool quiet = false;
  std::string sql;
  std::string format = "table";
  SceneFileAccess access;
};

void Run(const StudyFlags& f) {
  StudyRunOptions options = f.run;
  options.progress = !f.quiet;
  // The whole file is checked before the database is touched.
  const nlohmann::json json = ReadJsonFile(f.spec_path);
  std::string name;
  StudyRunSummary s;
  if (IsSceneStudy(json)) {
    const SceneStudySpec spec = ParseSceneStudySpec(json, f.spec_path, f.access);
    name = spec.name;
    s = RunSceneStudy(spec, options);
  } else {
    const StudySpec spec = ParseStudySpec(json, f.spec_path);
    name = spec.name;
    s = RunStudy(spec, options);
  }
  const double rate = s.point_wall_s > 0 ? s.points_computed / s.point_wall_s : 0.0;
  fmt::print("study {}: {} points in the study, {} computed now ({} jobs)\n", name,
             s.points_in_study, s.points_computed, s.jobs);
  fmt::print("  outcomes     ok {}, diverged {}, failed {}, reference_unconverged {}\n", s.ok,
             s.diverged, s.failed, s.reference_unconverged);
  fmt::print("  references   {} computed, {} reused from the database\n", s.references_computed,
             s.references_reused);
  if (s.points_reclaimed > 0) {
    fmt::print("  resumed      {} points left running by a stopped run\n", s.points_reclaimed);
  }
  fmt::print(
      "  wall time    {:.2f} s: references {:.2f} s ({:.0f} %), points {:.2f} s ({:.1f} "
      "points/s)\n",
      s.wall_s, s.reference_wall_s, s.wall_s > 0 ? 100.0 * s.reference_wall_s / s.wall_s : 0.0,
      s.point_wall_s, rate);
  fmt::print("  database     {}\n", options.database_path);
}

void Status(const StudyFlags& f) {
  const char* sql =
      "SELECT st.name AS study, count(*) AS points, "
      "sum(p.status = 'ok') AS ok, sum(p.status = 'diverged') AS diverged, "
      "sum(p.status = 'failed') AS failed, "
      "sum(p.status = 'reference_unconverged') AS reference_unconverged, "
      "sum(p.status = 'pending') AS pending, sum(p.status = 'running') AS running, "
      "max(p.updated_utc) AS last_update "
      "FROM (SELECT study_id, status, updated_utc FROM points UNION ALL "
      "SELECT study_id, status, updated_utc FROM scene_points) p "
      "JOIN studies st USING (study_id) GROUP BY st.name ORDER BY st.name";
  QueryResult r = RunReadOnlyQuery(f.run.database_path, sql);
  if (!f.study.empty()) {
    std::erase_if(r.rows,
                  [&](const auto& row) { return std::get<std::string>(row[0]) != f.study; });
    if (r.rows.empty()) {
      throw InputError("no study named \"" + f.study + "\" in " + f.run.database_path);
    }
  }
  WriteQueryResult(r, QueryFormat::kTable, std::cout);
}

}  // namespace

void AddStudyCommand(CLI::App& app) {
  auto flags = std::make_shared<StudyFlags>();
  CLI::App* study = app.add_subcommand("study", "Run studies into the database and follow them");
  study->require_subcommand(1);

  CLI::App* run = study->add_subcommand(
      "run", "Run every missing point of a study file into the database (resumable)");
  run->add_option("STUDY", flags->spec_path, "study file (JSON)")->required();
  run->add_option("--db", flags->run.database_path, "study database (SQLite)")
      ->capture_default_str();
  run->add_option("--jobs", flags->run.jobs, "worker threads (default: number of cores)")
      ->check(CLI::Range(1, 1024));
  run->add_flag("--retry-failed", flags->run.retry_failed, "compute failed points again");
  run->add_flag("--quiet", flags->quiet, "no progress on stderr");
  AddAllowPathFlag(run, flags->access);
  run->callback([flags] { Run(*flags); });

  CLI::App* status = study->add_subcommand("status", "Progress and outcomes of the studies");
  status->add_option("STUDY", flags->study, "one study's name (default: all)");
  status->add_option("--db", flags->run.database_path, "study database (SQLite)")
      ->capture_default_str();
  status->callback([flags] { Status(*flags); });
}

void AddQueryCommand(CLI::App& app) {
  auto flags = std::make_shared<StudyFlags>();
  CLI::App* query =
      app.add_subcommand("query",
                         "Run one read-only SQL statement on the database (the views `results` and "
                         "`scene_results` join parameters, scores and references)");
  query->add_option("SQL", flags->sql, "one SELECT (or other read-only) statement")->required();
  query->add_option("--db", flags->run.database_path, "study database (SQLite)")
      ->capture_default_str();
  query->add_option("--format", flags->format, "output format")
      ->capture_default_str()
      ->check(CLI::IsMember({"table", "csv", "json"}));
  query->callback([flags] {
    const QueryResult r = RunReadOnlyQuery(flags->run.database_path, flags->sql);
    WriteQueryResult(r, *QueryFormatFromString(flags->format), std::cout);
  });
}

}  // namespace shockmap

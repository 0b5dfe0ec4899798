#include "app/report_command.h"

#include <fmt/format.h>
#include <unistd.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "app/flag_checks.h"
#include "app/sizing_command.h"
#include "app/thresholds.h"
#include "compare/scene_run.h"
#include "core/input_error.h"
#include "db/ensemble_members.h"
#include "db/report_queries.h"
#include "db/schema.h"
#include "db/sqlite_handle.h"
#include "db/study_database.h"
#include "engine/point_replay.h"
#include "engine/provenance.h"
#include "formats/history_csv.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/study_file.h"
#include "views/comparison_plot.h"
#include "views/contact_force_map.h"
#include "views/ensemble_sizing.h"
#include "views/fig3_svg.h"
#include "views/html_report.h"
#include "views/scored_points.h"

namespace shockmap {
namespace {

struct ReportFlags {
  std::string database_path = kDefaultDatabasePath;
  std::string study;
  ThresholdFlags thresholds;
  std::string out;
};

// Fig. 3 of a stored point, its run computed again against its stored reference; `with_files`
// also writes its histories as CSV and the figure by gnuplot into ctx.dir/points/point_ID.
PointFigure Fig3Of(const ReportContext& ctx, const StudySpec& spec, std::int64_t point_id,
                   const StudyPoint& point, std::shared_ptr<const ReferenceRun> reference,
                   bool with_files) {
  const ReplayedPoint replay = ReplayStudyPoint(spec, point, std::move(reference));
  const double window_s = replay.options.window_s;
  PointFigure figure{Fig3Svg(replay.result, window_s), Fig3Note(replay.result, window_s),
                     replay.result.scores, std::nullopt};
  if (with_files) {
    const auto dir = ctx.dir / "points" / fmt::format("point_{}", point_id);
    CreateOutputDirectory(dir);
    WriteComparisonCsv(replay.result, dir);
    PlotComparison(replay.result, replay.problem, replay.options, dir);
    figure.files = dir;
  }
  return figure;
}

// Fig. 3 of every stored point whose reference is stored, by point_id, each reference read once;
// the points `with_files` names get theirs as files too. A corrupt stored reference spoils its
// points only: they are in `skipped`, with the database's message.
std::map<std::int64_t, PointFigure> DrawFigures(
    const ReportContext& ctx, const StudySpec& spec,
    const std::map<std::int64_t, StoredStudyPoint>& stored,
    const std::set<std::int64_t>& with_files, std::map<std::int64_t, std::string>& skipped) {
  StoredReferenceRuns references(ctx.database_path);
  std::map<std::int64_t, PointFigure> figures;
  const bool terminal = ::isatty(STDOUT_FILENO) != 0;
  for (const auto& [id, point] : stored) {
    if (terminal)
      fmt::print("  Fig. 3 of point {} ({}/{})\r", id, figures.size() + 1, stored.size());
    std::fflush(stdout);
    try {
      if (auto reference = references.Find(point.reference_key)) {
        figures[id] =
            Fig3Of(ctx, spec, id, point.point, std::move(reference), with_files.contains(id));
      }
    } catch (const DbError& e) {
      std::cerr << "shockmap: warning: Fig. 3 of point " << id << " not drawn: " << e.what()
                << '\n';
      skipped[id] = e.what();
    }
  }
  fmt::print("  Fig. 3 drawn for {} of {} points, with files for {}\n", figures.size(),
             stored.size(), with_files.size());
  return figures;
}

std::vector<ReportSection> CanonicalReport(const ReportContext& ctx, const std::string& json) {
  const StudySpec spec = ParseStudySpec(
      ParseJsonText(json, ctx.database_path + ": stored study " + ctx.study), ctx.database_path);
  const auto points = LoadScoredPoints(ctx.database_path, ctx.study, "explicit-modal");
  if (points.empty()) {
    throw InputError("study \"" + ctx.study + "\" has no stored explicit-modal point to report on");
  }
  const auto stored = StudyPointsById(ctx.database_path, ctx.study, spec);
  const auto chosen = PointsWorthFig3(points, ctx.thresholds);
  std::map<std::int64_t, std::string> skipped;
  const auto figures = DrawFigures(ctx, spec, stored, {chosen.begin(), chosen.end()}, skipped);
  auto sections = CanonicalSections(ctx, spec, figures);
  if (!skipped.empty()) sections.insert(sections.begin(), SkippedFigures(skipped));
  return sections;
}

// "bundle.wire.stiffness_n_per_m = 1e+05, solver.r_ftrunc = 1000"
std::string Described(const SceneParameters& parameters) {
  std::string text;
  for (const auto& [path, value] : parameters) {
    text += fmt::format("{}{} = {:g}", text.empty() ? "" : ", ", path, value);
  }
  return text;
}

// One contact-force map per combination of the swept parameters outside "solver.", at the
// reference's settings.
std::vector<SceneForceMap> DrawForceMaps(const ReportContext& ctx, const SceneStudySpec& spec) {
  std::map<SceneParameters, SceneParameters> physical;  // Non-solver parameters -> point.
  for (const SceneParameters& p : spec.points) {
    SceneParameters key;
    for (const auto& entry : p) {
      if (!entry.first.starts_with("solver.")) key.push_back(entry);
    }
    physical.try_emplace(key, ReferenceParameters(spec, p));
  }
  std::vector<SceneForceMap> maps;
  for (const auto& [key, parameters] : physical) {
    fmt::print("  contact-force map {}/{} at {}\n", maps.size() + 1, physical.size(),
               Described(parameters));
    std::fflush(stdout);
    Scene scene = ScoredScene(spec, parameters);
    const SceneRun run = RunScene(scene);
    const auto png = ctx.dir / fmt::format("contact_forces_{}.png", maps.size() + 1);
    DrawContactForceMap(scene, run.max_contact_force_n, png);
    maps.push_back({"Largest contact force per zone at " + Described(parameters), png});
  }
  return maps;
}

std::vector<ReportSection> SceneReport(const ReportContext& ctx, const std::string& json) {
  const SceneStudySpec spec = ParseStoredSceneStudySpec(
      ParseJsonText(json, ctx.database_path + ": stored study " + ctx.study),
      ctx.database_path + ": stored study " + ctx.study);
  return SceneSections(ctx, spec, DrawForceMaps(ctx, spec));
}

std::vector<ReportSection> EnsembleReport(const ReportContext& ctx) {
  Connection db(ctx.database_path, Connection::Mode::kReadOnly);
  CheckSchema(db);
  const StoredEnsemble stored = CurrentMembers(ReadEnsemble(db, ctx.study));
  return EnsembleSections(ctx, stored, StoredEnsembleScene(stored, ctx.database_path, ctx.study));
}

// The sections of the study's kind: the one place a new kind of study joins the report.
std::vector<ReportSection> StudySections(const ReportContext& ctx, StudyFileKind kind,
                                         const std::string& json) {
  switch (kind) {
    case StudyFileKind::kCanonical:
      return CanonicalReport(ctx, json);
    case StudyFileKind::kSceneSweep:
      return SceneReport(ctx, json);
    case StudyFileKind::kSceneEnsemble:
      return EnsembleReport(ctx);
  }
  throw InputError("study \"" + ctx.study + "\": no report for its kind");
}

void Run(const ReportFlags& f) {
  CheckPathLength(std::filesystem::path(f.out) / "points" / "point_1000000000" / "numerical.csv",
                  "--out");
  const std::string study = ResolveStudyName(f.database_path, f.study);
  ReportContext ctx{
      f.database_path,      study, "", ThresholdsFor(f.thresholds, f.database_path, study),
      CurrentProvenance(1), f.out};
  const auto json = StoredStudySpec(ctx.database_path, ctx.study);
  if (!json) throw InputError("no study named \"" + ctx.study + "\" in " + ctx.database_path);
  const StudyFileKind kind = StudyKindOf(
      ParseJsonText(*json, ctx.database_path + ": stored study " + ctx.study), ctx.database_path);
  ctx.kind = ToString(kind);
  // A report refused half-way (a corrupt stored row, a full disk) leaves no folder it created.
  WriteIntoDirectory(ctx.dir, "--out", [&] {
    const auto page = WriteReportIndex(ctx, StudySections(ctx, kind, *json));
    std::cout << "report written to " << page.string() << '\n';
  });
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

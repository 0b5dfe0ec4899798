#include "workflows/study_report.h"

#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "analysis/ensemble_sizing.h"
#include "analysis/scored_points.h"
#include "analysis/study_thresholds.h"
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
#include "specs/study_file.h"
#include "views/comparison_plot.h"
#include "views/contact_force_map.h"
#include "views/fig3_svg.h"
#include "views/html_report.h"
#include "workflows/stored_ensemble_scene.h"

namespace shockmap {
namespace {

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
    const std::set<std::int64_t>& with_files, std::map<std::int64_t, std::string>& skipped,
    const WorkflowLog& log) {
  StoredReferenceRuns references(ctx.database_path);
  std::map<std::int64_t, PointFigure> figures;
  for (const auto& [id, point] : stored) {
    log.Progress(fmt::format("Fig. 3 of point {}", id), static_cast<double>(figures.size() + 1),
                 static_cast<double>(stored.size()));
    try {
      if (auto reference = references.Find(point.reference_key)) {
        figures[id] =
            Fig3Of(ctx, spec, id, point.point, std::move(reference), with_files.contains(id));
      }
    } catch (const DbError& e) {
      log.Warn(fmt::format("Fig. 3 of point {} not drawn: {}", id, e.what()));
      skipped[id] = e.what();
    }
  }
  log.Say(fmt::format("  Fig. 3 drawn for {} of {} points, with files for {}", figures.size(),
                      stored.size(), with_files.size()));
  return figures;
}

std::vector<ReportSection> CanonicalReport(const ReportContext& ctx, const std::string& json,
                                           const WorkflowLog& log) {
  const StudySpec spec = ParseStudySpec(
      ParseJsonText(json, ctx.database_path + ": stored study " + ctx.study), ctx.database_path);
  const auto points = LoadScoredPoints(ctx.database_path, ctx.study, "explicit-modal");
  if (points.empty()) {
    throw InputError("study \"" + ctx.study + "\" has no stored explicit-modal point to report on");
  }
  const auto stored = StudyPointsById(ctx.database_path, ctx.study, spec);
  const auto chosen = PointsWorthFig3(points, ctx.thresholds);
  std::map<std::int64_t, std::string> skipped;
  const auto figures = DrawFigures(ctx, spec, stored, {chosen.begin(), chosen.end()}, skipped, log);
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
std::vector<SceneForceMap> DrawForceMaps(const ReportContext& ctx, const SceneStudySpec& spec,
                                         const WorkflowLog& log) {
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
    log.Say(fmt::format("  contact-force map {}/{} at {}", maps.size() + 1, physical.size(),
                        Described(parameters)));
    Scene scene = ScoredScene(spec, parameters);
    const SceneRun run = RunScene(scene);
    const auto png = ctx.dir / fmt::format("contact_forces_{}.png", maps.size() + 1);
    DrawContactForceMap(scene, run.max_contact_force_n, png);
    maps.push_back({"Largest contact force per zone at " + Described(parameters), png});
  }
  return maps;
}

std::vector<ReportSection> SceneReport(const ReportContext& ctx, const std::string& json,
                                       const WorkflowLog& log) {
  const SceneStudySpec spec = ParseStoredSceneStudySpec(
      ParseJsonText(json, ctx.database_path + ": stored study " + ctx.study),
      ctx.database_path + ": stored study " + ctx.study);
  return SceneSections(ctx, spec, DrawForceMaps(ctx, spec, log));
}

std::vector<ReportSection> EnsembleReport(const ReportContext& ctx) {
  Connection db(ctx.database_path, Connection::Mode::kReadOnly);
  CheckSchema(db);
  const StoredEnsemble stored = CurrentMembers(ReadEnsemble(db, ctx.study));
  return EnsembleSections(ctx, stored, StoredEnsembleScene(stored, ctx.database_path, ctx.study));
}

// The sections of the study's kind: the one place a new kind of study joins the report.
std::vector<ReportSection> StudySections(const ReportContext& ctx, StudyFileKind kind,
                                         const std::string& json, const WorkflowLog& log) {
  switch (kind) {
    case StudyFileKind::kCanonical:
      return CanonicalReport(ctx, json, log);
    case StudyFileKind::kSceneSweep:
      return SceneReport(ctx, json, log);
    case StudyFileKind::kSceneEnsemble:
      return EnsembleReport(ctx);
  }
  throw InputError("study \"" + ctx.study + "\": no report for its kind");
}

}  // namespace

std::filesystem::path WriteStudyReport(const StudyReportRequest& request, const WorkflowLog& log) {
  CheckPathLength(request.out / "points" / "point_1000000000" / "numerical.csv", request.out_name);
  const std::string study = ResolveStudyName(request.database_path, request.study);
  ReportContext ctx{request.database_path,
                    study,
                    "",
                    StudyCriteriaOptions(request.database_path, study, request.thresholds),
                    CurrentProvenance(1),
                    request.out};
  const auto json = StoredStudySpec(ctx.database_path, ctx.study);
  if (!json) throw InputError("no study named \"" + ctx.study + "\" in " + ctx.database_path);
  const StudyFileKind kind = StudyKindOf(
      ParseJsonText(*json, ctx.database_path + ": stored study " + ctx.study), ctx.database_path);
  ctx.kind = ToString(kind);
  std::filesystem::path page;
  WriteIntoDirectory(ctx.dir, request.out_name,
                     [&] { page = WriteReportIndex(ctx, StudySections(ctx, kind, *json, log)); });
  return page;
}

}  // namespace shockmap

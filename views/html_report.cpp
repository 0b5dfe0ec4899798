#include "views/html_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "analysis/cost_front.h"
#include "analysis/scored_points.h"
#include "core/input_error.h"
#include "db/report_queries.h"
#include "formats/output_file.h"
#include "specs/study_file.h"
#include "views/cost_front.h"
#include "views/criteria_report.h"
#include "views/fig4_plot.h"
#include "views/html_text.h"
#include "views/html_validity_map.h"
#include "views/study_verdict.h"
#include "views/validity_map.h"

namespace shockmap {
namespace {

// The R_k of the paper's Fig. 3.
constexpr double kFig3RK = 3000.0;

// The index of the results view's point_id column.
std::size_t PointIdColumn(const Table& results) {
  return static_cast<std::size_t>(std::ranges::find(results.columns, "point_id") -
                                  results.columns.begin());
}

std::string Figure(const std::filesystem::path& png, const std::string& caption,
                   const std::filesystem::path& dir) {
  return EmbeddedFigure(png, caption, PlotFiles(png, dir));
}

// The interactive maps: R_k by R_ftrunc at the finest dt, and R_k by dt at the largest R_ftrunc.
std::string InteractiveMaps(const std::vector<ScoredPoint>& points,
                            const ValidityCriteria& criteria) {
  const MapGrid by_rft = BuildMapGrid(points, MapAxis::kRFtrunc);
  const MapGrid by_dt = BuildMapGrid(points, MapAxis::kDt);
  return fmt::format(
      "<p>Hover a cell for its R_k, R_ftrunc, dt, scores and status; click it to open the "
      "point: its stored values, its Fig. 3 and the <code>compare</code> command that "
      "recomputes it.</p>\n<h3>Outcome over R_k and R_ftrunc, {}</h3>\n{}"
      "<h3>Outcome over R_k and dt at R_ftrunc = {:g}</h3>\n{}"
      "<h3>Scores and cost over R_k and R_ftrunc, {}</h3>\n{}",
      HtmlEscaped(DtShown(by_rft)),
      HtmlValidityMap(by_rft, MapAxis::kRFtrunc, criteria, "map-rftrunc"), by_dt.fixed_r_ftrunc,
      HtmlValidityMap(by_dt, MapAxis::kDt, criteria, "map-dt"), HtmlEscaped(DtShown(by_rft)),
      HtmlMetricMaps(points, by_rft, criteria, "map-metric"));
}

// One line of links to a drawn map's image, data and script.
std::string MapFileLinks(const std::filesystem::path& png, const std::string& caption,
                         const std::filesystem::path& dir) {
  std::string links;
  for (const FileLink& l : PlotFiles(png, dir)) {
    links += fmt::format(" <a href=\"{}\">{}</a>", HtmlEscaped(l.relative.generic_string()),
                         HtmlEscaped(l.label));
  }
  return fmt::format("<li>{}:{}</li>\n", HtmlEscaped(caption), links);
}

// The gnuplot maps, drawn into ctx.dir for papers and linked (the page shows the interactive
// maps).
std::string MapFiles(const ReportContext& ctx, const std::vector<ScoredPoint>& points,
                     const ValidityCriteria& criteria) {
  std::string items;
  for (const std::string& metric : MapMetrics()) {
    const auto png = ctx.dir / ("map_" + metric + ".png");
    DrawValidityMap(ctx.study, points, criteria, {metric, MapAxis::kRFtrunc, {}}, png);
    items += MapFileLinks(png, metric + " over R_k and R_ftrunc", ctx.dir);
  }
  const auto dt_png = ctx.dir / "map_status_dt.png";
  DrawValidityMap(ctx.study, points, criteria, {"status", MapAxis::kDt, {}}, dt_png);
  items += MapFileLinks(dt_png, "outcome over R_k and dt / dt_sharp", ctx.dir);
  return "<p>The maps as gnuplot figures, with their data and scripts:</p>\n<ul "
         "class=\"files\">\n" +
         items + "</ul>\n";
}

// The cost front of the paper's Fig. 3 case when studied, else of the nearest R_k, with its
// table; a sentence when no point is scored.
std::string CostSection(const ReportContext& ctx, const std::vector<ScoredPoint>& explicit_points,
                        const std::vector<ScoredPoint>& implicit_points) {
  const auto tables = BuildCostTables(explicit_points, implicit_points, kFig3RK);
  if (tables.empty()) return "<p>No scored point: no cost front.</p>\n";
  const auto cost_png = ctx.dir / "cost.png";
  DrawCost(ctx.study, tables.front(), cost_png);
  std::string html = Figure(
      cost_png, fmt::format("Err against wall time at R_k = {:.4g}", tables.front().r_k), ctx.dir);
  for (const CostTable& t : tables) {
    html += "<p>" + HtmlEscaped(CostHeadline(t)) + ".</p>\n" +
            SortableTable(CostRowsTable(t), "cost-table",
                          fmt::format("Every scored point at R_k = {:.4g}, fastest first", t.r_k));
  }
  return html;
}

// The criteria per R_k as a table, then the fit and the paper's rules, each line its label in
// bold.
std::string CriteriaHtml(const ValidityCriteria& criteria, const std::vector<ScoredPoint>& points) {
  std::string rules;
  for (const std::string& line : CriteriaRuleLines(criteria, points)) {
    const std::size_t gap = line.find("  ");
    const std::size_t text = line.find_first_not_of(' ', gap);
    rules += gap == std::string::npos || text == std::string::npos
                 ? "<li>" + HtmlEscaped(line) + "</li>\n"
                 : fmt::format("<li><strong>{}</strong>: {}</li>\n",
                               HtmlEscaped(line.substr(0, gap)), HtmlEscaped(line.substr(text)));
  }
  return SortableTable(CriteriaTable(criteria), "criteria-table",
                       "Per studied R_k (explicit-modal; " +
                           ThresholdsText(criteria.options, false) + "); an empty cell: none") +
         "<ul class=\"rules\">\n" + rules + "</ul>\n";
}

// The points table (a chosen set of the results view's columns), each row linking its page.
std::string PointsTable(const Table& results) {
  std::vector<std::string> shown_columns = {"point_id", "r_k",       "r_ftrunc",  "scheme",
                                            "dt_rule",  "dt_factor", "dt_used_s", "status"};
  for (const ScoreDefinition& score : Scores()) shown_columns.emplace_back(score.name);
  for (const char* name : {"n_modes", "steps", "wall_s", "message"})
    shown_columns.emplace_back(name);
  Table shown;
  std::vector<std::size_t> columns;
  for (const std::string& name : shown_columns) {
    const auto it = std::ranges::find(results.columns, name);
    if (it != results.columns.end()) {
      columns.push_back(static_cast<std::size_t>(it - results.columns.begin()));
      shown.columns.push_back(name);
    }
  }
  std::vector<std::string> links;
  for (const auto& row : results.rows) {
    auto& out = shown.rows.emplace_back();
    for (std::size_t c : columns) out.push_back(row[c]);
    links.push_back(
        PointPagePath(std::get<std::int64_t>(row[PointIdColumn(results)])).generic_string());
  }
  return SortableTable(shown, "points-table", "Every stored point (click a header to sort)", links);
}

// Writes points/point_ID.html for every row of `results`.
void WritePointPages(const ReportContext& ctx, const StudySpec& spec, const Table& results,
                     const std::map<std::int64_t, PointFigure>& figures) {
  const auto stored = StudyPointsById(ctx.database_path, ctx.study, spec);
  CreateOutputDirectory(ctx.dir / "points");
  for (const auto& row : results.rows) {
    PointPageInput in{ctx.study,
                      std::get<std::int64_t>(row[PointIdColumn(results)]),
                      &results.columns,
                      &row,
                      {},
                      &spec,
                      {}};
    if (const auto p = stored.find(in.point_id); p != stored.end()) in.point = p->second.point;
    if (const auto f = figures.find(in.point_id); f != figures.end()) in.figure = f->second;
    WriteFileAtomically(ctx.dir / PointPagePath(in.point_id), PointPage(in));
  }
}

// The facts of the header every kind shares.
std::vector<std::pair<std::string, std::string>> HeaderFacts(const ReportContext& ctx,
                                                             const Table& provenance) {
  std::set<std::string> versions;
  for (std::size_t i = 0; i < provenance.rows.size(); ++i) {
    versions.insert(CellText(NamedRow(provenance, i)["code_version"]));
  }
  std::string computed;
  for (const std::string& v : versions) computed += (computed.empty() ? "" : ", ") + v;
  std::vector<std::pair<std::string, std::string>> facts = {
      {"study", ctx.study},
      {"kind", ctx.kind},
      {"report written", UtcNow() + " (UTC)"},
      {"by code version", fmt::format("{} ({}, {})", ctx.writer.code_version, ctx.writer.compiler,
                                      ctx.writer.build_type)},
      {ctx.kind == ToString(StudyFileKind::kSceneEnsemble) ? "members computed by"
                                                           : "points computed by",
       computed.empty() ? "no run yet" : computed},
      {"database", ctx.database_path}};
  // An ensemble's members are not scored: the scores' thresholds judge nothing there.
  if (ctx.kind != ToString(StudyFileKind::kSceneEnsemble)) {
    facts.emplace_back("thresholds", ThresholdsText(ctx.thresholds, true));
  }
  return facts;
}

}  // namespace

std::vector<std::int64_t> PointsWorthFig3(const std::vector<ScoredPoint>& points,
                                          const CriteriaOptions& thresholds) {
  const ValidityCriteria criteria = DeriveCriteria(points, thresholds);
  const MapGrid grid = BuildMapGrid(points, MapAxis::kRFtrunc);
  std::map<double, std::vector<const MapCell*>> by_rk;  // Ascending R_ftrunc within each.
  for (const MapCell& c : grid.cells) by_rk[c.r_k].push_back(&c);
  std::set<std::int64_t> chosen;
  for (const RkBoundary& b : criteria.boundary) {
    const auto& column = by_rk[b.r_k];
    if (column.empty()) continue;
    auto at = std::ranges::find_if(
        column, [&](const MapCell* c) { return b.r_ftrunc_min && c->y >= *b.r_ftrunc_min; });
    if (at == column.end()) at = column.end() - 1;  // Nothing passes: the largest truncation.
    chosen.insert((*at)->point->point_id);
    if (at != column.begin()) chosen.insert((*(at - 1))->point->point_id);
  }
  const auto nearest = std::ranges::min_element(
      by_rk, {}, [](const auto& entry) { return std::abs(std::log(entry.first / kFig3RK)); });
  if (nearest != by_rk.end()) {
    chosen.insert(nearest->second.front()->point->point_id);
    chosen.insert(nearest->second.back()->point->point_id);
  }
  return {chosen.begin(), chosen.end()};
}

std::vector<ReportSection> CanonicalSections(const ReportContext& ctx, const StudySpec& spec,
                                             const std::map<std::int64_t, PointFigure>& figures) {
  const auto explicit_points = LoadScoredPoints(ctx.database_path, ctx.study, "explicit-modal");
  const auto implicit_points = LoadScoredPoints(ctx.database_path, ctx.study, "implicit-full");
  if (explicit_points.empty()) {
    throw InputError("study \"" + ctx.study + "\" has no stored explicit-modal point to report on");
  }
  const ValidityCriteria criteria = DeriveCriteria(explicit_points, ctx.thresholds);
  const ReportTables tables = LoadReportTables(ctx.database_path, ctx.study);
  const Table results = StudyResultRows(ctx.database_path, ctx.study, kCanonicalPoints);
  WritePointPages(ctx, spec, results, figures);
  const auto fig4_png = ctx.dir / "fig4.png";
  DrawFig4(ctx.study, explicit_points, implicit_points, ctx.thresholds, fig4_png);
  return {
      {"verdict", "Verdict",
       "<p class=\"verdict\" id=\"verdict-text\">" +
           HtmlEscaped(StudyVerdict(ctx.study, criteria, explicit_points, results)) + "</p>\n"},
      {"outcomes", "Outcomes",
       SortableTable(tables.outcomes, "outcomes-table", "Points by scheme and status")},
      {"criteria", "Validity criteria and the paper's rules",
       CriteriaHtml(criteria, explicit_points)},
      {"maps", "Validity maps", InteractiveMaps(explicit_points, criteria)},
      {"map-files", "Validity maps as files", MapFiles(ctx, explicit_points, criteria)},
      {"fig4", "The paper's Fig. 4",
       Figure(fig4_png, "Err and SRf against R_k, as the paper's Fig. 4", ctx.dir)},
      {"cost", "What accuracy costs", CostSection(ctx, explicit_points, implicit_points)},
      {"points", "Points", PointsTable(results)},
      {"provenance", "Provenance",
       SortableTable(tables.provenance, "provenance-table", "Runs of the study")},
      {"study-file", "Study file", Preformatted(tables.spec_json)},
  };
}

ReportSection SkippedFigures(const std::map<std::int64_t, std::string>& reasons) {
  std::string html = "<p>Fig. 3 was not drawn for these points:</p>\n<ul>\n";
  for (const auto& [point_id, reason] : reasons) {
    html += fmt::format("<li>point {}: {}</li>\n", point_id, HtmlEscaped(reason));
  }
  return {"skipped-figures", "Figures not drawn", html + "</ul>\n"};
}

std::filesystem::path WriteReportIndex(const ReportContext& ctx,
                                       const std::vector<ReportSection>& sections) {
  const ReportTables tables = LoadReportTables(ctx.database_path, ctx.study);
  const ReportHeader header{"shockmap report: " + ctx.study, HeaderFacts(ctx, tables.provenance)};
  const auto page = ctx.dir / "index.html";
  WriteFileAtomically(page, ReportPage(header, sections));
  return page;
}

}  // namespace shockmap

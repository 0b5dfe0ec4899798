#include "views/html_report.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "db/report_queries.h"
#include "formats/output_file.h"
#include "views/cost_front.h"
#include "views/criteria_report.h"
#include "views/fig4_plot.h"
#include "views/query_output.h"
#include "views/scored_points.h"
#include "views/validity_map.h"

namespace shockmap {
namespace {

std::string Escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string Base64(const std::string& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const auto n = (static_cast<unsigned char>(bytes[i]) << 16) |
                   (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                   static_cast<unsigned char>(bytes[i + 2]);
    out += {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63], kAlphabet[(n >> 6) & 63],
            kAlphabet[n & 63]};
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const auto n = (static_cast<unsigned char>(bytes[i]) << 16) |
                   (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0);
    out += {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63],
            two ? kAlphabet[(n >> 6) & 63] : '=', '='};
  }
  return out;
}

std::string Figure(const std::filesystem::path& png, const std::string& caption) {
  std::ifstream in(png, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return fmt::format(
      "<figure><img alt=\"{0}\" src=\"data:image/png;base64,{1}\"><figcaption>{0}</figcaption>"
      "</figure>\n",
      Escaped(caption), Base64(bytes.str()));
}

std::string Table(const QueryResult& r) {
  std::ostringstream text;
  WriteQueryResult(r, QueryFormat::kTable, text);
  return "<pre>" + Escaped(text.str()) + "</pre>\n";
}

// The validity maps over R_ftrunc for each metric, then the outcome over dt, as figures.
std::string MapFigures(const std::string& study, const std::vector<ScoredPoint>& points,
                       const ValidityCriteria& criteria, const std::filesystem::path& dir) {
  std::string figures;
  for (auto metric : {MapMetric::kErr, MapMetric::kSrf, MapMetric::kStatus, MapMetric::kCost}) {
    const auto png = dir / ("map_" + ToString(metric) + ".png");
    DrawValidityMap(study, points, criteria, {metric, MapAxis::kRFtrunc, {}}, png);
    figures += Figure(png, "Validity map: " + ToString(metric) + " over R_k and R_ftrunc");
  }
  const auto dt_png = dir / "map_status_dt.png";
  DrawValidityMap(study, points, criteria, {MapMetric::kStatus, MapAxis::kDt, {}}, dt_png);
  return figures + Figure(dt_png, "Outcome over R_k and dt / dt_sharp at the largest truncation");
}

// The cost front of the paper's Fig. 3 case when studied, else of the nearest R_k, with its
// table; "" when no point is scored.
std::string CostSection(const std::string& study, const std::vector<ScoredPoint>& explicit_points,
                        const std::vector<ScoredPoint>& implicit_points,
                        const std::filesystem::path& dir) {
  const auto tables = BuildCostTables(explicit_points, implicit_points, 3000.0);
  if (tables.empty()) return "";
  const auto cost_png = dir / "cost.png";
  DrawCost(study, tables.front(), cost_png);
  return Figure(cost_png,
                fmt::format("Err against wall time at R_k = {:.4g}", tables.front().r_k)) +
         "<pre>" + Escaped(CostSummary(tables)) + "</pre>\n";
}

// The parts of the page, already HTML.
struct ReportParts {
  std::string study, outcomes, criteria, figures, fig4, cost, provenance, spec;
};

std::string Page(const ReportParts& p, const CriteriaOptions& thresholds) {
  return fmt::format(
      R"html(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>shockmap report: {study}</title>
<style>
body {{ font-family: 'DejaVu Sans', sans-serif; max-width: 1200px; margin: 2em auto; color: #222; }}
figure {{ margin: 1.5em 0; }} img {{ max-width: 100%; border: 1px solid #ddd; }}
figcaption {{ color: #555; font-size: 0.9em; }} pre {{ background: #f6f6f6; padding: 1em; white-space: pre-wrap; }}
</style>
<script>
window.addEventListener('load', () => {{
  const images = Array.from(document.images);
  const loaded = images.filter(i => i.complete && i.naturalWidth > 0).length;
  document.body.dataset.imagesLoaded = loaded + '/' + images.length;
}});
</script></head>
<body>
<h1>shockmap report: {study}</h1>
<p>Validity of modal basis reduction with explicit integration for the beam-impact problem of
the EURODYN 2017 paper: Err (eq. 8) and SRf (eq. 9) against the semi-analytical reference.
Thresholds: Err &le; {err_max:g}, SRf &ge; {srf_min:g}.</p>
<h2>Outcomes</h2>
{outcomes}
<h2>Validity criteria and the paper's rules</h2>
<pre>{criteria}</pre>
<h2>Validity maps</h2>
{figures}
<h2>The paper's Fig. 4</h2>
{fig4}
<h2>What accuracy costs</h2>
{cost}
<h2>Provenance</h2>
{provenance}
<h3>Study file</h3>
<pre>{spec}</pre>
</body></html>
)html",
      fmt::arg("study", p.study), fmt::arg("err_max", thresholds.err_max),
      fmt::arg("srf_min", thresholds.srf_min), fmt::arg("outcomes", p.outcomes),
      fmt::arg("criteria", p.criteria), fmt::arg("figures", p.figures), fmt::arg("fig4", p.fig4),
      fmt::arg("cost", p.cost), fmt::arg("provenance", p.provenance), fmt::arg("spec", p.spec));
}

}  // namespace

std::filesystem::path WriteHtmlReport(const std::string& database_path, const std::string& study,
                                      const CriteriaOptions& thresholds,
                                      const std::filesystem::path& dir) {
  const auto explicit_points = LoadScoredPoints(database_path, study, "explicit-modal");
  const auto implicit_points = LoadScoredPoints(database_path, study, "implicit-full");
  if (explicit_points.empty()) {
    throw InputError("study \"" + study + "\" has no stored explicit-modal point to report on");
  }
  CreateOutputDirectory(dir);
  const ValidityCriteria criteria = DeriveCriteria(explicit_points, thresholds);
  ReportParts parts;
  parts.study = Escaped(study);
  parts.figures = MapFigures(study, explicit_points, criteria, dir);
  const auto fig4_png = dir / "fig4.png";
  DrawFig4(study, explicit_points, implicit_points, thresholds, fig4_png);
  parts.fig4 = Figure(fig4_png, "Err and SRf against R_k, as the paper's Fig. 4");
  parts.cost = CostSection(study, explicit_points, implicit_points, dir);
  const ReportTables tables = LoadReportTables(database_path, study);
  parts.outcomes = Table(tables.outcomes);
  parts.provenance = Table(tables.provenance);
  parts.spec = Escaped(tables.spec_json);
  parts.criteria = Escaped(CriteriaSummary(study, criteria, explicit_points));
  const auto page = dir / "report.html";
  WriteFileAtomically(page, Page(parts, thresholds));
  return page;
}

}  // namespace shockmap

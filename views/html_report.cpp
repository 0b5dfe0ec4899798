#include "views/html_report.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <variant>

#include "core/input_error.h"
#include "db/read_only_query.h"
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

}  // namespace

std::filesystem::path WriteHtmlReport(const std::string& database_path, const std::string& study,
                                      const CriteriaOptions& thresholds,
                                      const std::filesystem::path& dir) {
  const auto explicit_points = LoadScoredPoints(database_path, study, "explicit-modal");
  const auto implicit_points = LoadScoredPoints(database_path, study, "implicit-full");
  if (explicit_points.empty()) {
    throw InputError("study \"" + study + "\" has no stored explicit-modal point to report on");
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("cannot create " + dir.string() + ": " + ec.message());
  const ValidityCriteria criteria = DeriveCriteria(explicit_points, thresholds);

  std::string figures;
  for (auto metric : {MapMetric::kErr, MapMetric::kSrf, MapMetric::kStatus, MapMetric::kCost}) {
    const auto png = dir / ("map_" + ToString(metric) + ".png");
    DrawValidityMap(study, explicit_points, criteria, {metric, MapAxis::kRFtrunc, {}}, png);
    figures += Figure(png, "Validity map: " + ToString(metric) + " over R_k and R_ftrunc");
  }
  const auto dt_png = dir / "map_status_dt.png";
  DrawValidityMap(study, explicit_points, criteria, {MapMetric::kStatus, MapAxis::kDt, {}}, dt_png);
  figures += Figure(dt_png, "Outcome over R_k and dt / dt_sharp at the largest truncation");

  const auto fig4_png = dir / "fig4.png";
  DrawFig4(study, explicit_points, implicit_points, thresholds, fig4_png);

  // The paper's Fig. 3 case when studied, else the nearest R_k.
  const auto tables = BuildCostTables(explicit_points, implicit_points, 3000.0);
  std::string cost_html;
  if (!tables.empty()) {
    const auto cost_png = dir / "cost.png";
    DrawCost(study, tables.front(), cost_png);
    cost_html =
        Figure(cost_png, fmt::format("Err against wall time at R_k = {:.4g}", tables.front().r_k)) +
        "<pre>" + Escaped(CostSummary(tables)) + "</pre>\n";
  }

  const QueryResult provenance = RunReadOnlyQuery(
      database_path,
      "SELECT ru.run_id, ru.code_version, ru.compiler, ru.build_type, ru.host, ru.jobs, "
      "ru.started_utc, ru.ended_utc, ru.points_done FROM runs ru JOIN studies st USING "
      "(study_id) WHERE st.name = ?1 ORDER BY ru.run_id",
      {study});
  const QueryResult spec =
      RunReadOnlyQuery(database_path, "SELECT spec_json FROM studies WHERE name = ?1", {study});
  const QueryResult outcomes =
      RunReadOnlyQuery(database_path,
                       "SELECT scheme, status, count(*) AS points FROM results WHERE study = ?1 "
                       "GROUP BY scheme, status ORDER BY scheme, status",
                       {study});
  const std::string spec_json =
      spec.rows.empty() ? "" : std::get<std::string>(spec.rows.front().front());

  const auto page = dir / "report.html";
  std::ofstream html(page);
  html << fmt::format(
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
      fmt::arg("study", Escaped(study)), fmt::arg("err_max", thresholds.err_max),
      fmt::arg("srf_min", thresholds.srf_min), fmt::arg("outcomes", Table(outcomes)),
      fmt::arg("criteria", Escaped(CriteriaSummary(study, criteria, explicit_points))),
      fmt::arg("figures", figures),
      fmt::arg("fig4", Figure(fig4_png, "Err and SRf against R_k, as the paper's Fig. 4")),
      fmt::arg("cost", cost_html), fmt::arg("provenance", Table(provenance)),
      fmt::arg("spec", Escaped(spec_json)));
  if (!html) throw InputError("cannot write " + page.string());
  return page;
}

}  // namespace shockmap

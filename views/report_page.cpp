#include "views/report_page.h"

#include <fmt/format.h>

#include "validation/scores.h"
#include "views/html_text.h"
#include "views/vendored_scripts.h"

namespace shockmap {
namespace {

constexpr const char* kStyle = R"css(
body { font-family: 'DejaVu Sans', sans-serif; max-width: 1250px; margin: 1.5em auto; padding: 0 1em; color: #222; }
header dl { display: grid; grid-template-columns: max-content auto; gap: 0.2em 1.2em; margin: 0.5em 0 1em; }
header dt { color: #555; } header dd { margin: 0; font-family: 'DejaVu Sans Mono', monospace; }
nav#contents { background: #f6f6f6; padding: 0.6em 1.2em; border-left: 4px solid #1a9850; }
nav#contents ol { margin: 0.3em 0; }
h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 1.8em; }
figure { margin: 1.2em 0; } img { max-width: 100%; border: 1px solid #ddd; }
figcaption { color: #555; font-size: 0.9em; } .files a { margin-left: 0.6em; }
pre { background: #f6f6f6; padding: 0.8em; white-space: pre-wrap; font-size: 0.9em; }
code { background: #f0f0f0; padding: 0 0.2em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.88em; }
caption { text-align: left; font-weight: bold; padding: 0.3em 0; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: right; white-space: nowrap; vertical-align: top; }
td.long { white-space: normal; min-width: 24em; text-align: left; overflow-wrap: anywhere; }
th { background: #eef3ee; cursor: pointer; user-select: none; white-space: normal; vertical-align: bottom; }
th[aria-sort=ascending]::after { content: ' \25B2'; } th[aria-sort=descending]::after { content: ' \25BC'; }
td:first-child, th:first-child { text-align: left; }
.table-wrap { overflow-x: auto; }
.table-tools { margin: 1em 0 -0.4em; font-size: 0.88em; }
.table-tools input { width: 18em; padding: 0.15em 0.4em; } .table-tools a { margin-left: 0.8em; }
p.verdict { background: #f3f8f3; border-left: 4px solid #1a9850; padding: 0.6em 1em; line-height: 1.45; }
svg.map { width: 100%; max-width: 1100px; height: auto; display: block; }
svg.map rect.cell { stroke: #fff; stroke-width: 1; cursor: pointer; }
svg.map rect.cell:hover { stroke: #000; stroke-width: 2; }
svg.map text { font-size: 12px; } svg.map .axis { font-size: 13px; }
svg.sweep-map { width: 100%; max-width: 860px; height: auto; display: block; }
svg.sweep-map rect.cell { stroke: #fff; stroke-width: 1; } svg.sweep-map rect.cell:hover { stroke: #000; stroke-width: 2; }
svg.sweep-map text { font-size: 12px; }
svg.fig3 { width: 100%; max-width: 760px; height: auto; display: block; }
svg.fig3 text { font-size: 11px; } svg.fig3 .axis { font-size: 12px; }
svg.fig3 .grid { stroke: #ddd; stroke-dasharray: 2 2; } svg.fig3 .frame { fill: none; stroke: #333; }
.legend span { display: inline-block; margin-right: 1.2em; }
.legend .scale i { vertical-align: middle; display: inline-block; height: 1em; border: 1px solid #999; }
.legend i { display: inline-block; width: 1em; height: 1em; vertical-align: middle; margin-right: 0.3em; border: 1px solid #999; }
.legend b.marker { display: inline-block; width: 1em; text-align: center; margin-right: 0.3em; }
#cell-info { position: fixed; display: none; background: #fff; border: 1px solid #333; padding: 0.4em 0.6em; font-size: 0.85em; pointer-events: none; box-shadow: 2px 2px 6px #aaa; }
@media print {
  body { max-width: none; margin: 0; font-size: 10pt; }
  .table-tools, nav#contents, #cell-info, footer, select.metric-switch { display: none; }
  .metric-map[hidden] { display: block; }
  .table-wrap { overflow: visible; }
  table { font-size: 8pt; } th[aria-sort]::after { content: ''; }
  td.long { min-width: 12em; }
  section { break-before: page; } section:first-of-type { break-before: auto; }
  h2, h3, caption { break-after: avoid; } tr, figure, svg.map, svg.fig3, p.verdict { break-inside: avoid; }
  thead { display: table-header-group; }
  a { color: inherit; text-decoration: none; }
}
)css";

// After the vendored tablesort: a numeric sort that reads exponents (empty cells sort as
// -infinity), every sortable table taken, the map's hover box, the metric switch (with {scores}:
// one line per score of the registry), and the page's load marks. A format string: its braces are
// doubled.
constexpr const char* kScript = R"js(
Tablesort.extend('real', function () {{ return false; }}, function (a, b) {{
  var x = a.trim() === '' ? -Infinity : Number(a), y = b.trim() === '' ? -Infinity : Number(b);
  if (x === y || (isNaN(x) && isNaN(y))) return 0;
  return (isNaN(y) ? -Infinity : y) > (isNaN(x) ? -Infinity : x) ? 1 : -1;
}});
var sortableTables = 0;
document.querySelectorAll('table.sortable').forEach(function (t) {{ new Tablesort(t); ++sortableTables; }});
var info = document.getElementById('cell-info');
document.querySelectorAll('svg.map rect.cell').forEach(function (cell) {{
  cell.addEventListener('mousemove', function (e) {{
    var d = cell.dataset;
    info.innerHTML = '';
    [['R_k', d.rk], ['R_ftrunc', d.rftrunc], ['dt', d.dt + ' s (' + d.dtRatio + ' dt_sharp)'],
     {scores}['status', d.status + ' (' + d.outcome + ')']].forEach(function (row) {{
      var line = document.createElement('div');
      line.textContent = row[0] + ': ' + row[1];
      info.appendChild(line);
    }});
    info.style.left = (e.clientX + 14) + 'px';
    info.style.top = (e.clientY + 14) + 'px';
    info.style.display = 'block';
  }});
  cell.addEventListener('mouseleave', function () {{ info.style.display = 'none'; }});
}});
// Each metric switch shows the map of the metric chosen and hides the others.
document.querySelectorAll('select.metric-switch').forEach(function (choice) {{
  var maps = document.getElementById(choice.dataset.maps).querySelectorAll('.metric-map');
  function show() {{
    maps.forEach(function (m) {{ m.hidden = m.dataset.metric !== choice.value; }});
  }}
  choice.addEventListener('change', show);
  show();
}});
// Each table's filter box hides the body rows that do not hold every word typed (any case).
document.querySelectorAll('input.table-filter').forEach(function (box) {{
  var table = document.getElementById(box.dataset.table);
  box.addEventListener('input', function () {{
    var words = box.value.toLowerCase().split(/\s+/).filter(Boolean);
    Array.from(table.tBodies[0].rows).forEach(function (row) {{
      var text = row.textContent.toLowerCase();
      row.hidden = !words.every(function (w) {{ return text.indexOf(w) >= 0; }});
    }});
  }});
}});
// A table as CSV (RFC 4180): its header and the rows shown, each real at full precision.
function tableCsv(table) {{
  function field(cell) {{
    var text = cell.hasAttribute('data-sort') ? cell.getAttribute('data-sort') : cell.textContent;
    return /[",\r\n]/.test(text) ? '"' + text.replace(/"/g, '""') + '"' : text;
  }}
  var rows = [table.tHead.rows[0]].concat(Array.from(table.tBodies[0].rows).filter(function (r) {{
    return !r.hidden;
  }}));
  return rows.map(function (r) {{ return Array.from(r.cells).map(field).join(','); }}).join('\r\n') + '\r\n';
}}
document.querySelectorAll('a.table-csv').forEach(function (link) {{
  link.addEventListener('click', function () {{
    link.href = 'data:text/csv;charset=utf-8,' +
        encodeURIComponent(tableCsv(document.getElementById(link.dataset.table)));
  }});
}});
window.addEventListener('load', function () {{
  var images = Array.from(document.images);
  var loaded = images.filter(function (i) {{ return i.complete && i.naturalWidth > 0; }}).length;
  document.body.dataset.imagesLoaded = loaded + '/' + images.length;
  document.body.dataset.sortableTables = String(sortableTables);
}});
)js";

// The script with one hover line per score: ['Err', d.err], ['SRf', d.srf], ...
std::string Script() {
  std::string scores;
  for (const ScoreDefinition& score : Scores()) {
    scores += fmt::format("['{}', d.{}], ", score.label, score.name);
  }
  return fmt::format(fmt::runtime(kScript), fmt::arg("scores", scores));
}

std::string Header(const ReportHeader& header) {
  std::string facts;
  for (const auto& [label, value] : header.facts) {
    facts += fmt::format("<dt>{}</dt><dd>{}</dd>\n", HtmlEscaped(label), HtmlEscaped(value));
  }
  return fmt::format("<header><h1>{}</h1>\n<dl>\n{}</dl></header>\n", HtmlEscaped(header.title),
                     facts);
}

std::string Contents(const std::vector<ReportSection>& sections) {
  if (sections.size() < 2) return "";
  std::string items;
  for (const ReportSection& s : sections) {
    items +=
        fmt::format("<li><a href=\"#{}\">{}</a></li>", HtmlEscaped(s.id), HtmlEscaped(s.title));
  }
  return "<nav id=\"contents\"><strong>Contents</strong><ol>" + items + "</ol></nav>\n";
}

std::string Licences() {
  return fmt::format(
      "<details><summary>Third-party code in this page</summary><p>tablesort 5.7.1 (table "
      "sorting), under this licence:</p><pre>{}</pre></details>\n",
      HtmlEscaped(TablesortLicence()));
}

}  // namespace

std::string ReportPage(const ReportHeader& header, const std::vector<ReportSection>& sections) {
  std::string body;
  for (const ReportSection& s : sections) {
    body += fmt::format("<section id=\"{}\"><h2>{}</h2>\n{}</section>\n", HtmlEscaped(s.id),
                        HtmlEscaped(s.title), s.html);
  }
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>{title}</title>\n<style>{style}</style></head>\n<body>\n{header}{contents}{body}"
      "<footer>{licences}</footer>\n<div id=\"cell-info\"></div>\n"
      "<script>{tablesort}</script>\n<script>{script}</script>\n</body></html>\n",
      fmt::arg("title", HtmlEscaped(header.title)), fmt::arg("style", kStyle),
      fmt::arg("header", Header(header)), fmt::arg("contents", Contents(sections)),
      fmt::arg("body", body), fmt::arg("licences", Licences()),
      fmt::arg("tablesort", TablesortScript()), fmt::arg("script", Script()));
}

}  // namespace shockmap

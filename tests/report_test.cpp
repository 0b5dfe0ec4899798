// The report a user opens: index.html in a real browser (Debian's headless Chromium) has its
// tables, sorts them on a click, its map cells carry the stored values and link to point pages
// whose `compare` command recomputes the stored score; the other views of a study answer; the
// HTML pieces escape what comes from user files.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "analysis/cost_front.h"
#include "analysis/scored_points.h"
#include "formats/scene_file.h"
#include "specs/zone_family.h"
#include "tests/run_command.h"
#include "views/contact_force_map.h"
#include "views/cost_front.h"
#include "views/fig3_svg.h"
#include "views/html_text.h"
#include "views/map_grid.h"
#include "views/study_verdict.h"

namespace shockmap {
namespace {

using testing::ReadBytes;
using testing::RunShell;
using testing::RunShockmap;
using testing::WriteText;

// Where a test's study, report and browser profile live.
struct Place {
  std::filesystem::path dir;
  std::string db;
};

// A new empty folder named `name` and this process's id under the temporary directory, and the
// database file `database` in it.
Place FreshPlace(const std::string& name, const std::string& database) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return {dir, (dir / database).string()};
}

// The DOM of `page` after its scripts ran, from headless Chromium.
std::string Dom(const Place& at, const std::filesystem::path& page) {
  // Flags as the machine's own Chromium check uses them: no sandbox as root, no network.
  const auto dom = RunShell(
      "chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir=" +
      (at.dir / "chromium").string() + " --virtual-time-budget=10000 --dump-dom file://" +
      page.string() + " 2>/dev/null");
  EXPECT_EQ(dom.exit_code, 0) << "chromium did not run (is Debian's chromium installed?)";
  return dom.output;
}

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}

// The number of stored points with `status`, as `query --format csv` prints it.
std::string StatusCount(const Place& at, const std::string& status) {
  const auto q =
      RunShockmap("query --db " + at.db +
                  " --format csv \"SELECT count(*) FROM results WHERE status = '" + status + "'\"");
  EXPECT_EQ(q.exit_code, 0) << q.output;
  const auto line = q.output.find('\n');
  return q.output.substr(line + 1, q.output.find('\n', line + 1) - line - 1);
}

// The body rows of the table `id` in `dom`.
std::size_t TableRowCount(const std::string& dom, const std::string& id) {
  const auto start = dom.find("id=\"" + id + "\"");
  if (start == std::string::npos) return 0;
  const auto body = dom.find("<tbody>", start);
  return Count(dom.substr(body, dom.find("</tbody>", body) - body), "<tr");
}

// The values of the data rows of block `index` (blocks separated by two blank lines) of a
// gnuplot data file, comments skipped.
std::vector<std::vector<double>> DataBlock(const std::string& file, int index) {
  std::vector<std::vector<double>> rows;
  std::stringstream in(ReadBytes(file));
  int block = 0, blank = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) {
      if (++blank == 2) ++block;
      continue;
    }
    blank = 0;
    if (line[0] == '#' || block != index) continue;
    std::stringstream fields(line);
    std::vector<double>& row = rows.emplace_back();
    for (std::string f; fields >> f;) row.push_back(f == "NaN" ? NAN : std::stod(f));
  }
  return rows;
}

// The plot clauses of a gnuplot script whose text contains `what`.
std::vector<std::string> ClausesWith(const std::string& script, const std::string& what) {
  const std::string plot = script.substr(script.rfind("\nplot "));
  const std::regex clause("(?:plot |, \\\\\n +)([^\n]*?)(?=, \\\\\n|\n|$)");
  std::vector<std::string> found;
  for (auto it = std::sregex_iterator(plot.begin(), plot.end(), clause);
       it != std::sregex_iterator(); ++it) {
    if ((*it)[1].str().find(what) != std::string::npos) found.push_back((*it)[1]);
  }
  return found;
}

// The stored value of one column of a point, as `query --format csv` prints it.
std::string Stored(const Place& at, const std::string& column, const std::string& point_id) {
  const auto q = RunShockmap("query --db " + at.db + " --format csv \"SELECT " + column +
                             " FROM results WHERE point_id = " + point_id + "\"");
  EXPECT_EQ(q.exit_code, 0) << q.output;
  const auto line = q.output.find('\n');
  return q.output.substr(line + 1, q.output.find('\n', line + 1) - line - 1);
}

// One report, checked in its parts (writing it takes most of the time).
void CheckIndex(const Place& at) {
  const auto page = at.dir / "report" / "index.html";
  ASSERT_TRUE(std::filesystem::exists(page));
  const std::string html = ReadBytes(page.string());
  EXPECT_EQ(html.find("src=\"http"), std::string::npos) << "the page loads from the network";
  const std::string dom = Dom(at, page);
  const std::size_t images = Count(html, "<img ");
  const std::size_t tables = Count(html, "<table class=\"sortable\"");
  EXPECT_EQ(images, 2u);  // Fig. 4 and the cost front; the maps are inline SVG.
  EXPECT_NE(dom.find(fmt::format("data-images-loaded=\"{0}/{0}\"", images)), std::string::npos)
      << dom.substr(0, dom.find("<h1>"));
  EXPECT_NE(dom.find(fmt::format("data-sortable-tables=\"{}\"", tables)), std::string::npos);
  // The cost front's points as a table, not terminal text.
  for (const char* id : {"outcomes", "points", "provenance", "cost-table"}) {
    EXPECT_NE(dom.find(std::string("<table class=\"sortable\" id=\"") + id), std::string::npos)
        << id;
  }
  EXPECT_EQ(html.find("<pre>R_k ="), std::string::npos);
  for (const char* section : {"criteria", "maps", "fig4", "cost", "study-file"}) {
    EXPECT_NE(dom.find(std::string("href=\"#") + section + "\""), std::string::npos) << section;
  }
  // quick: 11 R_k by 7 R_ftrunc on the first map, 11 R_k by 4 dt factors on the second, and
  // the first's grid again on each metric map (Err, SRf, cost at least).
  const std::size_t metric_maps = Count(dom, "<div class=\"metric-map\"");
  EXPECT_GE(metric_maps, 3u);
  EXPECT_EQ(Count(dom, "<rect class=\"cell\""), 11u * 7u + 11u * 4u + metric_maps * 11u * 7u);
  // Each map's gnuplot figure is still written, and linked.
  for (const char* png : {"map_err.png", "map_srf.png", "map_cost.png", "map_status_dt.png"}) {
    EXPECT_TRUE(std::filesystem::exists(at.dir / "report" / png)) << png;
    EXPECT_NE(html.find(std::string("href=\"") + png + "\""), std::string::npos) << png;
  }
  // Every diverged cell carries a cross, every undecided one a diamond (both paths), every
  // unstable one a square; the dt map's bound names omega itself.
  EXPECT_GT(Count(html, "data-status=\"diverged\""), 0u);
  EXPECT_EQ(Count(html, "<path class=\"marker\""),
            Count(html, "data-status=\"diverged\"") + Count(html, "data-outcome=\"undecided\""));
  EXPECT_EQ(Count(html, "<rect class=\"marker\""), Count(html, "data-status=\"unstable\""));
  EXPECT_NE(html.find("dt = 2 / \u03c9<sub>max</sub>"), std::string::npos);
  // Each score's interactive map draws its own boundary: Err's fit rises above the knee, SRf
  // passes at every R_k's smallest truncation (no fit), PFr has no threshold.
  auto metric_map = [&](const std::string& metric) {
    const auto start = html.find("<div class=\"metric-map\" data-metric=\"" + metric + "\"");
    EXPECT_NE(start, std::string::npos) << metric;
    return html.substr(start, html.find("</div>", start) - start);
  };
  EXPECT_EQ(Count(metric_map("err"), "<polyline class=\"boundary\""), 1u);
  EXPECT_EQ(Count(metric_map("srf"), "<polyline class=\"boundary\""), 0u);
  const std::string pfr = metric_map("pfr");
  EXPECT_EQ(Count(pfr, "<polyline class=\"boundary\""), 0u);
  EXPECT_NE(pfr.find("no threshold: no boundary drawn"), std::string::npos) << pfr;
}

void CheckMapCells(const Place& at) {
  const std::string dom = Dom(at, at.dir / "report" / "index.html");
  const std::regex cell(
      "<a href=\"(points/point_(\\d+)\\.html)\"><rect class=\"cell\"[^>]* data-rk=\"([^\"]+)\" "
      "data-rftrunc=\"([^\"]+)\" data-dt=\"[^\"]+\" data-dt-ratio=\"([^\"]+)\" "
      "data-err=\"([^\"]+)\" "
      "data-srf=\"([^\"]+)\" (?:data-[a-z_]+=\"[^\"]+\" )*data-status=\"([^\"]+)\"");
  int checked = 0;
  for (auto it = std::sregex_iterator(dom.begin(), dom.end(), cell); it != std::sregex_iterator();
       ++it, ++checked) {
    const auto& m = *it;
    if (checked % 9 != 0) continue;  // Every ninth cell against the database.
    const std::string id = m[2];
    EXPECT_NEAR(std::stod(m[3]), std::stod(Stored(at, "r_k", id)), 1e-5 * std::stod(m[3])) << id;
    EXPECT_NEAR(std::stod(m[4]), std::stod(Stored(at, "r_ftrunc", id)), 1e-5 * std::stod(m[4]))
        << id;
    EXPECT_EQ(m[8].str(), Stored(at, "status", id)) << id;
    const std::string err = Stored(at, "err", id);
    if (err.empty()) {
      EXPECT_EQ(m[6].str(), "not scored") << id;
    } else {
      EXPECT_NEAR(std::stod(m[6]), std::stod(err), 5e-5) << id;
    }
    EXPECT_TRUE(std::filesystem::exists(at.dir / "report" / m[1].str())) << m[1];
  }
  const int metric_maps = static_cast<int>(Count(dom, "<div class=\"metric-map\""));
  EXPECT_EQ(checked, 11 * 7 + 11 * 4 + metric_maps * 11 * 7);
}

// The metric switch shows one metric map at a time, and the Err map's cells title the stored
// Err of their points.
void CheckMetricSwitch(const Place& at) {
  std::string html = ReadBytes((at.dir / "report" / "index.html").string());
  const std::string chooser = R"(<script>
function shown() {
  return Array.from(document.querySelectorAll('.metric-map')).filter(function (m) {
    return m.getBoundingClientRect().height > 0;
  }).map(function (m) { return m.dataset.metric; }).join(',');
}
var choice = document.querySelector('select.metric-switch[data-maps="map-metric"]');
document.body.dataset.before = shown();
choice.value = 'srf';
choice.dispatchEvent(new Event('change'));
document.body.dataset.after = shown();
</script></body>)";
  html.replace(html.rfind("</body>"), 7, chooser);
  const auto copy = at.dir / "report" / "switch_check.html";
  WriteText(copy.string(), html);
  const std::string dom = Dom(at, copy);
  EXPECT_NE(dom.find("data-before=\"err\""), std::string::npos) << dom.substr(0, 400);
  EXPECT_NE(dom.find("data-after=\"srf\""), std::string::npos) << dom.substr(0, 400);

  const auto start = dom.find("<svg class=\"map\" id=\"map-metric-err\"");
  ASSERT_NE(start, std::string::npos);
  const std::string err_map = dom.substr(start, dom.find("</svg>", start) - start);
  const std::regex cell("data-point-id=\"(\\d+)\"[^>]*><title>Err = ([^;]+);");
  int checked = 0;
  for (auto it = std::sregex_iterator(err_map.begin(), err_map.end(), cell);
       it != std::sregex_iterator() && checked < 5; ++it, ++checked) {
    const std::string id = (*it)[1];
    EXPECT_NEAR(std::stod((*it)[2]), std::stod(Stored(at, "err", id)), 1e-5 * std::stod((*it)[2]))
        << id;
  }
  EXPECT_EQ(checked, 5) << "no Err in the cells' titles";
}

void CheckSortOnClick(const Place& at) {
  // A copy of the page with a script that clicks the Err header twice, as a user would, and
  // records the column after each click.
  std::string html = ReadBytes((at.dir / "report" / "index.html").string());
  const std::string clicker = R"(<script>
var table = document.getElementById('points-table');
var headers = Array.from(table.tHead.rows[0].cells);
var column = headers.findIndex(function (h) { return h.textContent === 'err'; });
function values() {
  return Array.from(table.tBodies[0].rows).map(function (r) {
    return r.cells[column].getAttribute('data-sort') || '';
  }).join(',');
}
headers[column].click();
document.body.dataset.ascending = headers[column].getAttribute('aria-sort') + ':' + values();
headers[column].click();
document.body.dataset.descending = headers[column].getAttribute('aria-sort') + ':' + values();
</script></body>)";
  html.replace(html.rfind("</body>"), 7, clicker);
  const auto copy = at.dir / "report" / "sort_check.html";
  WriteText(copy.string(), html);
  const std::string dom = Dom(at, copy);
  for (const std::string order : {"ascending", "descending"}) {
    const std::regex attribute("data-" + order + "=\"" + order + ":([^\"]*)\"");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(dom, m, attribute)) << order;
    std::vector<double> column;
    std::stringstream list(m[1].str());
    for (std::string v; std::getline(list, v, ',');) {
      if (!v.empty()) column.push_back(std::stod(v));
    }
    ASSERT_GT(column.size(), 100u) << order;
    if (order == "descending") std::reverse(column.begin(), column.end());
    EXPECT_TRUE(std::is_sorted(column.begin(), column.end())) << order << ": " << m[1];
  }
}

// The numbers of an attribute of `element` ("x y w h").
std::vector<double> Numbers(const std::string& element, const std::string& attribute) {
  const auto start = element.find(attribute + "=\"") + attribute.size() + 2;
  std::stringstream in(element.substr(start, element.find('"', start) - start));
  std::vector<double> out;
  for (std::string v; in >> v;) out.push_back(std::stod(v));
  return out;
}

// A panel's polyline of `cls` as (t_s, value) pairs, mapped back through its data-box and
// data-range.
std::vector<std::pair<double, double>> DrawnCurve(const std::string& panel,
                                                  const std::string& cls) {
  const auto box = Numbers(panel, "data-box"), range = Numbers(panel, "data-range");
  const auto line = panel.find("<polyline class=\"" + cls + "\"");
  EXPECT_NE(line, std::string::npos) << cls;
  const std::string polyline = panel.substr(line);
  const auto points = polyline.find("points=\"") + 8;
  std::stringstream vertices(polyline.substr(points, polyline.find('"', points) - points));
  std::vector<std::pair<double, double>> curve;
  for (std::string v; vertices >> v;) {
    const double x = std::stod(v.substr(0, v.find(','))), y = std::stod(v.substr(v.find(',') + 1));
    curve.emplace_back(range[0] + (x - box[0]) / box[2] * (range[1] - range[0]),
                       range[2] + (box[1] + box[3] - y) / box[3] * (range[3] - range[2]));
  }
  return curve;
}

// The panel of `quantity` in a page's Fig. 3.
std::string Panel(const std::string& page, const std::string& quantity) {
  const auto start = page.find("<g class=\"panel\" data-quantity=\"" + quantity + "\"");
  EXPECT_NE(start, std::string::npos) << quantity;
  return page.substr(start, page.find("\n</g>\n", start) - start);
}

// The drawn reference force of a point's Fig. 3 against its stored reference: the first sample
// and the largest force, within the rounding of the SVG's coordinates (0.05 units); every curve
// within 2 * kFig3Columns vertices.
void CheckFigureAgainstStoredReference(const Place& at, const std::string& page,
                                       const std::string& id) {
  const auto csv = at.dir / ("reference_" + id + ".csv");
  const auto exported =
      RunShockmap("export reference --db " + at.db + " --point " + id + " --out " + csv.string());
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  std::stringstream rows(ReadBytes(csv.string()));
  std::string line;
  std::getline(rows, line);
  double first_tip = NAN, max_force = -INFINITY;
  while (std::getline(rows, line)) {
    std::stringstream fields(line);
    std::string t, tip, force;
    std::getline(fields, t, ',');
    std::getline(fields, tip, ',');
    std::getline(fields, force, ',');
    if (std::isnan(first_tip)) first_tip = std::stod(tip);
    max_force = std::max(max_force, std::stod(force));
  }
  const std::string force_panel = Panel(page, "force"), tip_panel = Panel(page, "tip");
  const auto range = Numbers(force_panel, "data-range"), box = Numbers(force_panel, "data-box");
  const auto force = DrawnCurve(force_panel, "reference");
  ASSERT_FALSE(force.empty());
  double drawn_max = -INFINITY;
  for (const auto& v : force) drawn_max = std::max(drawn_max, v.second);
  EXPECT_GT(max_force, 0.0) << "the point's reference has no contact";
  EXPECT_NEAR(drawn_max, max_force / 1e3, 0.05 / box[3] * (range[3] - range[2]) + 1e-12);
  const auto tip = DrawnCurve(tip_panel, "reference");
  const auto tip_range = Numbers(tip_panel, "data-range"), tip_box = Numbers(tip_panel, "data-box");
  EXPECT_NEAR(tip.front().first, 0.0, 0.05 / tip_box[2] * tip_range[1]);
  EXPECT_NEAR(tip.front().second, first_tip * 1e3,
              0.05 / tip_box[3] * (tip_range[3] - tip_range[2]) + 1e-12);
  for (const std::string& p : {force_panel, tip_panel}) {
    for (const std::string cls : {"reference", "numerical"}) {
      EXPECT_LE(DrawnCurve(p, cls).size(), 2 * shockmap::kFig3Columns) << cls;
    }
  }
}

void CheckPointPage(const Place& at) {
  // A point whose Fig. 3 is also written as files: its page links them, and its command
  // recomputes the stored Err.
  std::string page_path;
  for (const auto& entry : std::filesystem::directory_iterator(at.dir / "report" / "points")) {
    if (entry.is_directory() && std::filesystem::exists(entry.path() / "fig3.png")) {
      page_path = entry.path().string() + ".html";
      break;
    }
  }
  ASSERT_FALSE(page_path.empty()) << "no Fig. 3 was written as files";
  const std::string page = ReadBytes(page_path);
  const std::string id = std::filesystem::path(page_path).stem().string().substr(6);
  EXPECT_NE(page.find("href=\"point_" + id + "/fig3.png\""), std::string::npos);
  EXPECT_NE(page.find("href=\"point_" + id + "/numerical.csv\""), std::string::npos);
  // In the browser, the page shows its figure: two panels, each with both curves.
  const std::string dom = Dom(at, page_path);
  EXPECT_EQ(Count(dom, "<svg class=\"fig3\""), 1u);
  EXPECT_EQ(Count(dom, "<g class=\"panel\""), 2u);
  EXPECT_EQ(Count(dom, "<polyline class=\"reference\""), 2u);
  EXPECT_EQ(Count(dom, "<polyline class=\"numerical\""), 2u);
  std::smatch command;
  ASSERT_TRUE(std::regex_search(page, command, std::regex("shockmap compare ([^<]*) --out ")))
      << page;
  const auto run = RunShockmap("compare " + command[1].str() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::smatch err;
  ASSERT_TRUE(std::regex_search(run.output, err, std::regex("\"err\": ([0-9.e+-]+)")))
      << run.output;
  EXPECT_NEAR(std::stod(err[1]), std::stod(Stored(at, "err", id)), 1e-9) << command[1];
  CheckFigureAgainstStoredReference(at, page, id);

  // Every point page draws its Fig. 3, two panels, from a run whose recomputed scores are the
  // stored ones; prints its command once; a diverged run says where it stopped.
  std::size_t pages = 0, diverged = 0;
  for (const auto& entry : std::filesystem::directory_iterator(at.dir / "report" / "points")) {
    if (entry.path().extension() != ".html") continue;
    const std::string p = ReadBytes(entry.path().string());
    ++pages;
    EXPECT_EQ(Count(p, "<svg class=\"fig3\""), 1u) << entry.path();
    EXPECT_EQ(Count(p, "<g class=\"panel\""), 2u) << entry.path();
    EXPECT_EQ(Count(p, "the stored scores, exactly"), 1u) << entry.path();
    EXPECT_EQ(Count(p, "shockmap compare "), 1u) << entry.path();
    EXPECT_EQ(p.find("fig3-absent"), std::string::npos) << entry.path();
    diverged += Count(p, "The run stopped (diverged");
  }
  EXPECT_EQ(pages, 308u);
  EXPECT_EQ(std::to_string(diverged), StatusCount(at, "diverged"));
}

// The verdict opens the report and its counts are the database's.
void CheckVerdict(const Place& at) {
  const std::string dom = Dom(at, at.dir / "report" / "index.html");
  const auto verdict = dom.find("id=\"verdict-text\"");
  ASSERT_NE(verdict, std::string::npos);
  EXPECT_LT(verdict, dom.find("id=\"outcomes\"")) << "the verdict is not at the top";
  const std::string text = dom.substr(verdict, dom.find("</p>", verdict) - verdict);
  EXPECT_NE(text.find("judged by Err &lt;= 0.1, SRf &gt;= 0.8"), std::string::npos) << text;
  EXPECT_NE(text.find("Validity rule: R_ftrunc &gt;= "), std::string::npos) << text;
  EXPECT_NE(text.find("Time-step margin: runs pass up to dt = "), std::string::npos) << text;
  auto count = [&](const std::string& status) { return StatusCount(at, status); };
  EXPECT_NE(text.find("Of 308 points, " + count("ok") + " ran to the end"), std::string::npos)
      << text;
  EXPECT_NE(text.find("; " + count("diverged") + " diverged ("), std::string::npos) << text;
  // Points whose verdict the spread leaves undecided are counted apart from those a score fails.
  const CriteriaOptions thresholds;
  const auto points = LoadCriteriaPoints(at.db, "quick");
  const auto undecided =
      std::ranges::count_if(points, [&](const ScoredPoint& p) { return thresholds.Undecided(p); });
  EXPECT_EQ(text.find(fmt::format("{} undecided: a score's spread over perturbed runs",
                                  undecided)) != std::string::npos,
            undecided > 0)
      << text;
  // The criteria are a table, one row per studied R_k.
  EXPECT_EQ(TableRowCount(dom, "criteria-table"), 11u);
}

// Typing into the points table's filter hides the other rows; its CSV link then holds the header
// and the rows shown, reals at full precision.
void CheckFilterAndCsv(const Place& at) {
  std::string html = ReadBytes((at.dir / "report" / "index.html").string());
  const std::string typist = R"(<script>
var box = document.querySelector('input.table-filter[data-table="points-table"]');
box.value = 'diverged';
box.dispatchEvent(new Event('input'));
var rows = Array.from(document.getElementById('points-table').tBodies[0].rows);
document.body.dataset.shown = rows.filter(function (r) { return !r.hidden; }).length;
document.addEventListener('click', function (e) { e.preventDefault(); });
var link = document.querySelector('a.table-csv[data-table="points-table"]');
link.click();
var out = document.createElement('pre');
out.id = 'csv-out';
out.textContent = decodeURIComponent(link.href.slice(link.href.indexOf(',') + 1));
document.body.appendChild(out);
</script></body>)";
  html.replace(html.rfind("</body>"), 7, typist);
  const auto copy = at.dir / "report" / "filter_check.html";
  WriteText(copy.string(), html);
  const std::string dom = Dom(at, copy);
  const std::string diverged = StatusCount(at, "diverged");
  EXPECT_NE(dom.find("data-shown=\"" + diverged + "\""), std::string::npos) << diverged;
  const auto start = dom.find("<pre id=\"csv-out\">");
  ASSERT_NE(start, std::string::npos);
  std::stringstream csv(dom.substr(start + 18, dom.find("</pre>", start) - start - 18));
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 1 + std::stoul(diverged));
  EXPECT_EQ(lines[0].rfind("point_id,r_k,r_ftrunc,scheme,", 0), 0u) << lines[0];
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_NE(lines[i].find(",diverged,"), std::string::npos) << lines[i];
    // Each row's R_ftrunc at full precision, as stored.
    std::stringstream fields(lines[i]);
    std::string id, r_k, r_ftrunc;
    std::getline(fields, id, ',');
    std::getline(fields, r_k, ',');
    std::getline(fields, r_ftrunc, ',');
    EXPECT_EQ(std::stod(r_ftrunc), std::stod(Stored(at, "r_ftrunc", id))) << lines[i];
    if (i >= 3) break;  // A few rows against the database.
  }
}

class QuickStudyViews : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    at_.dir =
        std::filesystem::temp_directory_path() / ("shockmap_report_" + std::to_string(getpid()));
    std::filesystem::remove_all(at_.dir);
    std::filesystem::create_directories(at_.dir);
    at_.db = (at_.dir / "study.db").string();
    const auto run = RunShockmap("study run " + std::string(SHOCKMAP_SOURCE_DIR) +
                                 "/studies/quick.json --db " + at_.db + " --quiet");
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(at_.dir); }

  static inline Place at_;
};

TEST_F(QuickStudyViews, ReportOpensInHeadlessChromiumSortsAndLinksItsPoints) {
  const auto report =
      RunShockmap("report --db " + at_.db + " --out " + (at_.dir / "report").string());
  ASSERT_EQ(report.exit_code, 0) << report.output;
  CheckIndex(at_);
  CheckMapCells(at_);
  CheckSortOnClick(at_);
  CheckMetricSwitch(at_);
  CheckVerdict(at_);
  CheckFilterAndCsv(at_);
  CheckPointPage(at_);
  // The maps' scripts run from their own folder.
  std::filesystem::remove(at_.dir / "report" / "map_err.png");
  const auto gnuplot = RunShell("cd " + (at_.dir / "report").string() + " && gnuplot map_err.gp");
  EXPECT_EQ(gnuplot.exit_code, 0) << gnuplot.output;
  EXPECT_TRUE(std::filesystem::exists(at_.dir / "report" / "map_err.png"));
}

// The cells of each body row of the table `id` in `dom`: (attributes, text) per cell.
using Cells = std::vector<std::pair<std::string, std::string>>;
std::vector<Cells> TableRows(const std::string& dom, const std::string& id) {
  const auto start = dom.find("id=\"" + id + "\"");
  EXPECT_NE(start, std::string::npos) << id;
  if (start == std::string::npos) return {};
  const auto body = dom.find("<tbody>", start);
  const std::string rows = dom.substr(body, dom.find("</tbody>", body) - body);
  const std::regex row("<tr>(.*?)</tr>"), cell("<td([^>]*)>(.*?)</td>");
  std::vector<Cells> out;
  for (auto r = std::sregex_iterator(rows.begin(), rows.end(), row); r != std::sregex_iterator();
       ++r) {
    const std::string text = (*r)[1];
    auto& cells = out.emplace_back();
    for (auto c = std::sregex_iterator(text.begin(), text.end(), cell); c != std::sregex_iterator();
         ++c) {
      cells.emplace_back((*c)[1], std::regex_replace((*c)[2].str(), std::regex("&quot;"), "\""));
    }
  }
  return out;
}

// A scene study named with markup: the report has its sections, the points with their swept
// parameters as columns, the validity map over them, the contact-force map, and shows the name
// as text.
TEST(SceneStudyReport, HasItsTablesAndContactForceMapAndEscapesTheName) {
  const Place at = FreshPlace("shockmap_scene_report", "s.db");
  const nlohmann::json study = {
      {"name", "<b>spring</b> & \"q\""},
      {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json"},
      {"sweep", {{"solver.r_ftrunc", {10, 300}}, {"solver.dt.factor", {0.1, 0.5}}}},
      {"reference", {{"solver.r_ftrunc", 1000}}},
      {"scoring", {{"displacement", "tip"}, {"zone", "tip_spring"}, {"rest_duration_s", 0.0052}}}};
  WriteText((at.dir / "study.json").string(), study.dump());
  const auto run =
      RunShockmap("study run --quiet " + (at.dir / "study.json").string() + " --db " + at.db);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto report =
      RunShockmap("report --db " + at.db + " --out " + (at.dir / "report").string());
  ASSERT_EQ(report.exit_code, 0) << report.output;
  const auto page = at.dir / "report" / "index.html";
  const std::string html = ReadBytes(page.string());
  EXPECT_EQ(html.find("<b>spring"), std::string::npos) << "the study name went in as markup";
  EXPECT_NE(html.find("&lt;b&gt;spring&lt;/b&gt; &amp; &quot;q&quot;"), std::string::npos);
  const std::string dom = Dom(at, page);
  EXPECT_NE(dom.find("data-images-loaded=\"1/1\""), std::string::npos) << dom.substr(0, 400);
  EXPECT_NE(dom.find("data-sortable-tables=\"3\""), std::string::npos);
  EXPECT_NE(dom.find("<th data-sort-method=\"real\" role=\"columnheader\" "
                     "tabindex=\"0\">solver.r_<wbr>ftrunc</th>"),
            std::string::npos)
      << dom;
  const auto points_table = dom.find("id=\"points-table\"");
  const std::string rows =
      dom.substr(points_table, dom.find("</table>", points_table) - points_table);
  EXPECT_EQ(Count(rows, "<tr>"), 1u + 4u);  // The header and the four points.
  // Passes and fails counted apart from the run status, each point's outcome beside its status.
  std::smatch counts;
  ASSERT_TRUE(std::regex_search(
      dom, counts,
      std::regex("(\\d+) of 4 points pass Err &lt;= 0.1, SRf &gt;= 0.8; (\\d+) ran to the end "
                 "and fail them.*; (\\d+) did not run to the end")));
  EXPECT_EQ(std::stoi(counts[1]) + std::stoi(counts[2]) + std::stoi(counts[3]), 4);
  EXPECT_EQ(std::stoi(counts[1]), static_cast<int>(Count(rows, "<td>passes</td>")));
  EXPECT_EQ(std::stoi(counts[2]), static_cast<int>(Count(rows, "<td>fails thresholds</td>")));
  // The validity map over the swept settings: a cell per point, R_ftrunc across and dt up, each
  // cell's outcome the one the points table gives that point.
  std::map<std::string, std::string> outcome_of;  // By point id, from the table.
  for (const Cells& row : TableRows(dom, "points-table")) {
    outcome_of[row[0].second] = row[3].second;
  }
  const std::regex cell(
      "<rect class=\"cell\"[^>]* data-point-id=\"(\\d+)\" "
      "data-parameters=\"solver.dt.factor=([0-9.]+);solver.r_ftrunc=(\\d+)\" "
      "data-outcome=\"([^\"]+)\"");
  std::set<std::string> drawn;
  for (auto c = std::sregex_iterator(html.begin(), html.end(), cell); c != std::sregex_iterator();
       ++c) {
    EXPECT_EQ((*c)[4].str(), outcome_of[(*c)[1].str()]) << "point " << (*c)[1];
    drawn.insert((*c)[3].str() + "/" + (*c)[2].str());
  }
  EXPECT_EQ(drawn, (std::set<std::string>{"10/0.1", "10/0.5", "300/0.1", "300/0.5"}));
  EXPECT_EQ(Count(html, "<svg class=\"sweep-map\""), 1u);
  EXPECT_NE(dom.find("href=\"#contact-forces\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(at.dir / "report" / "contact_forces_1.png"));
  std::filesystem::remove_all(at.dir);
}

// The header cells of the table `id` in `dom`, as text.
std::vector<std::string> TableColumns(const std::string& dom, const std::string& id) {
  const auto start = dom.find("id=\"" + id + "\"");
  const auto head = dom.find("<thead>", start);
  const std::string header = dom.substr(head, dom.find("</thead>", head) - head);
  const std::regex th("<th[^>]*>((?:[^<]|<wbr>)*)</th>");
  std::vector<std::string> columns;
  for (auto h = std::sregex_iterator(header.begin(), header.end(), th); h != std::sregex_iterator();
       ++h) {
    columns.push_back(std::regex_replace((*h)[1].str(), std::regex("<wbr>"), ""));
  }
  return columns;
}

// A small ensemble named with markup (the row bundle over 0.03 s, two clearance states, two
// truncations): the report's table of the hottest zones holds, per state and setting, the zone
// and the P95 that `shockmap sizing --format json` prints, every picture loads, and the name
// and the description show as text.
TEST(EnsembleStudyReport, SizingTableMatchesTheSizingCommandAndEveryPictureLoads) {
  const Place at = FreshPlace("shockmap_ensemble_report", "e.db");
  const nlohmann::json study = {
      {"kind", "scene_ensemble"},
      {"name", "<b>small</b> & \"q\""},
      {"description", "row <i>bundle</i>"},
      {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json"},
      {"members", 12},
      {"seed", 11},
      {"window_s", 0.03},
      {"impact_statistics", {{"rest_duration_s", 0.002}}},
      {"draws", {{"effects.base_motion.half_sine.amplitude_m_s2", {{"normal", {{"std", 9.81}}}}}}},
      {"clearance_states",
       {{{"name", "new"}, {"pin_gap_m", {{"mean", 5e-5}, {"std", 5e-6}}}},
        {{"name", "worn"}, {"pin_gap_m", {{"mean", 1e-5}, {"std", 3e-5}, {"min", -4e-5}}}}}},
      {"settings", {{"solver.r_ftrunc", {100, 1000}}}},
      {"refined", {{"solver.r_ftrunc", 1000}}}};
  WriteText((at.dir / "study.json").string(), study.dump());
  const auto run = RunShockmap("study run --quiet --jobs 2 " + (at.dir / "study.json").string() +
                               " --db " + at.db);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto report =
      RunShockmap("report --db " + at.db + " --out " + (at.dir / "report").string());
  ASSERT_EQ(report.exit_code, 0) << report.output;
  const auto sizing = RunShockmap("sizing --db " + at.db + " --format json");
  ASSERT_EQ(sizing.exit_code, 0) << sizing.output;
  // (state, setting, family) -> the family's hottest zone.
  std::map<std::tuple<std::string, std::string, std::string>, nlohmann::json> hottest;
  for (const auto& row : nlohmann::json::parse(sizing.output)) {
    if (row["family_hottest"] != 1) continue;
    // The report names a setting by its values: {"solver.r_ftrunc":1000} (refined) is
    // solver.r_ftrunc = 1000 (refined).
    std::string setting = row["setting"];
    const std::string refined = " (refined)";
    const bool is_refined = setting.ends_with(refined);
    if (is_refined) setting.resize(setting.size() - refined.size());
    std::string name;
    const nlohmann::json values = nlohmann::json::parse(setting);
    for (const auto& [path, value] : values.items()) {
      name += (name.empty() ? "" : ", ") + path + " = " + value.dump();
    }
    hottest[{row["state"], name + (is_refined ? refined : ""), row["family"]}] = row;
  }
  ASSERT_EQ(hottest.size(), 12u);  // Two states by two settings by three zone families.

  // The terminal's table: 12 members have no Wilks limit and cannot bound a P95 from above; it
  // says how many would, shows no infinity and fits 120 characters.
  const auto table = RunShockmap("sizing --db " + at.db);
  ASSERT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find("a one-sided P95 at 95 % confidence needs at least 59 members"),
            std::string::npos)
      << table.output;
  EXPECT_EQ(table.output.find("inf"), std::string::npos) << table.output;
  std::istringstream lines(table.output);
  for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 120u) << line;
  // An ensemble is no study of the paper's problem: map and criteria say so and what to use.
  for (const std::string command : {"map", "criteria derive"}) {
    const auto named =
        RunShockmap(command + " --db " + at.db + " '" + study["name"].get<std::string>() + "'");
    EXPECT_EQ(named.exit_code, 2) << named.output;
    EXPECT_NE(named.output.find("is of kind \"scene_ensemble\""), std::string::npos)
        << named.output;
    EXPECT_NE(named.output.find("shockmap sizing"), std::string::npos) << named.output;
    const auto unnamed = RunShockmap(command + " --db " + at.db);
    EXPECT_EQ(unnamed.exit_code, 2) << unnamed.output;
    EXPECT_NE(unnamed.output.find("0 studies of the paper's problem"), std::string::npos)
        << unnamed.output;
    EXPECT_EQ(unnamed.output.find("small"), std::string::npos) << "listed as eligible";
  }

  const auto page = at.dir / "report" / "index.html";
  const std::string html = ReadBytes(page.string());
  EXPECT_EQ(html.find("<b>small"), std::string::npos) << "the study name went in as markup";
  EXPECT_EQ(html.find("<i>bundle"), std::string::npos) << "the description went in as markup";
  const std::string dom = Dom(at, page);
  // Per state its map, and per family (wire, pad, pin-wrapper) its convergence and histogram;
  // then per family the states and the settings.
  EXPECT_EQ(Count(html, "<img "), 2u * (1u + 3u * 2u) + 3u * 2u);
  EXPECT_NE(dom.find("data-images-loaded=\"20/20\""), std::string::npos) << dom.substr(0, 600);
  // Twelve members leave the P95's upper side unbounded: an empty cell, never "inf".
  EXPECT_EQ(html.find(">inf<"), std::string::npos);
  EXPECT_NE(html.find("data-sort=\"Infinity\" title=\"unbounded\"></td>"), std::string::npos);
  EXPECT_NE(dom.find("data-sortable-tables=\"4\""), std::string::npos);
  const auto columns = TableColumns(dom, "sizing-hottest-table");
  const auto p95 = std::ranges::find(columns, "p95_n") - columns.begin();
  ASSERT_LT(static_cast<std::size_t>(p95), columns.size());
  const auto rows = TableRows(dom, "sizing-hottest-table");
  ASSERT_EQ(rows.size(), hottest.size());
  for (const Cells& row : rows) {
    ASSERT_GT(row.size(), static_cast<std::size_t>(p95));
    const auto expected = hottest.find({row[0].second, row[1].second, row[4].second});
    ASSERT_NE(expected, hottest.end()) << row[0].second << " " << row[1].second;
    EXPECT_EQ(row[3].second, expected->second["zone"]);
    std::smatch full;
    ASSERT_TRUE(std::regex_search(row[p95].first, full, std::regex("data-sort=\"([^\"]+)\"")));
    EXPECT_EQ(std::stod(full[1]), expected->second["p95_n"].get<double>()) << row[1].second;
  }
  for (const char* id : {"sizing-zones-table", "impacts-table", "provenance-table"}) {
    EXPECT_NE(dom.find(std::string("<table class=\"sortable\" id=\"") + id), std::string::npos)
        << id;
  }
  EXPECT_EQ(Count(dom, "against the refined setting:"), 2u);  // One line per state.
  // The pictures' legends name only what is drawn: a band where some interval is bounded on
  // both sides, an upward arrow where some upper side is open; states are never joined.
  for (const std::string state : {"new", "worn"}) {
    const auto dir = at.dir / "report" / "sizing";
    const std::string convergence = "convergence_" + state + "_pin-pin_wire";
    const auto rows = DataBlock((dir / (convergence + ".dat")).string(), 0);
    const std::string script = ReadBytes((dir / (convergence + ".gp")).string());
    const bool closed = std::ranges::any_of(rows, [](auto& r) { return r[4] > 0 && r[5] > 0; });
    const bool open_up = std::ranges::any_of(rows, [](auto& r) { return r[5] == 0; });
    EXPECT_EQ(script.find("both sides bounded") != std::string::npos, closed) << script;
    EXPECT_EQ(script.find("open upward") != std::string::npos, open_up) << script;
    EXPECT_EQ(script.find("set key below"), script.find("set key")) << script;
  }
  for (const std::string family : {"pin-pin_wire", "duct_pad", "pin-wrapper"}) {
    const std::string states =
        ReadBytes((at.dir / "report" / "sizing" / ("states_" + family + ".gp")).string());
    EXPECT_EQ(states.find("lines"), std::string::npos) << states;
  }
  // Each histogram's count axis reaches above its tallest bar, whose top is not the frame.
  int histograms = 0;
  for (const auto& entry : std::filesystem::directory_iterator(at.dir / "report" / "sizing")) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with("histogram_") || entry.path().extension() != ".gp") continue;
    ++histograms;
    const std::string script = ReadBytes(entry.path().string());
    std::smatch top;
    ASSERT_TRUE(std::regex_search(script, top, std::regex("set yrange \\[0:([0-9.]+)\\]")))
        << script;
    double tallest = 0.0;
    for (const auto& bin :
         DataBlock(std::filesystem::path(entry.path()).replace_extension(".dat").string(), 0)) {
      tallest = std::max(tallest, bin[1]);
    }
    EXPECT_GT(std::stod(top[1]), tallest) << name;
  }
  EXPECT_EQ(histograms, 2 * 3);
  std::filesystem::remove_all(at.dir);
}

// An ensemble at one numerical setting (the scene's own): its tables name that setting once, in
// their captions, and have no column repeating it on every row.
TEST(EnsembleStudyReport, OneSettingIsNamedInTheCaptionNotOnEveryRow) {
  const Place at = FreshPlace("shockmap_one_setting", "e.db");
  const nlohmann::json study = {
      {"kind", "scene_ensemble"},
      {"name", "one_setting"},
      {"scene", std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_row.json"},
      {"members", 6},
      {"seed", 3},
      {"window_s", 0.03},
      {"impact_statistics", {{"rest_duration_s", 0.002}}},
      {"draws", {{"effects.base_motion.half_sine.amplitude_m_s2", {{"normal", {{"std", 9.81}}}}}}},
      {"clearance_states", {{{"name", "new"}, {"pin_gap_m", {{"mean", 5e-5}, {"std", 5e-6}}}}}}};
  WriteText((at.dir / "study.json").string(), study.dump());
  const auto run = RunShockmap("study run --quiet --jobs 2 " + (at.dir / "study.json").string() +
                               " --db " + at.db);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto report =
      RunShockmap("report --db " + at.db + " --out " + (at.dir / "report").string());
  ASSERT_EQ(report.exit_code, 0) << report.output;
  const std::string html = ReadBytes((at.dir / "report" / "index.html").string());
  for (const std::string id : {"sizing-hottest-table", "sizing-zones-table", "impacts-table"}) {
    const auto columns = TableColumns(html, id);
    ASSERT_FALSE(columns.empty()) << id;
    EXPECT_EQ(std::ranges::count(columns, "setting"), 0) << id;
    const auto table = html.find("id=\"" + id + "\"");
    const auto caption = html.find("<caption>", table);
    EXPECT_NE(html.substr(caption, html.find("</caption>", caption) - caption)
                  .find("at the one setting: the scene&#39;s own: R_ftrunc = "),
              std::string::npos)
        << id;
  }
  std::filesystem::remove_all(at.dir);
}

// A cross-section map of a bundle bending in both planes explains every mark in one legend:
// the beam axes, the zones between two pins, those between a pin and the wrapper (a mark of
// their own), the zones never in contact.
TEST(ContactForceMap, CrossSectionsShareALegendThatNamesEveryMark) {
  const Scene scene = LoadScene(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/bundle_hex_7.json");
  ASSERT_EQ(scene.planes, BendingPlanes::kBoth);
  std::vector<double> force;
  int wrapper_zones = 0;
  for (const SceneZone& z : scene.zones) {
    const bool wrapper =
        z.beam_b >= 0 && FamilyOfZone(scene.beams[z.beam_a].name, scene.beams[z.beam_b].name) ==
                             ZoneFamily::kPinWrapper;
    wrapper_zones += wrapper ? 1 : 0;
    force.push_back(force.size() % 5 == 0 ? 0.0 : wrapper ? 200.0 : 100.0);
  }
  ASSERT_GT(wrapper_zones, 0);
  const auto dir =
      std::filesystem::temp_directory_path() / ("shockmap_force_map_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  DrawContactForceMap(scene, force, dir / "map.png");
  const std::string script = ReadBytes((dir / "map.gp").string());
  EXPECT_EQ(Count(script, "set key "), 1u) << script;
  for (const char* mark :
       {"title 'beam axes'", "title 'between two pins (colour scale)'",
        "title 'between a pin and the wrapper (colour scale)'", "title 'never in contact'"}) {
    EXPECT_EQ(Count(script, mark), 1u) << mark;
  }
  const auto zones = DataBlock((dir / "map.zones.dat").string(), 0);
  ASSERT_EQ(zones.size(), scene.zones.size());
  EXPECT_EQ(std::ranges::count_if(zones, [](const auto& z) { return z.size() == 6 && z[5] == 1; }),
            wrapper_zones);
  std::filesystem::remove_all(dir);
}

// Min/max per column keeps every column's extremes in time order, at most two a column, and
// stops at the first non-finite sample (where a diverged run stopped).
TEST(Fig3Svg, MinMaxPerColumnKeepsThePeaksAndStopsWhereTheRunDid) {
  UniformSignal s{0.0, 1e-4, {}};
  for (int i = 0; i < 10000; ++i) s.values.push_back(std::sin(0.01 * i) + (i == 4321 ? 5.0 : 0.0));
  const auto curve = MinMaxPerColumn(s, 0.0, s.EndTime(), 100);
  EXPECT_LE(curve.size(), 200u);
  EXPECT_GE(curve.size(), 100u);
  const auto top = std::ranges::max_element(curve, {}, &CurveVertex::value);
  EXPECT_EQ(top->value, s.values[4321]);
  EXPECT_DOUBLE_EQ(top->t_s, s.TimeAt(4321));
  EXPECT_EQ(std::ranges::min_element(curve, {}, &CurveVertex::value)->value,
            *std::ranges::min_element(s.values));
  EXPECT_TRUE(std::ranges::is_sorted(curve, {}, &CurveVertex::t_s));
  EXPECT_EQ(curve.front().t_s, 0.0);
  EXPECT_DOUBLE_EQ(curve.back().t_s, s.EndTime());

  s.values[5000] = NAN;
  const auto cut = MinMaxPerColumn(s, 0.0, s.EndTime(), 100);
  EXPECT_DOUBLE_EQ(cut.back().t_s, s.TimeAt(4999));
}

// A study from R_k = 1000 up, on R_ftrunc 31.6 to 1000, whose points pass from 3 sqrt(R_k): its
// boundary rises at its first R_k, so its rule says nothing of a smaller R_k. Each failing
// point is counted once, by the scores it fails together: 5 fail, 3 of them SRf as well.
TEST(StudyVerdict, SpeaksOnlyOfTheStudiedRkAndCountsEachFailingPointOnce) {
  std::vector<ScoredPoint> points;
  for (double r_k : {1000.0, 3162.28, 1e4}) {
    for (double r_ftrunc : {31.6228, 100.0, 316.228, 1000.0}) {
      ScoredPoint p;
      p.point_id = static_cast<std::int64_t>(points.size()) + 1;
      p.r_k = r_k;
      p.r_ftrunc = r_ftrunc;
      p.status = RunStatus::kOk;
      p.dt_s = 1e-6;
      p.dt_sharp_s = 1e-5;
      p.scores.Set("err", r_ftrunc >= 3.0 * std::sqrt(r_k) ? 0.05 : 0.3);
      p.scores.Set("srf", r_ftrunc < 50.0 ? 0.5 : 0.95);
      points.push_back(p);
    }
  }
  const ValidityCriteria criteria = DeriveCriteria(points, CriteriaOptions{});
  ASSERT_TRUE(criteria.fit);
  EXPECT_EQ(criteria.fit->knee_r_k, 1000.0);
  const std::string verdict = StudyVerdict("stiff", criteria, points, Table{});
  EXPECT_EQ(verdict.find("below it"), std::string::npos) << verdict;
  EXPECT_EQ(verdict.find("R_ftrunc >= 31.6"), std::string::npos) << verdict;
  EXPECT_NE(verdict.find(" at R_k = 1000 to 1e+04 ("), std::string::npos) << verdict;
  EXPECT_NE(verdict.find("It holds over the studied R_k = 1000 to 1e+04 (3 values) and says "
                         "nothing outside them."),
            std::string::npos)
      << verdict;
  EXPECT_NE(verdict.find("7 pass and 5 fail the thresholds (2 by Err alone, 3 by Err and SRf "
                         "together)"),
            std::string::npos)
      << verdict;
}

TEST(ReportHtml, EscapesWhatComesFromUserFiles) {
  EXPECT_EQ(HtmlEscaped("<script>alert('x') & \"y\"</script>"),
            "&lt;script&gt;alert(&#39;x&#39;) &amp; &quot;y&quot;&lt;/script&gt;");
  Table r;
  r.columns = {"name<", "value"};
  r.rows = {{std::string("<b>study</b>"), 1.5e-3}, {std::string("a&b"), TableCell()}};
  const std::string table = SortableTable(r, "t\"1", "caption <i>");
  EXPECT_EQ(table.find("<b>"), std::string::npos) << table;
  EXPECT_EQ(table.find("<i>"), std::string::npos) << table;
  EXPECT_NE(table.find("id=\"t&quot;1\""), std::string::npos) << table;
  EXPECT_NE(table.find("<th data-sort-method=\"real\">value</th>"), std::string::npos) << table;
  EXPECT_NE(table.find("data-sort=\"0.0015\""), std::string::npos) << table;
}

TEST(ReportHtml, Base64MatchesRfc4648) {
  EXPECT_EQ(Base64(""), "");
  EXPECT_EQ(Base64("f"), "Zg==");
  EXPECT_EQ(Base64("fo"), "Zm8=");
  EXPECT_EQ(Base64("foo"), "Zm9v");
  EXPECT_EQ(Base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(Base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(StatusMap, HasOneCategoryPerRunStatusBeyondOkAndThreeForOk) {
  const auto& categories = OutcomeCategories();
  ASSERT_EQ(categories.size(), kAllRunStatuses.size() + 2);
  CriteriaOptions th;
  ScoredPoint p;
  p.status = RunStatus::kOk;
  p.scores.Set("err", 0.01);
  p.scores.Set("srf", 0.95);
  EXPECT_EQ(categories[OutcomeCategoryOf(p, th)].label, "passes");
  p.scores.Set("err", 0.5);
  EXPECT_EQ(categories[OutcomeCategoryOf(p, th)].label, "fails thresholds");
  p.spread_runs = 5;
  p.spread_low.Set("err", 0.05);
  p.spread_high.Set("err", 0.5);
  EXPECT_EQ(categories[OutcomeCategoryOf(p, th)].label, "undecided");
  for (RunStatus s : kAllRunStatuses) {
    if (s == RunStatus::kOk) continue;
    p.status = s;
    std::string label = ToString(s);
    std::replace(label.begin(), label.end(), '_', ' ');
    EXPECT_EQ(categories[OutcomeCategoryOf(p, th)].label, label);
  }
}

// A point that passes while a finer time step at the same R_k and R_ftrunc fails is flagged and
// kept off the front, however fast; its finer neighbours passing, it is on it.
TEST(CostFront, IsBuiltFromPointsWhoseFinerTimeStepsPassToo) {
  auto point = [](double r_ftrunc, double dt_ratio, double err, double cpu_s) {
    ScoredPoint p;
    p.r_k = 3162.0;
    p.r_ftrunc = r_ftrunc;
    p.status = RunStatus::kOk;
    p.dt_sharp_s = 1e-6;
    p.dt_s = dt_ratio * p.dt_sharp_s;
    p.cpu_s = cpu_s;
    p.scores.Set("err", err);
    p.scores.Set("srf", 1.0);
    return p;
  };
  const std::vector<ScoredPoint> points = {
      point(100, 0.1, 0.108, 0.5), point(100, 0.9, 0.089, 0.05),  // Passes by cancellation.
      point(316, 0.1, 0.020, 1.0), point(316, 0.9, 0.030, 0.1)};  // Passes at both steps.
  const auto tables = BuildCostTables(points, {}, std::nullopt);
  ASSERT_EQ(tables.size(), 1u);
  std::map<std::pair<double, long>, CostRow> rows;  // By R_ftrunc and 10 dt/dt_sharp.
  for (const CostRow& r : tables[0].rows)
    rows[{r.point.r_ftrunc, std::lround(10 * r.point.DtRatio())}] = r;
  const CostRow& cancelled = rows.at({100, 9});
  EXPECT_TRUE(cancelled.passes);
  EXPECT_TRUE(cancelled.fragile);
  EXPECT_FALSE(cancelled.pareto);
  EXPECT_FALSE(rows.at({100, 1}).passes);
  EXPECT_FALSE(rows.at({316, 9}).fragile);
  EXPECT_TRUE(rows.at({316, 9}).pareto);  // The fastest robust point heads the front.
  EXPECT_TRUE(rows.at({316, 1}).pareto);  // More accurate at a higher cost.
  EXPECT_NE(CostSummary(tables).find("fragile"), std::string::npos);
}

// The cells of a dt map: each reaches from the next finer studied ratio up to its own, and the
// cell above the sharp bound starts at the bound.
TEST(MapGrid, DtCellsEndAtTheirStepAndNeverStraddleTheSharpBound) {
  std::vector<ScoredPoint> points;
  for (double ratio : {0.1, 0.5, 0.9, 1.5}) {
    ScoredPoint& p = points.emplace_back();
    p.r_k = 100.0, p.r_ftrunc = 30.0, p.dt_sharp_s = 1e-4, p.dt_s = ratio * 1e-4;
  }
  const MapGrid grid = BuildMapGrid(points, MapAxis::kDt);
  ASSERT_EQ(grid.cells.size(), 4u);
  const std::vector<std::pair<double, double>> expected = {
      {0.1 / std::sqrt(5.0), 0.1}, {0.1, 0.5}, {0.5, 0.9}, {1.0, 1.5}};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(grid.cells[i].y_low, expected[i].first, 1e-9) << grid.cells[i].y;
    EXPECT_NEAR(grid.cells[i].y_high, expected[i].second, 1e-9) << grid.cells[i].y;
  }
}

// The dt map of quick, where runs at 1.5 dt_sharp diverge: diverged cells are white under a
// cross (never a colour of the Err palette), no cell straddles the bound, the bound names omega.
TEST_F(QuickStudyViews, DtMapMarksDivergedRunsAndKeepsCellsOnTheirSideOfTheBound) {
  const auto image = at_.dir / "map_err_dt.png";
  const auto map =
      RunShockmap("map --db " + at_.db + " --metric err --y dt --out " + image.string());
  ASSERT_EQ(map.exit_code, 0) << map.output;
  const std::string script = ReadBytes((at_.dir / "map_err_dt.gp").string());
  const auto crosses = ClausesWith(script, "pt 2 ");
  ASSERT_EQ(crosses.size(), 1u) << script;
  EXPECT_NE(crosses[0].find("title 'diverged (no score)'"), std::string::npos) << crosses[0];
  std::smatch palette;
  ASSERT_TRUE(std::regex_search(script, palette, std::regex("set palette defined \\(([^\n]*)\\)")));
  for (const std::string& fill : ClausesWith(script, "fc rgb")) {
    const std::string colour = fill.substr(fill.find("fc rgb '") + 8, 7);
    EXPECT_EQ(palette[1].str().find(colour), std::string::npos)
        << "a status cell is filled with a colour of the score palette: " << fill;
  }
  EXPECT_NE(script.find("2/\u03c9_{max}"), std::string::npos);
  EXPECT_EQ(script.find("Symbol"), std::string::npos);
  int above = 0, below = 0;
  for (const auto& cell : DataBlock((at_.dir / "map_err_dt.dat").string(), 0)) {
    ASSERT_EQ(cell.size(), 9u);
    EXPECT_DOUBLE_EQ(cell[5], cell[1]) << "a cell reaches above its own dt " << cell[1];
    if (cell[1] > 1.0) {
      EXPECT_GE(cell[4], 1.0) << "a cell above the bound reaches below it";
      ++above;
    } else {
      ++below;
    }
  }
  EXPECT_EQ(above, 11);
  EXPECT_EQ(below, 33);
}

// A score's map draws that score's boundary: the SRf map's triangles are the smallest R_ftrunc
// passing SRf alone at each R_k (lower than Err and SRf together on quick, where every
// truncation passes SRf somewhere), its legend says so; the PFr map, PFr having no threshold,
// draws no boundary and says why, and its colours span the values it shows.
TEST_F(QuickStudyViews, EachScoresMapDrawsItsOwnBoundaryOrSaysItHasNone) {
  const auto draw = [&](const std::string& metric) {
    const auto image = at_.dir / ("own_" + metric + ".png");
    const auto map =
        RunShockmap("map --db " + at_.db + " --metric " + metric + " --out " + image.string());
    EXPECT_EQ(map.exit_code, 0) << map.output;
    return ReadBytes((at_.dir / ("own_" + metric + ".gp")).string());
  };
  const std::string srf = draw("srf"), status = draw("status");
  const auto triangles = ClausesWith(srf, "pt 9 ");
  ASSERT_EQ(triangles.size(), 1u) << srf;
  EXPECT_NE(triangles[0].find("passing SRf >= 0.8 at each R_k"), std::string::npos) << triangles[0];
  EXPECT_EQ(triangles[0].find("Err"), std::string::npos) << triangles[0];
  const auto srf_boundary = DataBlock((at_.dir / "own_srf.dat").string(), 1);
  const auto both_boundary = DataBlock((at_.dir / "own_status.dat").string(), 1);
  CriteriaOptions srf_only;
  srf_only.thresholds = {{"srf", 0.8}};
  const ValidityCriteria expected = DeriveCriteria(LoadCriteriaPoints(at_.db, "quick"), srf_only);
  std::vector<std::vector<double>> expected_rows;
  for (const RkBoundary& b : expected.boundary) {
    if (b.r_ftrunc_min) expected_rows.push_back({b.r_k, *b.r_ftrunc_min});
  }
  ASSERT_EQ(srf_boundary.size(), expected_rows.size());
  for (std::size_t i = 0; i < expected_rows.size(); ++i) {
    EXPECT_NEAR(srf_boundary[i][0], expected_rows[i][0], 1e-9 * expected_rows[i][0]);
    EXPECT_NEAR(srf_boundary[i][1], expected_rows[i][1], 1e-9 * expected_rows[i][1]);
  }
  EXPECT_NE(srf_boundary, both_boundary) << "the SRf map draws the boundary of Err and SRf";

  const std::string pfr = draw("pfr");
  EXPECT_TRUE(ClausesWith(pfr, "pt 9 ").empty()) << pfr;
  EXPECT_TRUE(ClausesWith(pfr, "derived boundary").empty()) << pfr;
  EXPECT_EQ(ClausesWith(pfr, "PFr has no threshold, so no boundary is drawn").size(), 1u) << pfr;
  std::smatch range;
  ASSERT_TRUE(std::regex_search(pfr, range, std::regex("set cbrange \\[([^:]+):([^\\]]+)\\]")));
  double smallest = INFINITY;
  for (const auto& cell : DataBlock((at_.dir / "own_pfr.dat").string(), 0)) {
    if (std::isfinite(cell[6])) smallest = std::min(smallest, cell[6]);
  }
  ASSERT_TRUE(std::isfinite(smallest));
  EXPECT_LE(std::stod(range[1]), smallest) << "PFr values below the colour range look alike";
}

// The dt map names the stability bound only where it draws it: a study whose steps all lie
// below dt_sharp has no bound in its range, and none in its legend.
TEST_F(QuickStudyViews, DtMapNamesTheStabilityBoundOnlyWhenItIsInRange) {
  const auto file = at_.dir / "below_bound.json";
  WriteText(file.string(), R"({"kind": "canonical", "name": "below_bound",
    "scoring": {"window_s": 0.03},
    "grids": [{"rk": [1000, 3000], "rftrunc": [10, 100],
               "dt": {"rule": "sharp", "factor": [0.1, 0.5]}}]})");
  const std::string db = (at_.dir / "below_bound.db").string();
  const auto run = RunShockmap("study run " + file.string() + " --db " + db + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto map = RunShockmap("map --db " + db + " --metric status --y dt --out " +
                               (at_.dir / "below_bound_dt.png").string());
  ASSERT_EQ(map.exit_code, 0) << map.output;
  const std::string below = ReadBytes((at_.dir / "below_bound_dt.gp").string());
  EXPECT_EQ(below.find("stability bound"), std::string::npos) << below;
  // quick reaches 1.5 dt_sharp: its dt map draws and names the bound.
  const auto quick = RunShockmap("map --db " + at_.db + " --metric status --y dt --out " +
                                 (at_.dir / "quick_dt.png").string());
  ASSERT_EQ(quick.exit_code, 0) << quick.output;
  const std::string above = ReadBytes((at_.dir / "quick_dt.gp").string());
  EXPECT_EQ(ClausesWith(above, "sharp stability bound").size(), 1u) << above;
}

// The cost plot's Pareto line is its own data block, joined without breaks, in the order of
// CPU time; its legend names the schemes present and every dt / dt_sharp shown.
TEST_F(QuickStudyViews, CostPlotJoinsTheWholeFrontAndNamesOnlyWhatItDraws) {
  const auto cost =
      RunShockmap("cost --db " + at_.db + " --rk 3000 --out " + (at_.dir / "cost.png").string());
  ASSERT_EQ(cost.exit_code, 0) << cost.output;
  const std::string script = ReadBytes((at_.dir / "cost.gp").string());
  const auto front = ClausesWith(script, "Pareto");
  ASSERT_EQ(front.size(), 1u) << script;
  EXPECT_NE(front[0].find("index 1"), std::string::npos) << front[0];
  EXPECT_EQ(front[0].find("1/0"), std::string::npos) << front[0];
  const auto front_rows = DataBlock((at_.dir / "cost.dat").string(), 1);
  EXPECT_EQ(front_rows.size(), Count(cost.output, " *\n")) << cost.output;
  EXPECT_GE(front_rows.size(), 4u);
  for (std::size_t i = 1; i < front_rows.size(); ++i) {
    EXPECT_GE(front_rows[i][0], front_rows[i - 1][0]);
    EXPECT_LT(front_rows[i][1], front_rows[i - 1][1]);
  }
  EXPECT_EQ(script.find("implicit"), std::string::npos) << "quick has no implicit point";
  // The threshold the points are judged by is drawn; the colour bar is in R_ftrunc and says so.
  EXPECT_EQ(ClausesWith(script, "title 'Err threshold 0.1'").size(), 1u) << script;
  EXPECT_NE(script.find("set logscale cb"), std::string::npos) << script;
  EXPECT_EQ(script.find("log10"), std::string::npos) << script;
  std::set<std::string> ratios;
  for (const auto& row : DataBlock((at_.dir / "cost.dat").string(), 0)) {
    ratios.insert(fmt::format("{:.3g}", row[6]));
  }
  EXPECT_GE(ratios.size(), 2u);
  for (const std::string& ratio : ratios) {
    EXPECT_EQ(ClausesWith(script, "dt = " + ratio + " dt_{sharp}").size(), 1u) << ratio;
  }
}

TEST_F(QuickStudyViews, Fig4CostAndAdviceAnswer) {
  const auto fig4 =
      RunShockmap("plot fig4 --db " + at_.db + " --out " + (at_.dir / "fig4.svg").string());
  ASSERT_EQ(fig4.exit_code, 0) << fig4.output;
  EXPECT_GT(std::filesystem::file_size(at_.dir / "fig4.svg"), 1000u);
  // The SRf panel spans its data (0.81 to 1 on quick) and the threshold, not 0 to 1.
  const std::string fig4_script = ReadBytes((at_.dir / "fig4.gp").string());
  const std::regex srf_range("set ylabel 'SRf[^\n]*\nset yrange \\[([^:]+):([^\\]]+)\\]");
  std::smatch srf;
  ASSERT_TRUE(std::regex_search(fig4_script, srf, srf_range)) << fig4_script;
  EXPECT_GT(std::stod(srf[1]), 0.7);
  EXPECT_LT(std::stod(srf[1]), 0.8);  // Below the threshold line.
  EXPECT_GT(std::stod(srf[2]), 1.0);
  EXPECT_LT(std::stod(srf[2]), 1.05);

  const auto cost =
      RunShockmap("cost --db " + at_.db + " --rk 3000 --out " + (at_.dir / "cost.png").string());
  ASSERT_EQ(cost.exit_code, 0) << cost.output;
  EXPECT_NE(cost.output.find("R_k = 3162 (the studied R_k nearest to the 3000 asked)"),
            std::string::npos)
      << cost.output;
  EXPECT_NE(cost.output.find("*"), std::string::npos) << "no Pareto point marked";
  // R_ftrunc 100 passes at 0.9 dt_sharp (Err 0.089) and fails at 0.1 (Err 0.108): by error
  // cancellation, shown as such and off the front.
  const std::regex fragile_row(R"( explicit-modal +100 +0\.9 .* fragile *\n)");
  EXPECT_TRUE(std::regex_search(cost.output, fragile_row)) << cost.output;
  EXPECT_NE(cost.output.find("only by error cancellation"), std::string::npos) << cost.output;

  const auto inside = RunShockmap("advise --db " + at_.db + " --rk 5000");
  ASSERT_EQ(inside.exit_code, 0) << inside.output;
  EXPECT_EQ(inside.output.find("outside the studied range"), std::string::npos) << inside.output;
  EXPECT_NE(inside.output.find("nearest stored points"), std::string::npos) << inside.output;
  const auto outside = RunShockmap("advise --db " + at_.db + " --rk 1e7");
  ASSERT_EQ(outside.exit_code, 0) << outside.output;
  EXPECT_NE(outside.output.find("outside the studied range"), std::string::npos) << outside.output;

  const auto bad = RunShockmap("map --db " + at_.db + " --metric speed");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  const auto bad_out =
      RunShockmap("map --db " + at_.db + " --out " + (at_.dir / "map.jpg").string());
  EXPECT_EQ(bad_out.exit_code, 2) << bad_out.output;
  EXPECT_NE(bad_out.output.find(".png or .svg"), std::string::npos) << bad_out.output;
}

}  // namespace
}  // namespace shockmap

#include "views/contact_force_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <map>
#include <numeric>

#include "core/input_error.h"
#include "formats/output_file.h"
#include "views/gnuplot.h"

namespace shockmap {
namespace {

// Zone indices by increasing force, so that the largest forces are drawn on top.
std::vector<std::size_t> ByForce(const std::vector<double>& force) {
  std::vector<std::size_t> order(force.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return force[a] < force[b]; });
  return order;
}

// What the zones file spans: lateral extent (mm), top (m), largest force between two beams.
struct ZoneExtent {
  double y_min = 0.0, y_max = 0.0, top = 0.0, largest_between = 0.0;
};

// Columns: y (mm), z (mm), height (m), force (N), 1 between two beams / 0 against a stop; the
// largest forces last, to be drawn on top.
ZoneExtent WriteZones(const Scene& scene, const std::vector<double>& max_force_n,
                      const std::filesystem::path& zones_file) {
  AtomicFile out(zones_file);
  std::ostream& zones = out.Stream();
  ZoneExtent e;
  for (std::size_t i : ByForce(max_force_n)) {
    const SceneZone& z = scene.zones[i];
    zones << 1e3 * z.y_m << ' ' << 1e3 * z.z_m << ' ' << z.height_m << ' ' << max_force_n[i] << ' '
          << (z.beam_b >= 0 ? 1 : 0) << '\n';
    e.y_min = std::min(e.y_min, 1e3 * z.y_m), e.y_max = std::max(e.y_max, 1e3 * z.y_m);
    e.top = std::max(e.top, z.height_m);
    if (z.beam_b >= 0) e.largest_between = std::max(e.largest_between, max_force_n[i]);
  }
  out.Commit();
  for (const SceneBeam& b : scene.beams) e.top = std::max(e.top, b.length_m);
  return e;
}

// Cross-section, index 0: the largest force over the heights at each location (y, z in mm,
// force); index 1: the beams (y, z).
void WriteSection(const Scene& scene, const std::vector<double>& max_force_n,
                  const std::filesystem::path& section_file) {
  std::map<std::pair<long long, long long>, std::pair<std::size_t, double>> at;
  for (std::size_t i = 0; i < scene.zones.size(); ++i) {
    const SceneZone& z = scene.zones[i];
    const std::pair key{std::llround(z.y_m * 1e7), std::llround(z.z_m * 1e7)};
    auto [it, fresh] = at.try_emplace(key, i, max_force_n[i]);
    if (!fresh && max_force_n[i] > it->second.second) it->second = {i, max_force_n[i]};
  }
  std::vector<std::pair<double, std::size_t>> cells;
  for (const auto& [key, cell] : at) cells.emplace_back(cell.second, cell.first);
  std::stable_sort(cells.begin(), cells.end());
  AtomicFile out(section_file);
  std::ostream& section = out.Stream();
  for (const auto& [force, i] : cells) {
    section << 1e3 * scene.zones[i].y_m << ' ' << 1e3 * scene.zones[i].z_m << ' ' << force << '\n';
  }
  section << "\n\n";
  for (const SceneBeam& b : scene.beams) section << 1e3 * b.y_m << ' ' << 1e3 * b.z_m << '\n';
  out.Commit();
}

std::string ProfilePlot(const ZoneExtent& e, const std::filesystem::path& zones_file) {
  const double margin = std::max(5.0, 0.08 * (e.y_max - e.y_min));
  return fmt::format(
      R"(set title 'zones by height and lateral position' font ',12'
set xlabel 'lateral position y (mm)'
set ylabel 'height (m)'
set xrange [{x0}:{x1}]
set yrange [0:{top}]
set key top right opaque box font ',10'
plot {zones} using 1:($4 > 0 ? 1/0 : $3) with points pt 6 ps 0.8 lc rgb '#bdbdbd' title 'never in contact', \
     '' using 1:($4 > 0 && $5 == 1 ? $3 : 1/0):4 with points pt 7 ps 1.4 lc palette title 'between beams', \
     '' using 1:($4 > 0 && $5 == 0 ? $3 : 1/0) with points pt 5 ps 1.6 lc rgb '#000000' title 'against a stop', \
     '' using 1:($4 > 0 && $5 == 0 ? $3 : 1/0):(sprintf(' %.4g N', $4)) with labels left offset 1,0 font ',10' notitle
)",
      fmt::arg("zones", GnuplotFileName(zones_file)), fmt::arg("x0", e.y_min - margin),
      fmt::arg("x1", e.y_max + margin), fmt::arg("top", 1.05 * e.top));
}

std::string SectionPlot(const std::filesystem::path& section_file) {
  return fmt::format(
      R"(set title 'cross-section: largest force over the heights' font ',12'
set xlabel 'y (mm)'
set ylabel 'z (mm)'
set autoscale xy
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
set size ratio -1
plot {section} index 1 using 1:2 with points pt 6 ps 1.6 lc rgb '#969696' title 'beams', \
     '' index 0 using 1:2:3 with points pt 7 ps 1.1 lc palette title 'zones'
)",
      fmt::arg("section", GnuplotFileName(section_file)));
}

}  // namespace

void DrawContactForceMap(const Scene& scene, const std::vector<double>& max_force_n,
                         const std::filesystem::path& file, const std::string& quantity) {
  assert(max_force_n.size() == scene.zones.size());
  if (scene.zones.empty()) throw InputError(scene.name + ": the scene has no contact zone to map");
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const bool both = scene.planes == BendingPlanes::kBoth;
  const auto zones_file = std::filesystem::path(file).replace_extension(".zones.dat");
  const ZoneExtent extent = WriteZones(scene, max_force_n, zones_file);
  const auto section_file = std::filesystem::path(file).replace_extension(".section.dat");
  if (both) WriteSection(scene, max_force_n, section_file);

  const auto largest = std::max_element(max_force_n.begin(), max_force_n.end());
  const SceneZone& strongest = scene.zones[static_cast<std::size_t>(largest - max_force_n.begin())];
  // The colours span the zones between beams, whose forces a stop's (often far larger, and
  // labelled with its value) would wash out.
  const double cb_max = extent.largest_between > 0.0 ? extent.largest_between
                        : *largest > 0.0             ? *largest
                                                     : 1.0;
  const std::string title = fmt::format("{}: {} per zone (largest {:.4g} N at {})", scene.name,
                                        quantity, *largest, strongest.name);
  const std::string script = fmt::format(
      R"(set terminal {terminal}
set output {out}
set palette defined (0 '#fff5eb', 0.25 '#fdae6b', 0.6 '#e6550d', 1 '#7f2704')
set cbrange [0:{cb}]
set cblabel {cblabel} noenhanced
set grid lc rgb '#dddddd'
set multiplot layout 1,{columns} title {title} font ',13' noenhanced
{profile}{section}unset multiplot
)",
      fmt::arg("terminal", TerminalFor(file, both ? 1500 : 900, 800)),
      fmt::arg("out", GnuplotFileName(file)), fmt::arg("cb", cb_max),
      fmt::arg("cblabel", GnuplotQuoted(quantity + " (N)")), fmt::arg("columns", both ? 2 : 1),
      fmt::arg("title", GnuplotQuoted(title)), fmt::arg("profile", ProfilePlot(extent, zones_file)),
      fmt::arg("section", both ? SectionPlot(section_file) : ""));
  RunGnuplot(script, std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

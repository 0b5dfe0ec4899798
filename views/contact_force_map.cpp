#include "views/contact_force_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "core/input_error.h"
#include "formats/output_file.h"
#include "specs/zone_family.h"
#include "views/gnuplot.h"

namespace shockmap {
namespace {

// The faint open circle of a beam's axis in a cross-section.
constexpr const char* kBeamAxisStyle = "pt 6 ps 1.2 lc rgb '#d9d9d9'";

// Zone indices by increasing force, so that the largest forces are drawn on top.
std::vector<std::size_t> ByForce(const std::vector<double>& force) {
  std::vector<std::size_t> order(force.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return force[a] < force[b]; });
  return order;
}

// A zone height rounded to the micrometre: zones at one wire height share a panel.
double HeightKey(double height_m) { return std::round(height_m * 1e6) / 1e6; }

// What the zones file holds: lateral extent (mm), top (m), which kinds of zone are present,
// the largest force between two beams and against a stop, the distinct heights of the zones
// between beams (the stops have their own panel).
struct ZoneExtent {
  double y_min = 0.0, y_max = 0.0, top = 0.0, largest_between = 0.0, largest_stop = 0.0;
  // Present: never in contact; in contact between two beams (a pin and the wrapper apart),
  // between a pin and the wrapper, against a stop.
  bool idle = false, between = false, wrapper = false, stop = false;
  std::set<double> heights_m;
};

// A zone between a pin of a generated bundle and its wrapper (specs/zone_family.h).
bool AgainstWrapper(const Scene& scene, const SceneZone& z) {
  return z.beam_a >= 0 && z.beam_b >= 0 &&
         FamilyOfZone(scene.beams[static_cast<std::size_t>(z.beam_a)].name,
                      scene.beams[static_cast<std::size_t>(z.beam_b)].name) ==
             ZoneFamily::kPinWrapper;
}

// Columns: y (mm), z (mm), height (m), the quantity (a force in N, a wear volume in m^3), 1
// between two beams / 0 against a stop, 1 between a pin and the wrapper / 0 otherwise; the
// largest values last, to be drawn on top.
ZoneExtent WriteZones(const Scene& scene, const std::vector<double>& max_force_n,
                      const MapQuantity& quantity, const std::filesystem::path& zones_file) {
  AtomicFile out(zones_file);
  std::ostream& zones = out.Stream();
  zones << "# value: " << quantity.name << " (" << quantity.unit << ")\n"
        << "# y_mm z_mm height_m value between_beams pin_wrapper\n";
  ZoneExtent e;
  for (std::size_t i : ByForce(max_force_n)) {
    const SceneZone& z = scene.zones[i];
    const bool between = !z.AgainstStop(), wrapper = AgainstWrapper(scene, z);
    zones << fmt::format("{} {} {} {} {} {}\n", 1e3 * z.y_m, 1e3 * z.z_m, z.height_m,
                         max_force_n[i], between ? 1 : 0, wrapper ? 1 : 0);
    e.y_min = std::min(e.y_min, 1e3 * z.y_m), e.y_max = std::max(e.y_max, 1e3 * z.y_m);
    e.top = std::max(e.top, z.height_m);
    if (between) e.heights_m.insert(HeightKey(z.height_m));
    const bool touched = max_force_n[i] > 0.0;
    e.idle = e.idle || !touched;
    e.between = e.between || (touched && between && !wrapper);
    e.wrapper = e.wrapper || (touched && wrapper);
    e.stop = e.stop || (touched && !between);
    double& largest = between ? e.largest_between : e.largest_stop;
    largest = std::max(largest, max_force_n[i]);
  }
  out.Commit();
  for (const SceneBeam& b : scene.beams) e.top = std::max(e.top, b.length_m);
  return e;
}

// The lateral extent of a cross-section (mm), drawn with a margin of a tenth of its size.
struct SectionBox {
  double y0 = 0.0, y1 = 0.0, z0 = 0.0, z1 = 0.0;
  void Add(double y, double z) {
    y0 = std::min(y0, y), y1 = std::max(y1, y), z0 = std::min(z0, z), z1 = std::max(z1, z);
  }
  std::string Ranges() const {
    const double margin = std::max(1.0, 0.1 * std::max(y1 - y0, z1 - z0));
    return fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\n", y0 - margin, y1 + margin,
                       z0 - margin, z1 + margin);
  }
};

// The positions (y, z in mm) of the beams that meet another beam in a zone: the cross-section
// of the bundle, without the duct or the frame they are held in. Returns the section's box,
// which holds those beams and the zones between beams (a bundle's pin-wrapper zones lie
// outside its outer pins).
SectionBox WriteBeams(const Scene& scene, const std::filesystem::path& beams_file) {
  AtomicFile out(beams_file);
  out.Stream() << "# y_mm z_mm\n";
  std::set<int> in_section;  // Beams meeting another beam in a zone: the bundle's cross-section.
  SectionBox box;
  for (const SceneZone& z : scene.zones) {
    if (z.AgainstStop()) continue;
    for (const int beam : {z.beam_a, z.beam_b}) {
      if (beam >= 0) in_section.insert(beam);
    }
    box.Add(1e3 * z.y_m, 1e3 * z.z_m);
  }
  for (int i : in_section) {
    const SceneBeam& b = scene.beams[static_cast<std::size_t>(i)];
    out.Stream() << fmt::format("{} {}\n", 1e3 * b.y_m, 1e3 * b.z_m);
    box.Add(1e3 * b.y_m, 1e3 * b.z_m);
  }
  out.Commit();
  return box;
}

// How one kind of zone is drawn: which zones (a gnuplot condition on the zones file's
// columns), its point style, whether the colour scale colours it, its legend title.
struct ZoneMark {
  std::string condition, style;
  bool coloured = false;
  std::string title;
};

// The marks of the kinds of zone present.
std::vector<ZoneMark> ZoneMarks(const ZoneExtent& e) {
  std::vector<ZoneMark> marks;
  if (e.idle)
    marks.push_back({"$4 <= 0", "pt 6 ps 0.8 lc rgb '#bdbdbd'", false, "never in contact"});
  if (e.between) {
    marks.push_back(
        {"$4 > 0 && $5 == 1 && $6 == 0", "pt 7 ps 1.4", true,
         e.wrapper ? "between two pins (colour scale)" : "between beams (colour scale)"});
  }
  if (e.wrapper) {
    marks.push_back(
        {"$4 > 0 && $6 == 1", "pt 9 ps 1.6", true, "between a pin and the wrapper (colour scale)"});
  }
  if (e.stop) {
    marks.push_back({"$4 > 0 && $5 == 0", "pt 5 ps 1.4 lc rgb '#000000'", false,
                     "against a stop (right panel)"});
  }
  return marks;
}

// The clauses of the zones in one panel, only for the kinds present; `select` is the gnuplot
// expression of the y coordinate (1/0 for zones outside the panel), `x` of the x coordinate.
// `titled`: the panel's own legend names them.
std::string ZoneClauses(const ZoneExtent& e, const std::string& zones, const std::string& x,
                        const std::string& select, bool titled) {
  std::string joined;
  for (const ZoneMark& m : ZoneMarks(e)) {
    joined += fmt::format("{}{} using {}:({} ? {} : 1/0){} with points {}{} {}",
                          joined.empty() ? "" : ", \\\n     ", zones, x, m.condition, select,
                          m.coloured ? ":4" : "", m.style, m.coloured ? " lc palette" : "",
                          titled ? "title " + GnuplotQuoted(m.title) : "notitle");
  }
  return joined;
}

// The legend the cross-sections share, drawn across the bottom of the picture (the room
// MapScript leaves there): the beam axes and each kind of zone present.
std::string SharedLegend(const ZoneExtent& e, double height_fraction) {
  std::string entries = fmt::format("keyentry with points {} title 'beam axes'", kBeamAxisStyle);
  for (const ZoneMark& m : ZoneMarks(e)) {
    entries += fmt::format(", keyentry with points {}{} title {}", m.style,
                           m.coloured ? " lc palette frac 0.7" : "", GnuplotQuoted(m.title));
  }
  // The constant below the range only gives the plot something to draw: gnuplot refuses a
  // plot of key entries alone.
  return fmt::format(
      R"(unset title
unset xlabel
unset ylabel
unset tics
unset border
unset grid
unset colorbox
set size noratio
set lmargin at screen 0.02
set rmargin at screen 0.98
set bmargin at screen 0.01
set tmargin at screen {top}
set xrange [0:1]
set yrange [0:1]
set key center center horizontal maxrows 1 font ',11' box
plot -1 notitle, {entries}
)",
      fmt::arg("top", height_fraction), fmt::arg("entries", entries));
}

// Planar scenes: the zones by height and lateral position.
std::string ProfilePlot(const ZoneExtent& e, const std::string& zones) {
  const double margin = std::max(5.0, 0.08 * (e.y_max - e.y_min));
  return fmt::format(
      R"(set title 'zones by height and lateral position' font ',12'
set xlabel 'lateral position y (mm)'
set ylabel 'height (m)'
set xrange [{x0}:{x1}]
set yrange [0:{top}]
set key below font ',10'
plot {clauses}
)",
      fmt::arg("x0", e.y_min - margin), fmt::arg("x1", e.y_max + margin),
      fmt::arg("top", 1.05 * e.top), fmt::arg("clauses", ZoneClauses(e, zones, "1", "$3", true)));
}

// Scenes bending in both planes: the cross-section at one zone height, its legend shared
// (SharedLegend). The colour bar is drawn beside the last of these panels only.
std::string SectionPlot(const ZoneExtent& e, const SectionBox& box, const std::string& zones,
                        const std::string& beams, double height_m, bool colorbox) {
  const std::string at = fmt::format("(abs($3 - {}) < 5e-7 ? $2 : 1/0)", height_m);
  return fmt::format(
      R"(set title 'zones at height {h:.4g} m' font ',11'
set xlabel 'y (mm)'
set ylabel 'z (mm)'
{ranges}set offsets 0, 0, 0, 0
set size ratio -1
unset key
{colorbox}
plot {beams} using 1:2 with points {beam_style} notitle, \
     {clauses}
)",
      fmt::arg("h", height_m), fmt::arg("beams", beams), fmt::arg("beam_style", kBeamAxisStyle),
      fmt::arg("ranges", box.Ranges()),
      fmt::arg("colorbox", colorbox ? "set colorbox" : "unset colorbox"),
      fmt::arg("clauses", ZoneClauses(e, zones, "1", at, false)));
}

// The stops on their own axis: largest force against height, each labelled with its value.
std::string StopPlot(const ZoneExtent& e, const std::string& zones, const MapQuantity& quantity) {
  return fmt::format(
      R"(set title 'against a stop' font ',12'
set size noratio
set xlabel {xlabel} noenhanced
set ylabel 'height (m)'
set xrange [0:{x1}]
set yrange [0:{top}]
unset key
unset colorbox
plot {zones} using ($5 == 0 && $4 > 0 ? $4 : 1/0):3 with points pt 5 ps 1.6 lc rgb '#000000' notitle, \
     '' using ($5 == 0 && $4 > 0 ? $4 : 1/0):3:(sprintf('%.4g {unit}', $4)) with labels right offset -1,0 font ',10' notitle
)",
      fmt::arg("xlabel", GnuplotQuoted(quantity.name + " (" + quantity.unit + ")")),
      fmt::arg("unit", quantity.unit), fmt::arg("zones", zones),
      fmt::arg("x1", 1.15 * e.largest_stop), fmt::arg("top", 1.05 * e.top));
}

// The room (px) beneath the cross-sections for their shared legend.
constexpr int kSectionLegendPx = 60;

// The panels' grid: rows and columns; `legend_px` of room beneath them for a shared legend.
struct PanelGrid {
  int rows = 1, columns = 1, legend_px = 0;
};

// `quantity` names what the values are, in the title and on the colour bar.
std::string MapScript(const Scene& scene, const std::vector<double>& max_force_n,
                      const MapQuantity& quantity, const ZoneExtent& e,
                      const std::filesystem::path& file, PanelGrid layout,
                      const std::string& panels) {
  const auto largest = std::max_element(max_force_n.begin(), max_force_n.end());
  const SceneZone& strongest = scene.zones[static_cast<std::size_t>(largest - max_force_n.begin())];
  const std::string title = fmt::format("{}: {} per zone (largest {:.4g} {} at {})", scene.name,
                                        quantity.name, *largest, quantity.unit, strongest.name);
  const int width = layout.columns == 1 ? 900 : 480 * layout.columns + 200;
  const int height = layout.rows * 560 + 80 + layout.legend_px;
  // With a shared legend, the panels leave its room at the bottom; else gnuplot's own layout.
  const std::string margins =
      layout.legend_px > 0
          ? fmt::format(
                " margins screen {}, screen {}, screen {}, screen {} spacing screen {}, "
                "screen {}",
                70.0 / width, 1.0 - 110.0 / width, (layout.legend_px + 50.0) / height,
                1.0 - 70.0 / height, 190.0 / width, 110.0 / height)
          : "";
  return fmt::format(
      R"(set terminal {terminal}
set output {out}
set palette defined (0 '#fff5eb', 0.25 '#fdae6b', 0.6 '#e6550d', 1 '#7f2704')
set cbrange [0:{cb}]
set cblabel {cblabel} noenhanced
set grid lc rgb '#dddddd'
set multiplot layout {rows},{columns}{margins} title {title} font ',13' noenhanced
{panels}{legend}unset multiplot
)",
      fmt::arg("terminal", TerminalFor(file, width, height)), fmt::arg("margins", margins),
      fmt::arg("out", GnuplotOutputName(file)),
      fmt::arg("cb", e.largest_between > 0.0 ? e.largest_between : 1.0),
      fmt::arg("rows", layout.rows), fmt::arg("columns", layout.columns),
      fmt::arg("cblabel", GnuplotQuoted(quantity.name + " between beams (" + quantity.unit + ")")),
      fmt::arg("title", GnuplotQuoted(title)), fmt::arg("panels", panels),
      fmt::arg("legend",
               layout.legend_px > 0 ? SharedLegend(e, (layout.legend_px - 10.0) / height) : ""));
}

}  // namespace

void DrawContactForceMap(const Scene& scene, const std::vector<double>& max_force_n,
                         const std::filesystem::path& file, const MapQuantity& quantity) {
  assert(max_force_n.size() == scene.zones.size());
  if (scene.zones.empty()) throw InputError(scene.name + ": the scene has no contact zone to map");
  if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
  const auto zones_file = std::filesystem::path(file).replace_extension(".zones.dat");
  const auto beams_file = std::filesystem::path(file).replace_extension(".beams.dat");
  const ZoneExtent extent = WriteZones(scene, max_force_n, quantity, zones_file);
  const bool both = scene.planes == BendingPlanes::kBoth;
  const SectionBox box = both ? WriteBeams(scene, beams_file) : SectionBox{};
  const std::string zones = GnuplotFileName(zones_file);
  std::string panels;
  int count = 0;
  if (both) {
    for (double h : extent.heights_m) {
      panels += SectionPlot(extent, box, zones, GnuplotFileName(beams_file), h,
                            h == *extent.heights_m.rbegin());
      ++count;
    }
  } else {
    panels = ProfilePlot(extent, zones), count = 1;
  }
  if (extent.stop) panels += StopPlot(extent, zones, quantity), ++count;
  const int columns = both ? std::min(count, 4) : count;
  const int rows = (count + columns - 1) / columns;
  RunGnuplot(MapScript(scene, max_force_n, quantity, extent, file,
                       {rows, columns, both ? kSectionLegendPx : 0}, panels),
             std::filesystem::path(file).replace_extension(".gp"), file);
}

}  // namespace shockmap

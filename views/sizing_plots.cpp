#include "views/sizing_plots.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>

#include "formats/output_file.h"
#include "views/contact_force_map.h"
#include "views/gnuplot.h"
#include "views/sizing_text.h"

namespace shockmap {
namespace {

namespace fs = std::filesystem;

// Interval ends for a plot: an unbounded side drawn at the estimate.
double Lower(const QuantileInterval& q) { return q.lower_bounded ? q.lower : q.estimate; }
double Upper(const QuantileInterval& q) { return q.upper_bounded ? q.upper : q.estimate; }

// The force axis of a set of intervals: their estimates and bounded ends, with room around
// them, into which an unbounded side runs as an arrow to the axis' edge, open.
struct ForceAxis {
  double low = INFINITY, high = -INFINITY;
  void Add(const QuantileInterval& q) {
    low = std::min(low, Lower(q)), high = std::max(high, Upper(q));
  }
  double Margin() const {
    return std::max(0.12 * (high - low), 1e-3 * std::max(1.0, std::abs(high)));
  }
  double Bottom() const { return low - Margin(); }
  double Top() const { return high + Margin(); }
  std::string Range() const { return fmt::format("set yrange [{}:{}]\n", Bottom(), Top()); }
};

// Which kinds of interval a plot holds: both sides bounded, an upper or a lower side open.
struct IntervalKinds {
  bool closed = false, open_up = false, open_down = false;
  void Add(const QuantileInterval& q) {
    closed = closed || (q.lower_bounded && q.upper_bounded);
    open_up = open_up || !q.upper_bounded;
    open_down = open_down || (!q.lower_bounded && q.upper_bounded);
  }
};

// The arrows of the open intervals, from data columns x ($1), estimate ($2), lower ($3), upper
// ($4), lower_bounded ($5), upper_bounded ($6): an unbounded upper side from the lower end (or
// the axis' bottom) up to the top edge, an unbounded lower side from the upper end down to the
// bottom edge; one legend entry per kind present.
std::string OpenIntervalClauses(const IntervalKinds& kinds, const ForceAxis& axis) {
  std::string clauses;
  if (kinds.open_up) {
    clauses += fmt::format(
        ", \\\n     '' using 1:($6 > 0 ? 1/0 : ($5 > 0 ? $3 : {b})):(0):({t} - ($5 > 0 ? $3 : "
        "{b})) "
        "with vectors head filled size screen 0.012,25 lw 2 lc rgb '#de2d26' title 'interval "
        "open upward: upper side unbounded (too few members)'",
        fmt::arg("b", axis.Bottom()), fmt::arg("t", axis.Top()));
  }
  if (kinds.open_down) {
    clauses += fmt::format(
        ", \\\n     '' using 1:($5 > 0 || $6 == 0 ? 1/0 : $4):(0):({b} - $4) with vectors head "
        "filled size screen 0.012,25 lw 2 lc rgb '#756bb1' title 'interval open downward: lower "
        "side unbounded'",
        fmt::arg("b", axis.Bottom()));
  }
  return clauses;
}

fs::path Draw(const fs::path& image, const std::string& body, int width = 900, int height = 600) {
  const std::string script = fmt::format(
      "set terminal {}\nset output {}\nset termoption noenhanced\nset grid lc rgb '#dddddd'\n{}",
      TerminalFor(image, width, height), GnuplotOutputName(image), body);
  RunGnuplot(script, fs::path(image).replace_extension(".gp"), image);
  return image;
}

// The member counts as the x axis' tics when they are few (a log axis would tick one of them).
std::string MemberTics(const std::vector<ConvergencePoint>& points) {
  if (points.size() > 12) return "";
  std::string tics;
  for (const ConvergencePoint& p : points) {
    tics += fmt::format("{}{}", tics.empty() ? "" : ", ", p.members);
  }
  return "set xtics (" + tics + ")\n";
}

// A family's part of a picture's file name: "pin-pin_wire", "duct_pad", "pin-wrapper", "other".
std::string FamilyFilePart(ZoneFamily family) { return FileNamePart(FamilyName(family)); }

fs::path Convergence(const EnsembleSizing& s, const GroupSizing& g, const FamilyHottest& f,
                     const std::vector<double>& forces, const fs::path& folder) {
  const auto points = SizingConvergence(forces, s.options);
  const fs::path image = folder / fmt::format("convergence_{}_{}.png", FileNamePart(g.state),
                                              FamilyFilePart(f.family));
  const fs::path data = fs::path(image).replace_extension(".dat");
  std::string text = "# members estimate lower upper lower_bounded upper_bounded\n";
  ForceAxis axis;
  IntervalKinds kinds;
  for (const ConvergencePoint& p : points) {
    text += fmt::format("{} {} {} {} {} {}\n", p.members, p.sizing.estimate, Lower(p.sizing),
                        Upper(p.sizing), p.sizing.lower_bounded ? 1 : 0,
                        p.sizing.upper_bounded ? 1 : 0);
    axis.Add(p.sizing), kinds.Add(p.sizing);
  }
  WriteFileAtomically(data, text);
  const std::string title =
      fmt::format("{} ({}): P{} at {}, the hottest {}, {} % interval", s.study, g.state,
                  PercentText(s.options.quantile), g.zones[f.zone].name, FamilyName(f.family),
                  PercentText(s.options.confidence));
  const std::string band =
      kinds.closed ? "using 1:($5 > 0 && $6 > 0 ? $3 : 1/0):4 with filledcurves lc rgb '#9ecae1' "
                     "fs solid 0.5 title 'interval (both sides bounded)', \\\n     '' "
                   : "";
  return Draw(
      image,
      fmt::format(
          R"(set title {title} noenhanced
set xlabel 'members'
set ylabel 'force (N)'
set logscale x
{tics}set xrange [{first}:{last}]
{range}set key below
plot {data} {band}using 1:2 with linespoints pt 7 lc rgb '#08519c' title 'estimate'{open}
)",
          fmt::arg("title", GnuplotQuoted(title)), fmt::arg("tics", MemberTics(points)),
          fmt::arg("first", 0.9 * points.front().members), fmt::arg("last", 1.15 * forces.size()),
          fmt::arg("range", axis.Range()), fmt::arg("data", GnuplotFileName(data)),
          fmt::arg("band", band), fmt::arg("open", OpenIntervalClauses(kinds, axis))));
}

fs::path Histogram(const EnsembleSizing& s, const GroupSizing& g, const FamilyHottest& f,
                   const std::vector<double>& forces, const fs::path& folder) {
  const ZoneSizing& z = g.zones[f.zone];
  const fs::path image =
      folder / fmt::format("histogram_{}_{}.png", FileNamePart(g.state), FamilyFilePart(f.family));
  const fs::path data = fs::path(image).replace_extension(".dat");
  const auto [lo, hi] = std::minmax_element(forces.begin(), forces.end());
  const int bins = std::clamp(static_cast<int>(std::sqrt(forces.size())), 5, 40);
  const double width = *hi > *lo ? (*hi - *lo) / bins : std::max(1.0, std::abs(*lo) * 1e-3);
  std::vector<int> counts(bins, 0);
  for (double f : forces) counts[std::min(bins - 1, static_cast<int>((f - *lo) / width))]++;
  std::string text = "# bin_centre_n members\n";
  for (int i = 0; i < bins; ++i) text += fmt::format("{} {}\n", *lo + (i + 0.5) * width, counts[i]);
  // Room above the tallest bar, so that its top is not the frame, nor under the labels.
  const int tallest = *std::ranges::max_element(counts);
  const int top = tallest + std::max(1, static_cast<int>(std::ceil(0.25 * tallest)));
  WriteFileAtomically(data, text);
  const std::string title =
      fmt::format("{} ({}): largest force at {}, the hottest {}, over {} members", s.study, g.state,
                  z.name, FamilyName(f.family), forces.size());
  std::string marks = fmt::format(
      "set arrow from {0},graph 0 to {0},graph 1 nohead lw 2 lc rgb '#08519c'\n"
      "set label {1} at {0},graph 0.95 left offset 0.5,0 tc rgb '#08519c'\n",
      z.sizing.estimate, GnuplotQuoted("P" + PercentText(s.options.quantile)));
  if (z.wilks) {
    marks += fmt::format(
        "set arrow from {0},graph 0 to {0},graph 1 nohead lw 2 dt 2 lc rgb '#de2d26'\n"
        "set label {1} at {0},graph 0.88 left offset 0.5,0 tc rgb '#de2d26'\n",
        z.wilks->value, GnuplotQuoted(fmt::format("Wilks order {}", z.wilks->order)));
  }
  return Draw(image, fmt::format(
                         R"(set title {title} noenhanced
set xlabel 'largest force in the zone (N)'
set ylabel 'members'
set yrange [0:{top}]
set style fill solid 0.6 border lc rgb '#525252'
set boxwidth {width}
{marks}plot {data} using 1:2 with boxes lc rgb '#9ecae1' notitle
)",
                         fmt::arg("title", GnuplotQuoted(title)), fmt::arg("top", top),
                         fmt::arg("width", width), fmt::arg("marks", marks),
                         fmt::arg("data", GnuplotFileName(data))));
}

std::vector<const GroupSizing*> RefinedGroups(const EnsembleSizing& s) {
  std::vector<const GroupSizing*> refined;
  for (const GroupSizing& g : s.groups) {
    if (g.refined) refined.push_back(&g);
  }
  return refined;
}

std::string Tics(const std::vector<std::string>& labels) {
  std::string tics;
  for (std::size_t i = 0; i < labels.size(); ++i)
    tics += fmt::format("{}{} {}", i ? ", " : "", GnuplotQuoted(labels[i]), i);
  return "set xtics (" + tics + ")\n";
}

// The index in g.zones of `family`'s hottest zone. Precondition: g has the family.
int HottestOf(const GroupSizing& g, ZoneFamily family) {
  return std::ranges::find(g.families, family, &FamilyHottest::family)->zone;
}

// The family's hottest zone's sizing force (and, when streamed, its wear work rate) against the
// state: categories, drawn as points, never joined.
fs::path States(const EnsembleSizing& s, ZoneFamily family, const fs::path& folder) {
  const auto refined = RefinedGroups(s);
  const fs::path image = folder / ("states_" + FamilyFilePart(family) + ".png");
  const fs::path data = fs::path(image).replace_extension(".dat");
  std::string text =
      "# state_index sizing_n lower_n upper_n lower_bounded upper_bounded wear_work_rate_w\n";
  std::vector<std::string> labels;
  bool wear = false;
  ForceAxis axis;
  IntervalKinds kinds;
  for (std::size_t i = 0; i < refined.size(); ++i) {
    const ZoneSizing& z = refined[i]->zones[HottestOf(*refined[i], family)];
    labels.push_back(refined[i]->state + " (" + z.name + ")");
    const auto w = z.impacts ? z.impacts->wear_work_rate_w : std::nullopt;
    wear = wear || w.has_value();
    text += fmt::format("{} {} {} {} {} {} {}\n", i, z.sizing.estimate, Lower(z.sizing),
                        Upper(z.sizing), z.sizing.lower_bounded ? 1 : 0,
                        z.sizing.upper_bounded ? 1 : 0, w ? fmt::format("{}", *w) : "NaN");
    axis.Add(z.sizing), kinds.Add(z.sizing);
  }
  WriteFileAtomically(data, text);
  const std::string title =
      fmt::format("{}: P{} of the hottest {}'s largest force per clearance state", s.study,
                  PercentText(s.options.quantile), FamilyName(family));
  std::string plot = fmt::format(
      "plot {} using 1:2 with points pt 7 ps 1.5 lc rgb '#08519c' title 'P{} (estimate)'",
      GnuplotFileName(data), PercentText(s.options.quantile));
  if (kinds.closed) {
    plot += fmt::format(
        ", \\\n     '' using 1:($5 > 0 && $6 > 0 ? $2 : 1/0):3:4 with yerrorbars pt 7 ps 1.5 lw 2 "
        "lc rgb '#08519c' title '{} % interval (both sides bounded)'",
        PercentText(s.options.confidence));
  }
  plot += OpenIntervalClauses(kinds, axis);
  if (wear) {
    plot +=
        ", \\\n     '' using ($1 + 0.1):7 axes x1y2 with points pt 5 ps 1.3 lc rgb '#31a354' title "
        "'mean "
        "wear work rate (W, right axis)'";
  }
  return Draw(
      image,
      fmt::format(
          R"(set title {title} noenhanced
set xlabel 'clearance state'
set ylabel 'force (N)'
{y2}set xrange [-0.5:{last}]
{range}set key below
{tics}{plot}
)",
          fmt::arg("title", GnuplotQuoted(title)), fmt::arg("last", refined.size() - 0.5),
          fmt::arg("y2", wear ? "set y2label 'wear work rate (W)'\nset y2tics\nset ytics "
                                "nomirror\n"
                              : ""),
          fmt::arg("range", axis.Range()), fmt::arg("tics", Tics(labels)), fmt::arg("plot", plot)));
}

// The value of a setting on the x axis: the setting's one numeric parameter, if it has one.
std::optional<double> SettingValue(const std::string& setting_json) {
  const nlohmann::json s = nlohmann::json::parse(setting_json);
  if (s.size() != 1 || !s.begin()->is_number()) return std::nullopt;
  return s.begin()->get<double>();
}

// Per state: the sizing force of the family's hottest zone against the setting.
fs::path Settings(const EnsembleSizing& s, ZoneFamily family, const fs::path& folder) {
  const fs::path image = folder / ("settings_" + FamilyFilePart(family) + ".png");
  const fs::path data = fs::path(image).replace_extension(".dat");
  bool numeric = true;
  std::vector<std::string> settings;
  for (const GroupSizing& g : s.groups) {
    numeric = numeric && SettingValue(g.setting_json).has_value();
    if (std::find(settings.begin(), settings.end(), g.setting_json) == settings.end())
      settings.push_back(g.setting_json);
  }
  std::string text, plot;
  int block = 0;
  for (const GroupSizing* r : RefinedGroups(s)) {
    const int zone = HottestOf(*r, family);
    text += "# " + r->state + ": x sizing_n lower_n upper_n\n";
    for (const GroupSizing& g : s.groups) {
      if (g.state != r->state) continue;
      const ZoneSizing& z = g.zones[zone];
      const double x =
          numeric
              ? *SettingValue(g.setting_json)
              : static_cast<double>(std::find(settings.begin(), settings.end(), g.setting_json) -
                                    settings.begin());
      text += fmt::format("{} {} {} {}\n", x, z.sizing.estimate, Lower(z.sizing), Upper(z.sizing));
    }
    text += "\n\n";
    plot += fmt::format("{}{} index {} using 1:2:3:4 with yerrorlines pt 7 lw 2 title {}",
                        block ? ", " : "plot ", GnuplotFileName(data), block,
                        GnuplotQuoted(r->state + " (" + r->zones[zone].name + ")"));
    ++block;
  }
  WriteFileAtomically(data, text);
  const std::string axis =
      numeric ? "set logscale x\nset xlabel " +
                    GnuplotQuoted(nlohmann::json::parse(settings.front()).begin().key()) + "\n"
              : "set xlabel 'setting'\n" + Tics(settings);
  const std::string title = fmt::format(
      "{}: P{} of the hottest {}'s largest force per setting ({} % intervals)", s.study,
      PercentText(s.options.quantile), FamilyName(family), PercentText(s.options.confidence));
  return Draw(image, fmt::format("set title {} noenhanced\nset ylabel 'force (N)'\nset offsets "
                                 "graph 0.05, graph 0.05, graph 0.05, graph 0.05\nset key top "
                                 "right\n{}{}\n",
                                 GnuplotQuoted(title), axis, plot));
}

// The sizing estimate of each zone's wear volume; nullopt unless every zone has one.
std::optional<std::vector<double>> WearSizingValues(const GroupSizing& g) {
  std::vector<double> values;
  for (const ZoneSizing& z : g.zones) {
    if (!z.wear) return std::nullopt;
    values.push_back(z.wear->sizing.estimate);
  }
  return values;
}

// A state's pictures at its refined setting: the maps, then each family's convergence and
// histogram.
std::vector<SizingPicture> StatePictures(const EnsembleSizing& s, const StoredEnsemble& stored,
                                         const Scene& scene, const GroupSizing& g,
                                         const fs::path& folder) {
  const std::string q = "P" + PercentText(s.options.quantile);
  std::vector<double> sizing;
  for (const ZoneSizing& z : g.zones) sizing.push_back(z.sizing.estimate);
  const fs::path map = folder / ("map_" + FileNamePart(g.state) + ".png");
  DrawContactForceMap(scene, sizing, map,
                      {fmt::format("{} of {} members, {}", q, g.members, g.state), "N"});
  std::vector<SizingPicture> pictures = {
      {map, fmt::format("{}: every zone coloured by its {} of the largest force (paper Fig. 5b)",
                        g.state, q)}};
  if (const auto wear = WearSizingValues(g)) {
    const fs::path wear_map = folder / ("wear_map_" + FileNamePart(g.state) + ".png");
    DrawContactForceMap(
        scene, *wear, wear_map,
        {fmt::format("{} wear volume of {} members, {}", q, g.members, g.state), "m^3"});
    pictures.push_back({wear_map, fmt::format("{}: every zone coloured by the {} of its wear "
                                              "volume over the scene's wear life",
                                              g.state, q)});
  }
  for (const FamilyHottest& f : g.families) {
    const std::string zone = g.zones[f.zone].name, family = FamilyName(f.family);
    const std::vector<double> forces = ZoneForces(stored, g, f.zone);
    pictures.push_back({Convergence(s, g, f, forces, folder),
                        fmt::format("{}: {} of the hottest {} ({}) against the number of "
                                    "members, with its {} % interval",
                                    g.state, q, family, zone, PercentText(s.options.confidence))});
    pictures.push_back({Histogram(s, g, f, forces, folder),
                        fmt::format("{}: histogram of the hottest {}'s ({}) largest force over "
                                    "the members",
                                    g.state, family, zone)});
  }
  return pictures;
}

}  // namespace

std::vector<SizingPicture> DrawSizingPictures(const EnsembleSizing& s, const StoredEnsemble& stored,
                                              const Scene& scene, const fs::path& folder) {
  CreateOutputDirectory(folder);
  const std::string q = "P" + PercentText(s.options.quantile);
  std::vector<SizingPicture> pictures;
  const auto refined = RefinedGroups(s);
  for (const GroupSizing* g : refined) {
    std::ranges::move(StatePictures(s, stored, scene, *g, folder), std::back_inserter(pictures));
  }
  if (refined.empty()) return pictures;
  for (const FamilyHottest& f : refined.front()->families) {
    const std::string family = FamilyName(f.family);
    if (refined.size() > 1) {
      pictures.push_back({States(s, f.family, folder),
                          fmt::format("{} of the hottest {} (and its wear work rate, where "
                                      "streamed) per clearance state",
                                      q, family)});
    }
    // Each state's settings are drawn about its refined group's hottest zone of the family.
    if (s.groups.size() > refined.size()) {
      pictures.push_back({Settings(s, f.family, folder),
                          fmt::format("{} of the hottest {} per numerical setting", q, family)});
    }
  }
  return pictures;
}

}  // namespace shockmap

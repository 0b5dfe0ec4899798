#include "views/sizing_tables.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "specs/zone_family.h"
#include "statistics/wilks.h"
#include "views/setting_names.h"
#include "views/sizing_text.h"

namespace shockmap {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// An unbounded side of an interval is an infinite bound (`-inf` or `inf` in every format, as
// `query` prints infinities), not a missing value.
TableCell Bound(double value, bool bounded, double unbounded) {
  return TableCell(bounded ? value : unbounded);
}

// Wilks' order, none (an empty cell) while the members are too few for order 1.
TableCell WilksOrder(int order) {
  return order > 0 ? TableCell(static_cast<std::int64_t>(order)) : TableCell(std::monostate{});
}

TableCell FiniteCell(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? TableCell(*v) : TableCell(std::monostate{});
}

// The terminal's table: per family, its hottest zone's sizing quantile with its interval, the
// design value (Wilks' limit, or the members it needs) and the agreement with the refined
// setting ("refined" on the refined setting's rows); the rest is in ZoneTable.
std::vector<std::string> CompactColumns(const EnsembleSizing& s) {
  const std::string q = PercentText(s.options.quantile), c = PercentText(s.options.confidence);
  return {"state",      "setting",      "members",
          "family",     "hottest zone", "P" + q + " (N) [" + c + " %]",
          "design (N)", "agrees"};
}

std::string Agreement(std::optional<bool> agrees) { return !agrees ? "-" : *agrees ? "yes" : "no"; }

std::vector<TableCell> CompactRow(const EnsembleSizing& s, const GroupSizing& g,
                                  const ZoneSizing& z, std::optional<bool> agrees) {
  const int needed = WilksMembersNeeded(s.options.quantile, s.options.confidence, 1);
  return {g.state,
          g.setting_json,
          static_cast<std::int64_t>(z.members),
          FamilyName(z.family),
          z.name,
          IntervalText(z.sizing),
          z.wilks ? SignificantText(z.wilks->value) : fmt::format("needs {}", needed),
          g.refined ? std::string("refined") : Agreement(agrees)};
}

std::vector<std::string> Columns(const EnsembleSizing& s) {
  const std::string q = PercentText(s.options.quantile);
  std::vector<std::string> c = {"state", "setting", "members", "zone", "family"};
  auto interval = [&](const std::string& name) {
    for (const char* suffix : {"_n", "_lower_n", "_upper_n"}) c.push_back(name + suffix);
  };
  interval("p50");
  interval("p95");
  interval("p99");
  if (q != "50" && q != "95" && q != "99") interval("p" + q);
  c.insert(c.end(), {"wilks_order", "wilks_limit_n", "wilks_members_needed", "bootstrap_lower_n",
                     "bootstrap_upper_n", "nominal_n"});
  c.insert(c.end(), {"agrees_with_refined", "impacts_per_s", "contact_time_fraction",
                     "mean_force_n", "wear_work_rate_w", "wall_s_per_member", "cpu_s_per_member"});
  return c;
}

std::vector<TableCell> Row(const EnsembleSizing& s, const GroupSizing& g, const ZoneSizing& z,
                           std::optional<bool> agrees) {
  std::vector<TableCell> row = {g.state, g.setting_json + (g.refined ? " (refined)" : ""),
                                static_cast<std::int64_t>(z.members), z.name, FamilyName(z.family)};
  auto interval = [&](const QuantileInterval& q) {
    row.insert(row.end(), {q.estimate, Bound(q.lower, q.lower_bounded, -kInfinity),
                           Bound(q.upper, q.upper_bounded, kInfinity)});
  };
  interval(z.p50);
  interval(z.p95);
  interval(z.p99);
  const std::string q = PercentText(s.options.quantile);
  if (q != "50" && q != "95" && q != "99") interval(z.sizing);
  row.push_back(WilksOrder(z.wilks_order));
  row.push_back(z.wilks ? TableCell(z.wilks->value) : TableCell(std::monostate{}));
  row.emplace_back(std::in_place_type<std::int64_t>,
                   WilksMembersNeeded(s.options.quantile, s.options.confidence, 1));
  row.insert(row.end(), {z.bootstrap.lower, z.bootstrap.upper, FiniteCell(z.nominal_n)});
  row.push_back(Agreement(agrees));
  if (z.impacts) {
    row.insert(row.end(), {z.impacts->impacts_per_s, z.impacts->contact_time_fraction,
                           z.impacts->mean_force_n, FiniteCell(z.impacts->wear_work_rate_w)});
  } else {
    row.insert(row.end(), 4, std::monostate{});
  }
  row.push_back(g.mean_wall_s);
  row.push_back(g.mean_cpu_s);
  return row;
}

}  // namespace

Table HottestZoneTable(const EnsembleSizing& s, bool compact) {
  Table t;
  t.columns = compact ? CompactColumns(s) : Columns(s);
  for (const GroupSizing& g : s.groups) {
    for (const FamilyHottest& f : g.families) {
      const ZoneSizing& z = g.zones[f.zone];
      t.rows.push_back(compact ? CompactRow(s, g, z, f.agrees) : Row(s, g, z, f.agrees));
    }
  }
  return t;
}

Table ZoneTable(const EnsembleSizing& s) {
  Table t;
  t.columns = Columns(s);
  t.columns.insert(t.columns.end(), {"hottest", "family_hottest"});
  const auto refined_of = [&](const GroupSizing& g) -> const GroupSizing* {
    for (const GroupSizing& r : s.groups) {
      if (r.refined && r.state == g.state) return &r;
    }
    return nullptr;
  };
  for (const GroupSizing& g : s.groups) {
    const GroupSizing* refined = g.refined ? nullptr : refined_of(g);
    for (const ZoneSizing& z : g.zones) {
      std::optional<bool> agrees;
      if (refined != nullptr) agrees = Agrees(z, refined->zones[z.zone], s.options.tolerance);
      auto row = Row(s, g, z, agrees);
      row.emplace_back(std::in_place_type<std::int64_t>, z.zone == g.hottest ? 1 : 0);
      const bool family_hottest =
          std::ranges::any_of(g.families, [&](const FamilyHottest& f) { return f.zone == z.zone; });
      row.emplace_back(std::in_place_type<std::int64_t>, family_hottest ? 1 : 0);
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

namespace {

std::vector<std::string> WearColumns(const EnsembleSizing& s, bool compact) {
  const std::string q = "p" + PercentText(s.options.quantile);
  std::vector<std::string> c = {"state", "setting", "members", "zone"};
  if (compact) {
    const std::string c_percent = PercentText(s.options.confidence);
    const std::string p = "P" + PercentText(s.options.quantile);
    c.insert(c.end(), {"wear " + p + " (m3) [" + c_percent + " %]",
                       "Wilks " + p + "/" + c_percent + " %", "mean (m3)", "force " + p + " (N)"});
    return c;
  }
  for (const char* suffix : {"_m3", "_lower_m3", "_upper_m3"}) c.push_back("wear_" + q + suffix);
  c.insert(c.end(), {"wilks_order", "wilks_limit_m3", "mean_wear_volume_m3", "force_" + q + "_n"});
  return c;
}

// Precondition: z.wear.
std::vector<TableCell> WearRow(const GroupSizing& g, const ZoneSizing& z, bool compact) {
  const QuantileInterval& w = z.wear->sizing;
  if (compact) {
    return {g.state,
            g.setting_json + (g.refined ? " (refined)" : ""),
            static_cast<std::int64_t>(z.members),
            z.name,
            IntervalText(w),
            z.wear->wilks ? SignificantText(z.wear->wilks->value) : std::string("-"),
            SignificantText(z.wear->mean_m3),
            SignificantText(z.sizing.estimate)};
  }
  std::vector<TableCell> row = {g.state, g.setting_json + (g.refined ? " (refined)" : ""),
                                static_cast<std::int64_t>(z.members), z.name};
  row.insert(row.end(), {w.estimate, Bound(w.lower, w.lower_bounded, -kInfinity),
                         Bound(w.upper, w.upper_bounded, kInfinity)});
  row.push_back(WilksOrder(z.wear->wilks_order));
  row.push_back(z.wear->wilks ? TableCell(z.wear->wilks->value) : TableCell(std::monostate{}));
  row.insert(row.end(), {z.wear->mean_m3, z.sizing.estimate});
  return row;
}

}  // namespace

Table WearTable(const EnsembleSizing& s) {
  Table t;
  t.columns = WearColumns(s, false);
  for (const GroupSizing& g : s.groups) {
    for (const ZoneSizing& z : g.zones) {
      if (z.wear) t.rows.push_back(WearRow(g, z, false));
    }
  }
  return t;
}

Table MostWornZoneTable(const EnsembleSizing& s) {
  Table t;
  t.columns = WearColumns(s, true);
  for (const GroupSizing& g : s.groups) {
    const ZoneSizing* most = nullptr;
    for (const ZoneSizing& z : g.zones) {
      if (z.wear && (most == nullptr || z.wear->sizing.estimate > most->wear->sizing.estimate))
        most = &z;
    }
    if (most != nullptr) t.rows.push_back(WearRow(g, *most, true));
  }
  return t;
}

std::vector<std::string> SizingFootnotes(const EnsembleSizing& s, bool wear) {
  const double q = s.options.quantile, c = s.options.confidence;
  std::vector<std::string> lines;
  int fewest = std::numeric_limits<int>::max();
  bool unbounded = false;
  for (const GroupSizing& g : s.groups) {
    for (const ZoneSizing& z : g.zones) {
      if (wear && !z.wear) continue;
      const QuantileInterval& interval = wear ? z.wear->sizing : z.sizing;
      unbounded = unbounded || !interval.lower_bounded || !interval.upper_bounded;
      if (!(wear ? z.wear->wilks.has_value() : z.wilks.has_value()))
        fewest = std::min(fewest, z.members);
    }
  }
  if (fewest != std::numeric_limits<int>::max()) {
    lines.push_back(fmt::format(
        "Wilks' limit: a one-sided P{} at {} % confidence needs at least {} members (the "
        "largest of n members bounds P{} once 1 - {:g}^n >= {:g}); this study has {}: run more",
        PercentText(q), PercentText(c), WilksMembersNeeded(q, c, 1), PercentText(q), q, c, fewest));
  }
  if (!wear) {
    lines.push_back(fmt::format(
        "family: pin-pin wires, the duct pad, pins against the wrapper; each family's hottest zone "
        "at the refined setting; design: Wilks' P{}/{} % limit, or the members it needs; agrees: "
        "with the refined setting",
        PercentText(q), PercentText(c)));
  }
  if (unbounded) {
    lines.push_back("-: a side of an interval the members are too few to bound, or no value");
  }
  lines.push_back(wear ? "every zone, with the interval's bounds and Wilks' order: --format "
                         "csv|json or --out DIR"
                       : "P50, P99, bounds, bootstrap, nominal run, impact statistics and run "
                         "times of every zone: --format csv|json or --out DIR");
  return lines;
}

std::vector<std::string> AgreementLines(const EnsembleSizing& s, const Scene& scene) {
  std::vector<std::string> lines;
  for (const GroupSizing& g : s.groups) {
    if (g.refined) continue;
    const std::size_t undecided = g.zones.size() - g.zones_agreeing - g.zones_disagreeing;
    lines.push_back(fmt::format(
        "{} {} against the refined setting: {} zones agree, {} do not, {} undecided "
        "(an unbounded interval); hottest zone {}",
        g.state, SettingName(g, scene, false), g.zones_agreeing, g.zones_disagreeing, undecided,
        !g.hottest_agrees   ? "undecided"
        : *g.hottest_agrees ? "agrees"
                            : "does not agree"));
  }
  return lines;
}

}  // namespace shockmap

#include "analysis/ensemble_sizing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <tuple>

#include "core/input_error.h"
#include "db/stored_json.h"
#include "specs/ensemble_study_spec.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

void CheckOptions(const SizingOptions& o) {
  auto open_unit = [](double v, const char* flag) {
    if (!(v > 0.0 && v < 1.0)) {
      throw InputError(std::string(flag) + ": value " + std::to_string(v) + " must lie in (0, 1)");
    }
  };
  open_unit(o.quantile, "--quantile");
  open_unit(o.confidence, "--confidence");
  if (!(o.tolerance >= 0.0 && o.tolerance <= 1.0)) {
    throw InputError("--tolerance: value " + std::to_string(o.tolerance) + " must lie in [0, 1]");
  }
}

// The refined setting: the file's "refined", or the members' only setting. Compared by value,
// as the study file matched it (100.0 is the setting 100).
Json RefinedSetting(const Json& spec, const std::vector<StoredMember>& members) {
  if (spec.contains("refined")) return spec.at("refined");
  return Json::parse(members.front().setting_json);
}

// Whether `setting` (a member's, {"path": value}) is one of the file's "settings": one of the
// list ([{"path": value}, ...]), or of the product of the axes ({"path": [values]}; absent:
// the empty setting). Compared by value (100.0 is 100).
bool IsSettingOf(const Json& setting, const Json& settings) {
  if (settings.is_array())
    return std::find(settings.begin(), settings.end(), setting) != settings.end();
  const Json& axes = settings;
  if (setting.size() != (axes.is_object() ? axes.size() : 0)) return false;
  for (const auto& [path, value] : setting.items()) {
    const auto axis = axes.find(path);
    if (axis == axes.end() || !axis->is_array() ||
        std::find(axis->begin(), axis->end(), value) == axis->end())
      return false;
  }
  return true;
}

// What the stored spec, as last run, says of its members: how many, in which clearance states
// (absent: the one state "scene"), at which settings (the file's "settings": axes
// {"path": [values]} or a list [{"path": value}, ...]).
struct CurrentSpec {
  std::int64_t members = 0;
  std::vector<std::string> states;
  Json settings;
};

// DbError "<file>: database corrupt: study <name>: spec_json: <reason>" unless "members" is a
// whole number in [1, kMaxEnsembleMembers], "clearance_states" a list of objects with a text
// "name" and "settings" an object or a list of objects.
CurrentSpec ReadCurrentSpec(const StoredEnsemble& stored) {
  const StoredCell cell{stored.database_path, "study " + stored.study, "spec_json"};
  return ReadStoredJson(cell, stored.spec_json, [&](const Json& spec) {
    CurrentSpec current;
    const Json& members = spec.at("members");
    if (!members.is_number_integer() || members.get<std::int64_t>() < 1 ||
        members.get<std::int64_t>() > kMaxEnsembleMembers) {
      ThrowCorruptCell(cell, "members: " + members.dump() + " is not a whole number from 1 to " +
                                 std::to_string(kMaxEnsembleMembers));
    }
    current.members = members.get<std::int64_t>();
    const Json states = spec.value("clearance_states", Json::array({Json{{"name", "scene"}}}));
    for (const Json& s : states.get<std::vector<Json>>()) {
      current.states.push_back(s.at("name").get<std::string>());
    }
    current.settings = spec.value("settings", Json::object());
    const bool list_of_objects =
        current.settings.is_array() &&
        std::ranges::all_of(current.settings, [](const Json& s) { return s.is_object(); });
    if (!current.settings.is_object() && !list_of_objects)
      ThrowCorruptCell(cell, "settings: neither a JSON object nor a list of objects");
    return current;
  });
}

// Each zone's name and family (from the beams it joins, as the nominal run stored them).
std::pair<std::vector<std::string>, std::vector<ZoneFamily>> ZoneNames(
    const StoredEnsemble& stored) {
  for (const EnsembleReferenceRow& r : stored.references) {
    if (r.zones_json.empty()) continue;
    std::pair<std::vector<std::string>, std::vector<ZoneFamily>> zones;
    for (const Json& z : Json::parse(r.zones_json)) {
      zones.first.push_back(z.at("name"));
      zones.second.push_back(FamilyOfZone(z.value("beam_a", ""), z.value("beam_b", "")));
    }
    return zones;
  }
  throw InputError("the study's nominal runs are not stored: run the study again");
}

// The members of each (state, setting), in the order the study lists them.
std::vector<std::pair<GroupSizing, std::vector<const StoredMember*>>> Groups(
    const StoredEnsemble& stored, const Json& refined) {
  std::vector<std::pair<GroupSizing, std::vector<const StoredMember*>>> groups;
  std::map<std::pair<std::string, std::string>, std::size_t> index;
  for (const StoredMember& m : stored.members) {
    const auto [it, fresh] = index.try_emplace({m.state, m.setting_json}, groups.size());
    if (fresh) {
      GroupSizing g;
      g.state = m.state;
      g.setting_json = m.setting_json;
      g.refined = Json::parse(m.setting_json) == refined;
      groups.push_back({std::move(g), {}});
    }
    groups[it->second].second.push_back(&m);
  }
  std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
    return a.second.front()->point_id < b.second.front()->point_id;
  });
  return groups;
}

std::optional<MeanImpacts> MeanOf(const std::vector<const StoredMember*>& members, int zone) {
  MeanImpacts sum;
  int counted = 0, with_wear = 0;
  double wear = 0.0;
  for (const StoredMember* m : members) {
    const EnsembleZoneRow& z = m->zones[zone];
    if (!z.impacts) continue;
    ++counted;
    sum.impacts_per_s += z.impacts_per_s.value_or(0.0);
    sum.rebounds_per_impact += z.rebounds_per_impact.value_or(0.0);
    sum.mean_impact_duration_s += z.mean_impact_duration_s.value_or(0.0);
    sum.contact_time_fraction += z.contact_time_fraction.value_or(0.0);
    sum.mean_force_n += z.mean_force_n.value_or(0.0);
    sum.rms_force_n += z.rms_force_n.value_or(0.0);
    sum.impulse_n_s += z.impulse_n_s.value_or(0.0);
    if (z.wear_work_rate_w) wear += *z.wear_work_rate_w, ++with_wear;
  }
  if (counted == 0) return std::nullopt;
  for (double* v :
       {&sum.impacts_per_s, &sum.rebounds_per_impact, &sum.mean_impact_duration_s,
        &sum.contact_time_fraction, &sum.mean_force_n, &sum.rms_force_n, &sum.impulse_n_s}) {
    *v /= counted;
  }
  if (with_wear > 0) sum.wear_work_rate_w = wear / with_wear;
  return sum;
}

// The wear volumes' sizing, when every member has one at the zone.
std::optional<WearSizing> WearOf(const std::vector<const StoredMember*>& members, int zone,
                                 const SizingOptions& options) {
  std::vector<double> volumes;
  for (const StoredMember* m : members) {
    const std::optional<double>& v = m->zones[zone].wear_volume_m3;
    if (!v) return std::nullopt;
    volumes.push_back(*v);
  }
  return SizeWear(volumes, options);
}

std::optional<double> NominalForce(const StoredEnsemble& stored, const std::string& state,
                                   int zone) {
  for (const EnsembleReferenceRow& r : stored.references) {
    if (r.state == state && r.status == "ok" && zone < static_cast<int>(r.max_force_n.size()))
      return r.max_force_n[zone];
  }
  return std::nullopt;
}

GroupSizing SizeGroup(GroupSizing g, const std::vector<const StoredMember*>& members,
                      const StoredEnsemble& stored, const std::vector<std::string>& names,
                      const std::vector<ZoneFamily>& families, const SizingOptions& options) {
  g.members = static_cast<int>(members.size());
  for (const StoredMember* m : members) {
    if (m->zones.size() != names.size()) {
      throw InputError("member " + std::to_string(m->member) + " of state \"" + m->state +
                       "\" has " + std::to_string(m->zones.size()) + " zones, the scene " +
                       std::to_string(names.size()) +
                       ": a draw changes the scene's zones, so zones cannot be compared");
    }
    g.mean_wall_s += m->wall_s / g.members;
    g.mean_cpu_s += m->cpu_s / g.members;
  }
  for (int zone = 0; zone < static_cast<int>(names.size()); ++zone) {
    std::vector<double> forces;
    for (const StoredMember* m : members) forces.push_back(m->zones[zone].max_force_n);
    ZoneSizing z = SizeZone(forces, options);
    z.zone = zone;
    z.name = names[zone];
    z.family = families[zone];
    z.nominal_n = NominalForce(stored, g.state, zone);
    z.impacts = MeanOf(members, zone);
    z.wear = WearOf(members, zone, options);
    g.zones.push_back(std::move(z));
  }
  return g;
}

int HighestSizing(const GroupSizing& g, const std::string& among) {
  int hottest = -1;
  for (int z = 0; z < static_cast<int>(g.zones.size()); ++z) {
    if (g.zones[z].name.find(among) == std::string::npos) continue;
    if (hottest < 0 || g.zones[z].sizing.estimate > g.zones[hottest].sizing.estimate) hottest = z;
  }
  if (hottest < 0) throw InputError("--hottest-among: no zone name holds \"" + among + "\"");
  return hottest;
}

// The hottest zone of each family among the zones whose name holds `among`.
std::vector<FamilyHottest> HottestPerFamily(const GroupSizing& g, const std::string& among) {
  std::vector<FamilyHottest> families;
  for (const ZoneFamily family : {ZoneFamily::kPinPinWire, ZoneFamily::kDuctPad,
                                  ZoneFamily::kPinWrapper, ZoneFamily::kOther}) {
    int hottest = -1;
    for (const ZoneSizing& z : g.zones) {
      if (z.family != family || z.name.find(among) == std::string::npos) continue;
      if (hottest < 0 || z.sizing.estimate > g.zones[hottest].sizing.estimate) hottest = z.zone;
    }
    if (hottest >= 0) families.push_back({family, hottest, std::nullopt});
  }
  return families;
}

const GroupSizing* RefinedOf(const std::vector<GroupSizing>& groups, const std::string& state) {
  for (const GroupSizing& r : groups) {
    if (r.refined && r.state == state) return &r;
  }
  return nullptr;
}

// Each group's hottest zone is its state's at the refined setting (so that settings compare
// the same zone), and each setting is judged against that refined group.
void JudgeAgainstRefined(std::vector<GroupSizing>& groups, const SizingOptions& options) {
  for (GroupSizing& g : groups) {
    const GroupSizing* refined = RefinedOf(groups, g.state);
    g.hottest = HighestSizing(refined != nullptr ? *refined : g, options.hottest_among);
    g.families = HottestPerFamily(refined != nullptr ? *refined : g, options.hottest_among);
  }
  for (GroupSizing& g : groups) {
    const GroupSizing* refined = RefinedOf(groups, g.state);
    if (g.refined || refined == nullptr) continue;
    for (std::size_t z = 0; z < g.zones.size(); ++z) {
      const auto agrees = Agrees(g.zones[z], refined->zones[z], options.tolerance);
      if (agrees) ++(*agrees ? g.zones_agreeing : g.zones_disagreeing);
    }
    g.hottest_agrees = Agrees(g.zones[g.hottest], refined->zones[g.hottest], options.tolerance);
    for (FamilyHottest& f : g.families)
      f.agrees = Agrees(g.zones[f.zone], refined->zones[f.zone], options.tolerance);
  }
}

}  // namespace

std::optional<bool> Agrees(const ZoneSizing& setting, const ZoneSizing& refined, double tolerance) {
  for (const QuantileInterval* q : {&setting.sizing, &refined.sizing}) {
    if (!q->lower_bounded || !q->upper_bounded) return std::nullopt;
  }
  const double slack = tolerance * std::abs(refined.sizing.estimate);
  return setting.sizing.lower - slack <= refined.sizing.upper + slack &&
         refined.sizing.lower - slack <= setting.sizing.upper + slack;
}

ZoneSizing SizeZone(const std::vector<double>& forces, const SizingOptions& options) {
  ZoneSizing z;
  z.members = static_cast<int>(forces.size());
  z.p50 = EstimateQuantile(forces, 0.50, options.confidence);
  z.p95 = EstimateQuantile(forces, 0.95, options.confidence);
  z.p99 = EstimateQuantile(forces, 0.99, options.confidence);
  z.sizing = EstimateQuantile(forces, options.quantile, options.confidence);
  z.wilks_order = WilksHighestOrder(z.members, options.quantile, options.confidence);
  z.wilks = WilksUpperLimit(forces, options.quantile, options.confidence);
  z.bootstrap = BootstrapQuantileInterval(forces, options.quantile, options.confidence,
                                          options.bootstrap_resamples, options.bootstrap_seed);
  return z;
}

WearSizing SizeWear(const std::vector<double>& volumes, const SizingOptions& options) {
  WearSizing w;
  w.sizing = EstimateQuantile(volumes, options.quantile, options.confidence);
  w.wilks_order =
      WilksHighestOrder(static_cast<int>(volumes.size()), options.quantile, options.confidence);
  w.wilks = WilksUpperLimit(volumes, options.quantile, options.confidence);
  for (const double v : volumes) w.mean_m3 += v / static_cast<double>(volumes.size());
  return w;
}

StoredEnsemble CurrentMembers(StoredEnsemble stored) {
  const CurrentSpec spec = ReadCurrentSpec(stored);
  const auto superseded = [&](const StoredMember& m) {
    return !(m.member < spec.members && std::ranges::count(spec.states, m.state) > 0 &&
             IsSettingOf(Json::parse(m.setting_json), spec.settings));
  };
  stored.superseded = static_cast<std::int64_t>(std::erase_if(stored.members, superseded));
  std::erase_if(stored.not_ok, superseded);
  stored.pending = std::count_if(stored.not_ok.begin(), stored.not_ok.end(), [](const auto& m) {
    return m.status == "pending" || m.status == "running";
  });
  stored.failed = static_cast<std::int64_t>(stored.not_ok.size()) - stored.pending;
  return stored;
}

EnsembleSizing SizeEnsemble(const StoredEnsemble& stored, const std::string& study,
                            const SizingOptions& options) {
  CheckOptions(options);
  if (stored.members.empty()) {
    throw InputError("study \"" + study + "\" has no computed member yet (" +
                     std::to_string(stored.pending) + " pending, " + std::to_string(stored.failed) +
                     " failed): run it first");
  }
  EnsembleSizing sizing;
  sizing.study = study;
  sizing.options = options;
  sizing.pending = stored.pending;
  sizing.failed = stored.failed;
  sizing.superseded = stored.superseded;
  std::tie(sizing.zone_names, sizing.zone_families) = ZoneNames(stored);
  const Json spec = Json::parse(stored.spec_json);
  for (auto& [group, members] : Groups(stored, RefinedSetting(spec, stored.members))) {
    sizing.groups.push_back(SizeGroup(std::move(group), members, stored, sizing.zone_names,
                                      sizing.zone_families, options));
  }
  JudgeAgainstRefined(sizing.groups, options);
  return sizing;
}

std::vector<ConvergencePoint> SizingConvergence(const std::vector<double>& forces,
                                                const SizingOptions& options) {
  std::vector<ConvergencePoint> points;
  const int n = static_cast<int>(forces.size());
  for (double x = 10.0;; x *= std::pow(10.0, 1.0 / 12.0)) {
    const int m = std::min(n, static_cast<int>(std::lround(x)));
    if (points.empty() || points.back().members != m) {
      const std::vector<double> first(forces.begin(), forces.begin() + m);
      points.push_back({m, EstimateQuantile(first, options.quantile, options.confidence)});
    }
    if (m == n) break;
  }
  return points;
}

namespace {

// Least-squares slope of log(width) against log(members) over positive widths; NaN with fewer
// than two.
double LogLogSlope(const std::vector<std::pair<int, double>>& widths) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (const auto& [members, width] : widths) {
    if (!(width > 0.0) || !std::isfinite(width)) continue;
    const double x = std::log(members), y = std::log(width);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
  }
  if (count < 2) return std::nan("");
  return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

}  // namespace

double WidthSlope(const std::vector<ConvergencePoint>& points) {
  std::vector<std::pair<int, double>> widths;
  for (const ConvergencePoint& p : points) {
    if (p.sizing.lower_bounded && p.sizing.upper_bounded)
      widths.emplace_back(p.members, p.sizing.upper - p.sizing.lower);
  }
  return LogLogSlope(widths);
}

WidthScaling MeanWidthScaling(const std::vector<double>& forces, const SizingOptions& options,
                              int resamples, std::uint64_t seed) {
  WidthScaling scaling;
  const int n = static_cast<int>(forces.size());
  std::mt19937_64 rng(seed);
  std::vector<double> sample;
  for (double x = 10.0; x <= n * 1.0000001; x *= std::pow(10.0, 1.0 / 12.0)) {
    const int m = static_cast<int>(std::lround(x));
    if (!scaling.mean_width.empty() && scaling.mean_width.back().first == m) continue;
    double sum = 0.0;
    bool bounded = true;
    for (int r = 0; r < resamples && bounded; ++r) {
      sample.resize(m);
      for (double& v : sample) v = forces[rng() % static_cast<std::uint64_t>(n)];
      const QuantileInterval q = EstimateQuantile(sample, options.quantile, options.confidence);
      bounded = q.lower_bounded && q.upper_bounded;
      sum += q.upper - q.lower;
    }
    if (bounded) scaling.mean_width.emplace_back(m, sum / resamples);
  }
  scaling.slope = LogLogSlope(scaling.mean_width);
  return scaling;
}

std::vector<double> ZoneForces(const StoredEnsemble& stored, const GroupSizing& group, int zone) {
  std::vector<double> forces;
  for (const StoredMember& m : stored.members) {
    if (m.state == group.state && m.setting_json == group.setting_json)
      forces.push_back(m.zones[zone].max_force_n);
  }
  return forces;
}

}  // namespace shockmap

#include "specs/ensemble_study_spec.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "compare/scene_run.h"
#include "core/input_error.h"
#include "core/scene_model.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/parameter_path.h"
#include "specs/advice_check_study.h"
#include "specs/study_spec.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// A normal or lognormal law without a bound is clipped this many standard deviations out.
constexpr double kDefaultClipSigmas = 5.0;
constexpr const char* kPinGapPath = "bundle.wire.gap_m";
constexpr const char* kWrapperGapPath = "bundle.wrapper.gap_m";

std::uint64_t ParseSeed(JsonObjectReader& r) {
  const Json* v = r.Get("seed");
  if (v == nullptr) r.Fail("seed", "required: a non-negative integer, e.g. 2026");
  if (!v->is_number_unsigned()) {
    r.Fail("seed", "expected a non-negative integer, got " + Shown(*v));
  }
  return v->get<std::uint64_t>();
}

int ParseMembers(JsonObjectReader& r) {
  if (!r.Has("members")) r.Fail("members", "required: the number of members, e.g. 200");
  const int members = r.Integer("members", 0);
  if (members < 1 || members > kMaxEnsembleMembers) {
    r.Fail("members", "value " + std::to_string(members) + " must lie in [1, " +
                          std::to_string(kMaxEnsembleMembers) + "]");
  }
  return members;
}

// {"normal": {"mean"?, "std", "min"?, "max"?}}, {"lognormal": {"median"?, "sigma", "min"?,
// "max"?}} or {"uniform": {"min", "max"}}; the centre defaults to the scene's value.
ParameterScatter ParseScatter(const Json& value, double scene_value, const std::string& file,
                              const std::string& where) {
  JsonObjectReader r(value, file, where);
  if (!value.is_object() || value.size() != 1) {
    FailAt(file, where,
           "expected one law: {\"normal\": {\"std\": s}}, {\"lognormal\": {\"sigma\": s}} or "
           "{\"uniform\": {\"min\": a, \"max\": b}}, got " +
               Shown(value));
  }
  ParameterScatter s;
  const std::string law = value.begin().key();
  JsonObjectReader l(*r.Get(law), file, r.PathOf(law));
  if (law == "normal") {
    s.law = ScatterLaw::kNormal;
    s.centre = l.Number("mean", scene_value);
    s.spread = l.RequiredNumber("std");
    if (!(s.spread >= 0.0)) l.Fail("std", "value " + Shown(Json(s.spread)) + " must be >= 0");
    s.min = l.Number("min", s.centre - kDefaultClipSigmas * s.spread);
    s.max = l.Number("max", s.centre + kDefaultClipSigmas * s.spread);
  } else if (law == "lognormal") {
    s.law = ScatterLaw::kLognormal;
    s.centre = l.Number("median", scene_value);
    if (!(s.centre > 0.0)) l.Fail("median", "value " + Shown(Json(s.centre)) + " must be > 0");
    s.spread = l.RequiredNumber("sigma");
    if (!(s.spread >= 0.0) || s.spread > 3.0)
      l.Fail("sigma", "value " + Shown(Json(s.spread)) + " must lie in [0, 3]");
    s.min = l.Number("min", s.centre * std::exp(-kDefaultClipSigmas * s.spread));
    s.max = l.Number("max", s.centre * std::exp(kDefaultClipSigmas * s.spread));
  } else if (law == "uniform") {
    s.law = ScatterLaw::kUniform;
    s.min = l.RequiredNumber("min");
    s.max = l.RequiredNumber("max");
    s.centre = 0.5 * (s.min + s.max);
  } else {
    r.Fail(law,
           "\"" + Excerpt(law) + "\" is not a law: use \"normal\", \"lognormal\" or \"uniform\"");
  }
  if (!(s.min <= s.max)) {
    l.Fail("max", "the bounds [" + Shown(Json(s.min)) + ", " + Shown(Json(s.max)) +
                      "] are empty: min must not exceed max");
  }
  l.Finish();
  return s;
}

std::vector<ParameterScatter> ParseDraws(JsonObjectReader& r, const Json& scene,
                                         const std::string& file) {
  std::vector<ParameterScatter> draws;
  const Json* v = r.Get("draws");
  if (v == nullptr) return draws;
  if (!v->is_object())
    r.Fail("draws", "expected {\"parameter.path\": {law}, ...}, got " + Shown(*v));
  for (const auto& [path, law] : v->items()) {
    const std::string where = r.PathOf("draws") + "." + path;
    const auto pointer = NumericParameter(scene, path, file, where);
    ParameterScatter s = ParseScatter(law, scene.at(pointer).get<double>(), file, where);
    s.path = path;
    draws.push_back(std::move(s));
  }
  return draws;
}

// "impact_statistics": the counting of a scene's outputs.impact_statistics, its window inside
// the study's window_s.
std::optional<ImpactCounting> ParseStudyImpactCounting(JsonObjectReader& r, double window_s) {
  const Json* v = r.Get("impact_statistics");
  if (v == nullptr) return std::nullopt;
  JsonObjectReader im(*v, r.File(), r.PathOf("impact_statistics"));
  const ImpactCounting counting = ParseImpactCounting(im, window_s, "window_s");
  im.Finish();
  return counting;
}

GapLaw ParseGapLaw(const Json& value, const std::string& file, const std::string& where) {
  JsonObjectReader r(value, file, where);
  GapLaw g;
  g.mean_m = r.RequiredNumber("mean");
  g.std_m = r.Number("std", 0.0);
  g.min_m = r.Number("min", 0.0);
  r.Finish();
  if (std::abs(g.mean_m) > 1.0)
    r.Fail("mean", "value " + Shown(Json(g.mean_m)) + " must lie in [-1, 1] m");
  if (!(g.std_m >= 0.0) || g.std_m > 1.0)
    r.Fail("std", "value " + Shown(Json(g.std_m)) + " must lie in [0, 1] m");
  if (std::abs(g.min_m) > 1.0)
    r.Fail("min", "value " + Shown(Json(g.min_m)) +
                      " must lie in [-1, 1] m (a negative gap is a preloaded contact)");
  if (g.min_m > g.mean_m)
    r.Fail("min", "value " + Shown(Json(g.min_m)) + " m" + (r.Has("min") ? "" : " (the default)") +
                      " lies above the mean " + Shown(Json(g.mean_m)) +
                      " m: the nominal run, at the mean, would have a gap no member has");
  return g;
}

std::vector<ClearanceState> ParseStates(JsonObjectReader& r, const Json& scene,
                                        const std::string& file) {
  const Json* v = r.Get("clearance_states");
  if (v == nullptr) return {ClearanceState{"scene", std::nullopt, std::nullopt}};
  if (!v->is_array() || v->empty()) {
    r.Fail("clearance_states",
           "expected a non-empty list of {\"name\", \"pin_gap_m\": {\"mean\", "
           "\"std\", \"min\"}, \"wrapper_gap_m\"?: {...}}, got " +
               Shown(*v));
  }
  if (!scene.contains("bundle")) {
    r.Fail("clearance_states",
           "the scene has no \"bundle\": clearance states set the gaps of a "
           "bundle's wires (bundle.wire.gap_m) and wrapper");
  }
  std::vector<ClearanceState> states;
  std::set<std::string> names;
  std::map<std::string, std::string> by_file_part;  // Lower-case file name part -> name.
  for (std::size_t i = 0; i < v->size(); ++i) {
    JsonObjectReader s((*v)[i], file, r.PathOf("clearance_states") + "[" + std::to_string(i) + "]");
    ClearanceState state;
    state.name = s.RequiredName("name");
    if (state.name.empty() || state.name.size() > 100)
      s.Fail("name", "must be 1 to 100 characters");
    if (!names.insert(state.name).second)
      s.Fail("name", "state \"" + state.name + "\" is given twice; names must be unique");
    std::string part = FileNamePart(state.name);
    std::transform(part.begin(), part.end(), part.begin(), ::tolower);
    if (const auto [it, fresh] = by_file_part.emplace(part, state.name); !fresh) {
      const std::string same = "\" would write the same picture files as state \"";
      s.Fail("name", "state \"" + Excerpt(state.name) + same + Excerpt(it->second) + "\" (map_" +
                         FileNamePart(state.name) +
                         ".png): names must differ in a letter (not only in case), a digit, '-' "
                         "or '_'");
    }
    const Json* pin = s.Get("pin_gap_m");
    if (pin == nullptr) s.Fail("pin_gap_m", "required: {\"mean\": m, \"std\": m, \"min\": m}");
    state.pin_gap = ParseGapLaw(*pin, file, s.PathOf("pin_gap_m"));
    if (const Json* wrapper = s.Get("wrapper_gap_m")) {
      state.wrapper_gap = ParseGapLaw(*wrapper, file, s.PathOf("wrapper_gap_m"));
    }
    s.Finish();
    states.push_back(std::move(state));
  }
  return states;
}

// "scene_set": {"path": value, ...}: numbers or true/false written into the scene before
// anything else reads it, so that keys the scene leaves at their default (a bundle pin's own
// "r_ftrunc") can then be set by "settings". Each path's parent object must be in the scene.
void ApplySceneSet(JsonObjectReader& r, Json& scene) {
  const Json* v = r.Get("scene_set");
  if (v == nullptr) return;
  if (!v->is_object())
    r.Fail("scene_set", "expected {\"parameter.path\": value, ...}, got " + Shown(*v));
  for (const auto& [path, value] : v->items()) {
    const std::string where = r.PathOf("scene_set") + "." + path;
    const auto pointer = ParameterPointer(path);
    if (!pointer) FailAt(r.File(), where, "is not a parameter path (keys joined by dots)");
    if (!value.is_number() && !value.is_boolean())
      FailAt(r.File(), where, "expected a number or true/false, got " + Shown(value));
    if (!scene.contains(pointer->parent_pointer()) ||
        !scene.at(pointer->parent_pointer()).is_object())
      FailAt(r.File(), where, "the scene has no object to hold it");
    scene[*pointer] = value;
  }
}

using SettingAxes = std::vector<std::pair<std::string, std::vector<Json>>>;

// "settings": {"path": [values...], ...}, the axes whose full product is run.
SettingAxes ParseSettingAxes(const Json& v, const Json& scene, const std::string& file,
                             const std::string& where) {
  SettingAxes axes;
  for (const auto& [path, values] : v.items()) {
    const std::string at = where + "." + path;
    if (!values.is_array() || values.empty())
      FailAt(file, at, "expected a non-empty list of numbers or true/false, got " + Shown(values));
    for (std::size_t i = 0; i < values.size(); ++i) {
      SameTypeParameter(scene, path, values[i], file, at + "[" + std::to_string(i) + "]");
    }
    axes.emplace_back(path, std::vector<Json>(values.begin(), values.end()));
  }
  return axes;
}

std::vector<Json> SettingProduct(const SettingAxes& axes) {
  std::vector<Json> settings = {Json::object()};
  for (const auto& [path, values] : axes) {
    std::vector<Json> next;
    for (const Json& s : settings) {
      for (const Json& value : values) {
        Json t = s;
        t[path] = value;
        next.push_back(std::move(t));
      }
    }
    settings = std::move(next);
  }
  std::sort(settings.begin(), settings.end());
  settings.erase(std::unique(settings.begin(), settings.end()), settings.end());
  return settings;
}

// "settings": [{"path": value, ...}, ...], settings listed one by one (parameters that change
// together, e.g. each beam's truncation and the mesh resolving it), in the file's order; each
// sets the same paths, and no two are equal.
std::vector<Json> ParseSettingList(const Json& v, const Json& scene, const std::string& file,
                                   const std::string& where) {
  std::vector<Json> settings;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Json& setting = v[i];
    const std::string at = where + "[" + std::to_string(i) + "]";
    if (!setting.is_object() || setting.empty())
      FailAt(file, at, "expected {\"parameter.path\": value, ...}, got " + Shown(setting));
    for (const auto& [path, value] : setting.items()) {
      SameTypeParameter(scene, path, value, file, at + "." + path);
      if (!v[0].contains(path))
        FailAt(file, at + "." + path,
               "is not set by " + where + "[0]: every setting sets the same paths");
    }
    if (setting.size() != v[0].size())
      FailAt(file, at, "sets other paths than " + where + "[0]: every setting sets the same paths");
    if (std::ranges::find(settings, setting) != settings.end())
      FailAt(file, at, Shown(setting) + " is listed twice");
    settings.push_back(setting);
  }
  return settings;
}

// The numerical settings: the product of axes, a list, or (absent) the one empty setting.
std::vector<Json> ParseSettings(JsonObjectReader& r, const Json& scene, const std::string& file) {
  const Json* v = r.Get("settings");
  if (v == nullptr) return {Json::object()};
  const std::string where = r.PathOf("settings");
  if (v->is_array() && !v->empty()) return ParseSettingList(*v, scene, file, where);
  if (!v->is_object() || v->empty()) {
    r.Fail("settings",
           "expected {\"parameter.path\": [values...], ...} (their product), e.g. "
           "{\"solver.r_ftrunc\": [30, 100, 300, 1000]}, or a list of settings "
           "[{\"parameter.path\": value, ...}, ...], got " +
               Shown(*v));
  }
  return SettingProduct(ParseSettingAxes(*v, scene, file, where));
}

int ParseRefined(JsonObjectReader& r, const std::vector<Json>& settings) {
  const Json* v = r.Get("refined");
  if (v == nullptr) {
    if (settings.size() == 1) return 0;
    r.Fail("refined",
           "required with more than one setting: the setting the others are judged "
           "against, e.g. {\"solver.r_ftrunc\": 1000}");
  }
  const auto found = std::find(settings.begin(), settings.end(), *v);
  if (found == settings.end()) {
    std::string allowed;
    for (const Json& s : settings) allowed += (allowed.empty() ? "" : ", ") + s.dump();
    r.Fail("refined", Shown(*v) + " is not one of the settings: " + allowed);
  }
  return static_cast<int>(found - settings.begin());
}

Json GapJson(const GapLaw& law, int seed) {
  return Json{
      {"normal", {{"mean", law.mean_m}, {"std", law.std_m}, {"min", law.min_m}, {"seed", seed}}}};
}

// The scene JSON of a state and setting with `values` of the draws applied.
Json VariantJson(const EnsembleStudySpec& spec, int state, int setting,
                 const std::vector<double>& values, std::uint64_t member_seed) {
  Json variant = spec.scene;
  for (const auto& [path, value] : spec.settings[setting].items()) {
    variant[*ParameterPointer(path)] = value;
  }
  for (std::size_t i = 0; i < spec.draws.size(); ++i) {
    variant[*ParameterPointer(spec.draws[i].path)] = values[i];
  }
  const ClearanceState& s = spec.states[state];
  if (s.pin_gap)
    variant[*ParameterPointer(kPinGapPath)] = GapJson(*s.pin_gap, GapSeed(member_seed, 1));
  if (s.wrapper_gap) {
    variant[*ParameterPointer(kWrapperGapPath)] = GapJson(*s.wrapper_gap, GapSeed(member_seed, 2));
  }
  return variant;
}

Scene SceneOf(const EnsembleStudySpec& spec, const Json& variant) {
  Scene scene = ParseScene(variant, spec.scene_file, spec.access);
  SceneOutputs outputs;
  outputs.max_contact_force = true;
  if (spec.impact_counting) {
    outputs.impact_statistics = true;
    outputs.impact_counting = *spec.impact_counting;
    outputs.impact_table_zones = scene.outputs.impact_table_zones;
  }
  scene.outputs = outputs;
  scene.solver.end_time_s = spec.window_s;
  return scene;
}

std::vector<double> Centres(const EnsembleStudySpec& spec) {
  std::vector<double> centres;
  for (const ParameterScatter& s : spec.draws) centres.push_back(s.centre);
  return centres;
}

// Where a checked scene is, for messages: state "<name>", setting <setting>.
std::string Where(const EnsembleStudySpec& spec, int state, int setting) {
  return "state \"" + spec.states[state].name + "\", setting " + spec.settings[setting].dump();
}

// Throws InputError "<file>: <where>: <reason>" when the model of `scene` cannot be built (a
// preload's static equilibrium not found), and "<file>: window_s: <value> s in <where>: <reason>"
// unless its run takes at least one time step (a shorter window has nothing to size), at most
// TransientOptions::max_steps steps and records histories of an affordable size
// (compare/scene_run.h).
void CheckModelAndWindow(const EnsembleStudySpec& spec, const Scene& scene,
                         const std::string& where) {
  SceneModel model;
  try {
    model = BuildSceneModel(scene);
  } catch (const InputError& e) {
    throw InputError(spec.file + ": " + where + ": " + e.what());
  }
  const std::string window =
      spec.file + ": window_s: " + Shown(Json(spec.window_s)) + " s in " + where + ": ";
  const double dt_s = scene.solver.dt.Resolve(model.bounds);
  if (spec.window_s < dt_s) {
    throw InputError(window + fmt::format("shorter than one time step ({:g} s): a member would "
                                          "have nothing to size; it must hold at least one step",
                                          dt_s));
  }
  try {
    CheckSceneAffordable(scene, std::move(model));
  } catch (const InputError& e) {
    throw InputError(window + e.what());
  }
}

// Every state and setting at the draws' centres and with each draw at both its bounds: each
// scene valid, its model built (a preload's static equilibrium found) and affordable (a
// member's dt follows its setting and its draws through the stability bound). An invalid scene
// or a model not built is refused naming the state and setting, an unaffordable one naming
// window_s.
void CheckScenes(const EnsembleStudySpec& spec) {
  const std::vector<double> centres = Centres(spec);
  auto check = [&](int state, int setting, const std::vector<double>& values,
                   const std::string& what) {
    Scene scene;
    try {
      scene = SceneOf(spec, VariantJson(spec, state, setting, values, 0));
    } catch (const InputError& e) {
      throw InputError(spec.file + ": " + Where(spec, state, setting) + what + ": " + e.what());
    }
    CheckModelAndWindow(spec, scene, Where(spec, state, setting) + what);
  };
  for (int state = 0; state < static_cast<int>(spec.states.size()); ++state) {
    for (int setting = 0; setting < static_cast<int>(spec.settings.size()); ++setting) {
      check(state, setting, centres, "");
      for (std::size_t i = 0; i < spec.draws.size(); ++i) {
        for (const double bound : {spec.draws[i].min, spec.draws[i].max}) {
          std::vector<double> values = centres;
          values[i] = bound;
          check(state, setting, values,
                ", draws." + spec.draws[i].path + " at its bound " + Shown(Json(bound)));
        }
      }
    }
  }
}

// A path may be set by one of: the draws, the settings, the clearance states.
void CheckDisjointPaths(JsonObjectReader& r, const EnsembleStudySpec& spec) {
  std::set<std::string> drawn;
  for (const ParameterScatter& s : spec.draws) drawn.insert(s.path);
  const bool states_set_gaps = spec.states.front().pin_gap.has_value();
  for (const std::string& path : drawn) {
    if (states_set_gaps && (path.starts_with(kPinGapPath) || path.starts_with(kWrapperGapPath)))
      r.Fail("draws", "\"" + path + "\" is set by the clearance states; draw it there");
  }
  for (const auto& [path, _] : spec.settings.front().items()) {
    if (drawn.contains(path)) r.Fail("settings", "\"" + path + "\" is also drawn in \"draws\"");
  }
}

std::vector<EnsembleMember> MemberMajor(const EnsembleStudySpec& spec) {
  std::vector<EnsembleMember> points;
  for (int m = 0; m < spec.members; ++m) {
    for (int state = 0; state < static_cast<int>(spec.states.size()); ++state) {
      for (int setting = 0; setting < static_cast<int>(spec.settings.size()); ++setting) {
        points.push_back({state, setting, m});
      }
    }
  }
  return points;
}

}  // namespace

EnsembleStudySpec ParseEnsembleStudySpec(const Json& json, const std::string& file,
                                         const SceneFileAccess& access) {
  EnsembleStudySpec spec;
  spec.file = file;
  spec.access = access;
  JsonObjectReader r(json, file, "");
  std::tie(spec.name, spec.description) = ReadStudyTitle(r, "scene_ensemble");
  spec.scene_file =
      (std::filesystem::path(file).parent_path() / r.RequiredString("scene")).lexically_normal();
  spec.scene = ReadJsonFile(spec.scene_file);
  ApplySceneSet(r, spec.scene);
  const Scene base = ParseScene(spec.scene, spec.scene_file, access);
  spec.seed = ParseSeed(r);
  spec.members = ParseMembers(r);
  spec.window_s = r.Number("window_s", base.solver.end_time_s);
  if (!(spec.window_s > 0.0) || spec.window_s > 1e4)
    r.Fail("window_s", "value " + Shown(Json(spec.window_s)) + " must lie in (0, 1e4] s");
  spec.impact_counting = ParseStudyImpactCounting(r, spec.window_s);
  spec.draws = ParseDraws(r, spec.scene, file);
  spec.states = ParseStates(r, spec.scene, file);
  spec.settings = ParseSettings(r, spec.scene, file);
  spec.refined = ParseRefined(r, spec.settings);
  if (const Json* ladder = r.Get("advice_check")) {
    ParseAdviceCheckRecord(*ladder, file, r.PathOf("advice_check"), spec.settings.size());
  }
  const double points =
      static_cast<double>(spec.members) * spec.states.size() * spec.settings.size();
  if (points > static_cast<double>(kMaxStudyPoints)) {
    r.Fail("members", std::to_string(spec.members) + " members over " +
                          std::to_string(spec.states.size()) + " states and " +
                          std::to_string(spec.settings.size()) + " settings make " +
                          Shown(Json(points)) + " runs: at most " +
                          std::to_string(kMaxStudyPoints) + " are allowed");
  }
  CheckDisjointPaths(r, spec);
  r.Finish();
  CheckScenes(spec);
  for (int state = 0; state < static_cast<int>(spec.states.size()); ++state) {
    CheckModelAndWindow(spec, NominalScene(spec, state),
                        Where(spec, state, spec.refined) + " (its nominal run)");
  }
  spec.points = MemberMajor(spec);
  Json stored = json;
  stored["scene_json"] = spec.scene;
  stored["settings_key"] = Json::parse(EnsembleSettingsKey(spec));
  spec.spec_json = stored.dump();
  return spec;
}

std::uint64_t MemberSeedOf(const EnsembleStudySpec& spec, const EnsembleMember& m) {
  return MemberSeed(spec.seed, spec.states[m.state].name, m.member);
}

Scene MemberScene(const EnsembleStudySpec& spec, const EnsembleMember& m) {
  const std::uint64_t seed = MemberSeedOf(spec, m);
  return SceneOf(spec,
                 VariantJson(spec, m.state, m.setting, DrawParameters(spec.draws, seed), seed));
}

Scene NominalScene(const EnsembleStudySpec& spec, int state) {
  EnsembleStudySpec nominal_gaps = spec;
  for (ClearanceState& s : nominal_gaps.states) {
    if (s.pin_gap)
      s.pin_gap->std_m = 0.0, s.pin_gap->min_m = std::min(s.pin_gap->min_m, s.pin_gap->mean_m);
    if (s.wrapper_gap)
      s.wrapper_gap->std_m = 0.0,
      s.wrapper_gap->min_m = std::min(s.wrapper_gap->min_m, s.wrapper_gap->mean_m);
  }
  return SceneOf(spec, VariantJson(nominal_gaps, state, spec.refined, Centres(spec), 0));
}

std::string MemberKey(const EnsembleStudySpec& spec, const EnsembleMember& m) {
  return Json{{"member", m.member},
              {"setting", spec.settings[m.setting]},
              {"state", spec.states[m.state].name}}
      .dump();
}

Json StateJson(const ClearanceState& state) {
  auto law = [](const std::optional<GapLaw>& g) {
    return g ? Json{{"mean", g->mean_m}, {"std", g->std_m}, {"min", g->min_m}} : Json();
  };
  return Json{{"pin_gap_m", law(state.pin_gap)}, {"wrapper_gap_m", law(state.wrapper_gap)}};
}

namespace {
Json DrawsJson(const EnsembleStudySpec& spec) {
  Json draws = Json::object();
  for (const ParameterScatter& s : spec.draws) {
    draws[s.path] = {{"law", ToString(s.law)},
                     {"centre", s.centre},
                     {"spread", s.spread},
                     {"min", s.min},
                     {"max", s.max}};
  }
  return draws;
}
}  // namespace

namespace {
Json ImpactCountingJson(const EnsembleStudySpec& spec) {
  if (!spec.impact_counting) return Json();
  const ImpactCounting& c = *spec.impact_counting;
  Json counting = {{"rest_duration_s", c.rest_duration_s},
                   {"force_threshold_n", c.force_threshold_n}};
  // Only where they differ from the defaults, so that studies stored before they existed keep
  // their key.
  if (c.convention != ImpactConvention::kShockmap) counting["convention"] = ToString(c.convention);
  if (c.window_start_s != 0.0 || c.window_end_s != spec.window_s)
    counting["window_s"] = {c.window_start_s, c.window_end_s};
  return counting;
}
}  // namespace

std::string NominalKey(const EnsembleStudySpec& spec, int state) {
  return Json{{"ensemble_nominal", true},
              {"scene", spec.scene},
              {"draws", DrawsJson(spec)},
              {"state", StateJson(spec.states[state])},
              {"state_name", spec.states[state].name},
              {"setting", spec.settings[spec.refined]},
              {"window_s", spec.window_s}}
      .dump();
}

std::string EnsembleSettingsKey(const EnsembleStudySpec& spec) {
  Json states = Json::object();
  for (const ClearanceState& s : spec.states) states[s.name] = StateJson(s);
  return Json{{"scene", spec.scene},
              {"seed", spec.seed},
              {"draws", DrawsJson(spec)},
              {"states", states},
              {"impact_counting", ImpactCountingJson(spec)},
              {"window_s", spec.window_s}}
      .dump();
}

}  // namespace shockmap

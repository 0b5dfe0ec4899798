#include "specs/advice_check_study.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/cantilever_impact.h"
#include "core/input_error.h"
#include "core/stability_bounds.h"
#include "formats/json_reader.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// The least and the largest truncation a scene file takes (formats/scene_file.cpp).
constexpr double kMinRFtrunc = 1.0;
constexpr double kMaxRFtrunc = 1e5;

bool IsPin(const std::string& name) { return name.starts_with("pin_"); }

// The setting path of a beam's key: the bundle's pin or wrapper (which the bundle generator
// names so, and no listed beam may be named like), else the listed beam's in the scene file.
std::string BeamPath(const Json& scene_json, const std::string& beam, const std::string& key) {
  if (scene_json.contains("bundle") && IsPin(beam)) return "bundle.pin." + key;
  if (scene_json.contains("bundle") && beam == "wrapper") return "bundle.wrapper." + key;
  const Json& listed = scene_json.at("beams");
  const auto it = std::ranges::find_if(
      listed, [&](const Json& b) { return b.value("name", std::string()) == beam; });
  return fmt::format("beams[{}].{}", it - listed.begin(), key);
}

const SceneBeam& BeamNamed(const Scene& scene, const std::string& name) {
  return *std::ranges::find(scene.beams, name, &SceneBeam::name);
}

// The criteria file's truncation criterion, for messages: its fit's c and p when it has one.
std::string TruncationCriterion(const Json& criteria_json) {
  const auto fit = criteria_json.find("fit");
  if (fit == criteria_json.end() || !fit->is_object()) return "boundary";
  return "fit.c = " + Shown(fit->value("c", Json())) +
         ", fit.p = " + Shown(fit->value("p", Json()));
}

}  // namespace

std::vector<double> LadderFactors(int rungs) {
  std::vector<double> factors = {1.0 / 3.0};
  for (int k = 0; static_cast<int>(factors.size()) < rungs; ++k)
    factors.push_back(std::pow(3.0, k));
  return factors;
}

bool RungFits(const SceneAdvice& advice, double factor) {
  return std::ranges::all_of(
      advice.beams, [&](const BeamAdvice& b) { return b.r_ftrunc * factor <= kMaxRFtrunc; });
}

void CheckLowestRung(const SceneAdvice& advice, double factor, const std::string& criteria_file,
                     const Json& criteria_json) {
  for (const BeamAdvice& b : advice.beams) {
    if (b.r_ftrunc * factor >= kMinRFtrunc) continue;
    throw InputError(fmt::format(
        "{}: {}: the criteria advise R_ftrunc {:.4g} for beam {}, so the "
        "ladder's lowest rung (x {:.4g}) would be {:.4g}, below {:g}, the least truncation a "
        "scene takes; check-advice needs every advised truncation to be at least {:.4g} "
        "(`shockmap advise` gives the advice unchecked)",
        criteria_file, TruncationCriterion(criteria_json), b.r_ftrunc, b.name, factor,
        b.r_ftrunc * factor, kMinRFtrunc, kMinRFtrunc / factor));
  }
}

Json RungSetting(const Json& scene_json, const Scene& scene, const SceneAdvice& advice,
                 double factor) {
  if (scene.solver.dt.dt_s || scene.solver.dt.rule != DtRule::kSharp) {
    throw InputError(
        "solver.dt: the scene's time step is not a factor of the sharp bound ({\"rule\": "
        "\"sharp\", \"factor\": x}); the advice gives dt / dt_sharp");
  }
  Json setting = Json::object();
  for (const BeamAdvice& b : advice.beams) {
    const double r_ftrunc = b.r_ftrunc * factor;
    if (r_ftrunc > kMaxRFtrunc) {
      throw InputError(
          fmt::format("beam {}: the ladder's truncation {:.4g} (x {:.4g} of the "
                      "advised {:.4g}) exceeds the largest allowed, {:g}",
                      b.name, r_ftrunc, factor, b.r_ftrunc, kMaxRFtrunc));
    }
    // A structure's mesh is its FE code's: only its truncation climbs the ladder.
    const auto structure = std::ranges::find(scene.structures, b.name, &SceneStructure::name);
    if (structure != scene.structures.end()) {
      setting[fmt::format("structures[{}].r_ftrunc", structure - scene.structures.begin())] =
          std::round(r_ftrunc * 1e3) / 1e3;
      continue;
    }
    const std::string path = BeamPath(scene_json, b.name, "r_ftrunc");
    const int elements =
        std::max(BeamNamed(scene, b.name).n_elements, DefaultElementCount(r_ftrunc));
    // A bundle's pins share one setting: the largest any of them needs.
    const double rounded = std::round(r_ftrunc * 1e3) / 1e3;
    setting[path] = std::max(setting.value(path, 0.0), rounded);
    const std::string mesh = BeamPath(scene_json, b.name, "elements");
    setting[mesh] = std::max(setting.value(mesh, 0), elements);
  }
  setting["solver.dt.factor"] = advice.dt_ratio;
  return setting;
}

Json AdviceCheckRecordJson(const AdviceCheckRecord& r) {
  return {{"factors", r.factors},
          {"advised", r.advised},
          {"quantile", r.quantile},
          {"tolerance", r.tolerance}};
}

AdviceCheckRecord ParseAdviceCheckRecord(const Json& json, const std::string& file,
                                         const std::string& where, std::size_t settings) {
  JsonObjectReader r(json, file, where);
  AdviceCheckRecord record;
  const Json* factors = r.Get("factors");
  if (factors == nullptr || !factors->is_array() || factors->size() != settings)
    r.Fail("factors", fmt::format("expected a list of {} numbers, one per setting", settings));
  for (const Json& f : *factors) {
    const double factor = f.is_number() ? f.get<double>() : 0.0;
    if (!(factor > 0.0) || !std::isfinite(factor) ||
        (!record.factors.empty() && factor <= record.factors.back()))
      r.Fail("factors", Shown(f) + " is not a positive number above the one before");
    record.factors.push_back(factor);
  }
  record.advised = r.Integer("advised", record.advised);
  if (record.advised < 0 || record.advised >= static_cast<int>(settings))
    r.Fail("advised", fmt::format("{} is not a rung from 0 to {}", record.advised, settings - 1));
  record.quantile = r.Number("quantile", record.quantile);
  if (!(record.quantile > 0.0 && record.quantile < 1.0))
    r.Fail("quantile", Shown(Json(record.quantile)) + " does not lie in (0, 1)");
  record.tolerance = r.Number("tolerance", record.tolerance);
  if (!(record.tolerance >= 0.0 && record.tolerance <= 1.0))
    r.Fail("tolerance", Shown(Json(record.tolerance)) + " does not lie in [0, 1]");
  r.Finish();
  return record;
}

Json AdviceCheckStudy(const Json& ensemble, const std::string& file, const Json& scene_json,
                      const Scene& scene, const SceneAdvice& advice,
                      const AdviceCheckRecord& record, int members, double window_s) {
  const std::vector<double>& factors = record.factors;
  Json study = ensemble;
  const std::string name = ensemble.value("name", std::string("ensemble"));
  study["name"] = name + "_advice_check";
  study["description"] = fmt::format(
      "The advice of `shockmap advise` for the scene of study {} checked on its members: every "
      "beam's advised truncation times {} on the same draws (shockmap check-advice).",
      name, fmt::format("{:.4g}", fmt::join(factors, ", ")));
  study["scene"] = std::filesystem::absolute(std::filesystem::path(file).parent_path() /
                                             ensemble.at("scene").get<std::string>())
                       .lexically_normal()
                       .string();
  if (members > 0) study["members"] = members;
  if (window_s > 0.0) study["window_s"] = window_s;
  Json settings = Json::array();
  for (double f : factors) settings.push_back(RungSetting(scene_json, scene, advice, f));
  Json scene_set = Json::object();
  for (const auto& [path, value] : settings.front().items()) {
    if (path == "solver.dt.factor") continue;
    scene_set[path] = value;  // Any value: the settings set it.
  }
  study["scene_set"] = scene_set;
  study["settings"] = settings;
  study["refined"] = settings.back();
  study["advice_check"] = AdviceCheckRecordJson(record);
  return study;
}

}  // namespace shockmap

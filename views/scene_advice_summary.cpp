#include "views/scene_advice_summary.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace shockmap {
namespace {

// "bundle_row_ensemble: P95 of 120 members per state and rung (states new, end_of_life) over
// the first 0.1 s, tolerance 5 %; recorded in FILE".
std::string CheckSource(const AdviceCheckOutcome& c, const std::string& checks_file) {
  return fmt::format(
      "{}: P{:g} of {} members per state and rung ({} {}) over the first {:g} s, tolerance "
      "{:g} %; recorded in {}",
      c.study, 100.0 * c.quantile, c.members, c.states.size() == 1 ? "state" : "states",
      fmt::join(c.states, ", "), c.window_s, 100.0 * c.tolerance, checks_file);
}

// The check on the scene's ensemble, then what the single-beam criteria did not measure: as
// such where the check held the advice, else as warnings with the check that answers them.
std::string CheckLines(const SceneAdvice& a, const AdviceCheckOutcome* check,
                       const std::string& checks_file) {
  std::string s;
  if (check != nullptr && check->Held()) {
    s += fmt::format(
        "  checked      on the scene's ensemble: the advice held at {} of {} state and zone "
        "family pairs ({})\n",
        check->held, check->pairs, CheckSource(*check, checks_file));
    for (const std::string& w : a.warnings) s += "  one beam     " + w + "\n";
    return s;
  }
  if (check != nullptr) {
    s += fmt::format(
        "  warning      on the scene's ensemble the advice held at only {} of {} "
        "state and zone family pairs ({}): {}\n",
        check->held, check->pairs, CheckSource(*check, checks_file), check->verdict);
  }
  for (const std::string& w : a.warnings) s += "  warning      " + w + "\n";
  if (check == nullptr && !a.warnings.empty()) {
    s += "  hint         check the advice on an ensemble of the scene: shockmap check-advice "
         "STUDY.json --record FILE, then advise --checks FILE (docs/ensembles.md)\n";
  }
  return s;
}

// How each power law was made a stiffness for R_k: its tangent p k d_b^(p-1) at the bound
// penetration d_b, one line per law, naming its first zone and how many share it.
std::string PowerLawLines(const Scene& scene) {
  struct Shared {
    const SceneZone* first;
    int zones;
  };
  std::vector<Shared> laws;
  for (const SceneZone& z : scene.zones) {
    if (!z.power_law) continue;
    const auto same = std::ranges::find_if(laws, [&](const Shared& l) {
      const ScenePowerLaw& a = *l.first->power_law;
      return a.coefficient == z.power_law->coefficient && a.exponent == z.power_law->exponent &&
             a.bound_penetration_m == z.power_law->bound_penetration_m;
    });
    if (same != laws.end()) {
      ++same->zones;
    } else {
      laws.push_back({&z, 1});
    }
  }
  std::string s;
  for (const Shared& l : laws) {
    const ScenePowerLaw& law = *l.first->power_law;
    s += fmt::format(
        "  power law    zone {}{}: F = k d^{:g} (k = {:.4g} N/m^{:g}) linearised as its tangent "
        "stiffness p k d_b^(p-1) = {:.4g} N/m at the bound penetration d_b = {:.4g} m "
        "(power_law.bound_penetration_m); R_k above is taken from it, and a zone pressed deeper "
        "is stiffer\n",
        l.first->name,
        l.zones > 1 ? fmt::format(" and {} more with the same law", l.zones - 1) : "", law.exponent,
        law.coefficient, law.exponent, l.first->stiffness_n_per_m, law.bound_penetration_m);
  }
  return s;
}

}  // namespace

std::string SceneAdviceSummary(const Scene& scene, const SceneAdvice& a, bool every_zone,
                               const AdviceCheckOutcome* check, const std::string& checks_file) {
  std::string s = fmt::format("advice for scene {} ({} zones)\n", scene.name, a.zones.size());
  s += fmt::format("  {:<14} {:>5} {:>10} {:<28} {:>10} {:>10}\n", "beam", "zones", "max R_k",
                   "at zone", "R_ftrunc", "scene's");
  for (const BeamAdvice& b : a.beams) {
    s += fmt::format("  {:<14} {:>5} {:>10.3g} {:<28} {:>10.4g} {:>10.4g}\n", b.name, b.zones,
                     b.r_k_max, b.stiffest_zone, b.r_ftrunc, b.r_ftrunc_scene);
  }
  s += fmt::format(
      "  dt           {:.4g} s = {:.3g} x the sharp bound {:.4g} s at the advised truncations "
      "(the scene asks for {:.4g} s)\n",
      a.dt_s, a.dt_ratio, a.dt_sharp_s, a.scene_dt_s);
  s += PowerLawLines(scene);
  s += CheckLines(a, check, checks_file);
  if (!every_zone) return s;
  s += fmt::format("  {:<32} {:>8} {:>10} {:>10} {:>10} {:>10} {:>10}\n", "zone", "height_m", "k_s",
                   "R_k (a)", "R_k (b)", "R_ftrunc a", "R_ftrunc b");
  auto optional = [](const std::optional<double>& v) {
    return v ? fmt::format("{:.4g}", *v) : std::string("stop");
  };
  for (const ZoneAdvice& z : a.zones) {
    s += fmt::format("  {:<32} {:>8.4g} {:>10.4g} {:>10.4g} {:>10} {:>10.4g} {:>10}\n", z.name,
                     z.height_m, z.stiffness_n_per_m, z.r_k_a, optional(z.r_k_b), z.r_ftrunc_a,
                     optional(z.r_ftrunc_b));
  }
  return s;
}

}  // namespace shockmap

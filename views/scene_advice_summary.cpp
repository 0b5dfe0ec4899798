#include "views/scene_advice_summary.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

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

#include "views/scene_advice_summary.h"

#include <fmt/format.h>

namespace shockmap {

std::string SceneAdviceSummary(const Scene& scene, const SceneAdvice& a, bool every_zone) {
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
  for (const std::string& warning : a.warnings) s += "  warning      " + warning + "\n";
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

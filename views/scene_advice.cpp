#include "views/scene_advice.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/input_error.h"
#include "core/scene_model.h"

namespace shockmap {
namespace {

double SceneTruncation(const Scene& scene, const SceneBeam& beam) {
  return beam.r_ftrunc.value_or(scene.solver.r_ftrunc);
}

// The scene with each beam at its advised truncation, for its time-step bound.
Scene AtAdvisedTruncations(Scene scene, const std::vector<BeamAdvice>& beams) {
  for (const BeamAdvice& b : beams) {
    for (SceneBeam& beam : scene.beams) {
      if (beam.name == b.name) beam.r_ftrunc = b.r_ftrunc, beam.f_trunc_hz.reset();
    }
  }
  scene.outputs = SceneOutputs{};
  return scene;
}

}  // namespace

SceneAdvice AdviseScene(const Scene& scene, const ValidityCriteria& criteria) {
  if (!criteria.fit || !criteria.dt_ratio_max) {
    throw InputError(
        "--criteria: the criteria have no fitted truncation boundary or time-step "
        "bound to advise from; derive them from a study over a wider range of R_k");
  }
  SceneAdvice a;
  std::vector<BeamAdvice> beams(scene.beams.size());
  double r_k_min = 0.0, r_k_max = 0.0;
  for (const SceneZone& z : scene.zones) {
    ZoneAdvice zone{z.name, z.height_m, z.stiffness_n_per_m};
    for (const int b : {z.beam_a, z.beam_b}) {
      if (b < 0) continue;
      const double k_local = LocalBendingStiffness(scene.beams[b], z.height_m);
      const double r_k = z.stiffness_n_per_m / k_local;
      const double r_ftrunc = *criteria.RequiredRFtrunc(r_k);
      if (b == z.beam_a) {
        zone.k_local_a = k_local, zone.r_k_a = r_k, zone.r_ftrunc_a = r_ftrunc;
      } else {
        zone.k_local_b = k_local, zone.r_k_b = r_k, zone.r_ftrunc_b = r_ftrunc;
      }
      r_k_min = a.zones.empty() && b == z.beam_a ? r_k : std::min(r_k_min, r_k);
      r_k_max = std::max(r_k_max, r_k);
      BeamAdvice& beam = beams[b];
      ++beam.zones;
      if (r_k > beam.r_k_max) beam.r_k_max = r_k, beam.stiffest_zone = z.name;
      beam.r_ftrunc = std::max(beam.r_ftrunc, r_ftrunc);
    }
    a.zones.push_back(std::move(zone));
  }
  for (std::size_t b = 0; b < beams.size(); ++b) {
    if (beams[b].zones == 0) continue;
    beams[b].name = scene.beams[b].name;
    beams[b].r_ftrunc_scene = SceneTruncation(scene, scene.beams[b]);
    a.beams.push_back(beams[b]);
  }
  a.dt_ratio = *criteria.dt_ratio_max;
  a.dt_sharp_s = BuildSceneModel(AtAdvisedTruncations(scene, a.beams)).bounds.dt_sharp_s;
  a.dt_s = a.dt_ratio * a.dt_sharp_s;
  Scene as_given = scene;
  as_given.outputs = SceneOutputs{};
  a.scene_dt_s = scene.solver.dt.Resolve(BuildSceneModel(as_given).bounds);
  const auto [lo, hi] =
      std::ranges::minmax_element(criteria.boundary, {}, [](const RkBoundary& b) { return b.r_k; });
  if (lo != criteria.boundary.end() && !a.zones.empty() &&
      (r_k_max > hi->r_k || r_k_min < lo->r_k)) {
    a.warning = fmt::format(
        "the zones' R_k span [{:.3g}, {:.3g}], beyond the criteria's studied range [{:g}, {:g}]: "
        "the truncation criterion is extrapolated there",
        r_k_min, r_k_max, lo->r_k, hi->r_k);
  }
  return a;
}

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
  if (a.warning) s += "  warning      " + *a.warning + "\n";
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

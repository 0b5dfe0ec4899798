#include "validation/scene_advice.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <tuple>

#include "core/input_error.h"
#include "core/scene_model.h"
#include "core/structure_modes.h"

namespace shockmap {
namespace {

// A beam's or a structure's.
template <typename Part>
double SceneTruncation(const Scene& scene, const Part& part) {
  return part.r_ftrunc.value_or(scene.solver.r_ftrunc);
}

// The scene with each beam and structure at its advised truncation, for its time-step bound.
Scene AtAdvisedTruncations(Scene scene, const std::vector<BeamAdvice>& beams) {
  for (const BeamAdvice& b : beams) {
    for (SceneBeam& beam : scene.beams) {
      if (beam.name == b.name) beam.r_ftrunc = b.r_ftrunc, beam.f_trunc_hz.reset();
    }
    for (SceneStructure& structure : scene.structures) {
      if (structure.name == b.name) structure.r_ftrunc = b.r_ftrunc, structure.f_trunc_hz.reset();
    }
  }
  scene.outputs = SceneOutputs{};
  return scene;
}

// Studied R_k where no truncation passes carry no boundary, so the fit's envelope does not
// cover them: those from the studied R_k at or below r_k_min to the one at or above r_k_max
// are named, since the advice there is not a measured boundary.
std::optional<std::string> UnpassedWarning(const ValidityCriteria& criteria, double r_k_min,
                                           double r_k_max) {
  std::vector<double> unpassed;
  const auto& all = criteria.boundary;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const bool next_below = i + 1 < all.size() && all[i + 1].r_k <= r_k_min;
    const bool previous_above = i > 0 && all[i - 1].r_k >= r_k_max;
    if (!all[i].r_ftrunc_min && !next_below && !previous_above) unpassed.push_back(all[i].r_k);
  }
  if (unpassed.empty()) return std::nullopt;
  return fmt::format(
      "no studied truncation passes at R_k = {:.3g}, among the studied R_k around the zones' "
      "[{:.3g}, {:.3g}]: the fit's envelope does not cover it, so the truncation advised near it "
      "is not a measured boundary; study larger truncations there",
      fmt::join(unpassed, ", "), r_k_min, r_k_max);
}

// The criteria with only the unscored R_k among the studied R_k around the zones' [r_k_min,
// r_k_max] (from the studied one at or below r_k_min to the one at or above r_k_max): elsewhere
// an unmeasured boundary does not bear on the advice.
ValidityCriteria UnscoredAroundZones(ValidityCriteria criteria, double r_k_min, double r_k_max) {
  double lower = r_k_min;
  std::optional<double> upper;
  for (const RkBoundary& b : criteria.boundary) {
    if (b.r_k <= r_k_min) lower = b.r_k;
    if (!upper && b.r_k >= r_k_max) upper = b.r_k;
  }
  std::erase_if(criteria.unscored, [&](const PointsSetAside& u) {
    return u.r_k < lower || (upper && u.r_k > *upper);
  });
  return criteria;
}

// The local stiffness of one side of a zone (N/m): a beam's bending stiffness at the zone's
// height, across its axis (along a zone's 3D normal n, K / (n_y^2 + n_z^2): the beam does not
// move along its axis); a structure's node's along n: 1 / (n^T K^-1 n) (the paper's K_bend).
double SideStiffness(const Scene& scene, const SceneZone& z, bool side_b) {
  const int structure = side_b ? z.structure_b : z.structure_a;
  if (structure >= 0) {
    const auto& n = *z.normal_xyz;
    return LocalStiffness(*scene.structures[static_cast<std::size_t>(structure)].fe,
                          side_b ? z.node_b : z.node_a, Eigen::Vector3d(n[0], n[1], n[2]));
  }
  const int beam = side_b ? z.beam_b : z.beam_a;
  const double k_bend =
      LocalBendingStiffness(scene.beams[static_cast<std::size_t>(beam)], z.height_m);
  if (!z.AtNode()) return k_bend;
  const auto& n = *z.normal_xyz;
  return k_bend / std::max(n[1] * n[1] + n[2] * n[2], 1e-300);
}

// The name and truncation of part `i`: the beams, then the structures.
std::pair<std::string, double> PartOf(const Scene& scene, std::size_t i) {
  if (i < scene.beams.size()) {
    return {scene.beams[i].name, SceneTruncation(scene, scene.beams[i])};
  }
  const SceneStructure& s = scene.structures[i - scene.beams.size()];
  return {s.name, SceneTruncation(scene, s)};
}

}  // namespace

SceneAdvice AdviseScene(const Scene& scene, const ValidityCriteria& criteria) {
  if (!criteria.fit || !criteria.dt_ratio_max) {
    throw InputError(
        "--criteria: the criteria have no fitted truncation boundary or time-step "
        "bound to advise from; derive them from a study over a wider range of R_k");
  }
  SceneAdvice a;
  // The beams', then the structures'.
  std::vector<BeamAdvice> beams(scene.beams.size() + scene.structures.size());
  auto part = [&](const SceneZone& z, bool side_b) {
    const int structure = side_b ? z.structure_b : z.structure_a;
    const int beam = side_b ? z.beam_b : z.beam_a;
    return structure >= 0 ? static_cast<int>(scene.beams.size()) + structure : beam;
  };
  double r_k_min = 0.0, r_k_max = 0.0;
  for (const SceneZone& z : scene.zones) {
    ZoneAdvice zone;
    zone.name = z.name;
    zone.height_m = z.height_m;
    zone.stiffness_n_per_m = z.stiffness_n_per_m;
    for (const bool side_b : {false, true}) {
      const int b = part(z, side_b);
      if (b < 0) continue;
      const double k_local = SideStiffness(scene, z, side_b);
      const double r_k = z.stiffness_n_per_m / k_local;
      const double r_ftrunc = *criteria.RequiredRFtrunc(r_k);
      if (!side_b) {
        zone.k_local_a = k_local, zone.r_k_a = r_k, zone.r_ftrunc_a = r_ftrunc;
      } else {
        zone.k_local_b = k_local, zone.r_k_b = r_k, zone.r_ftrunc_b = r_ftrunc;
      }
      r_k_min = a.zones.empty() && !side_b ? r_k : std::min(r_k_min, r_k);
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
    std::tie(beams[b].name, beams[b].r_ftrunc_scene) = PartOf(scene, b);
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
    a.warnings.push_back(fmt::format(
        "the zones' R_k span [{:.3g}, {:.3g}], beyond the criteria's studied range [{:g}, {:g}]: "
        "the truncation criterion is extrapolated there",
        r_k_min, r_k_max, lo->r_k, hi->r_k));
  }
  if (const auto unscored = UnscoredWarning(UnscoredAroundZones(criteria, r_k_min, r_k_max)))
    a.warnings.push_back(*unscored);
  if (const auto holes = UnpassedWarning(criteria, r_k_min, r_k_max)) a.warnings.push_back(*holes);
  return a;
}

}  // namespace shockmap

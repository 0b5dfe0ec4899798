#include "core/reached_bound.h"

#include <algorithm>
#include <cmath>

#include "core/scene_model.h"

namespace shockmap {

ReachedBound CheckReachedBound(const SceneModalSystem& system) {
  ReachedBound b;
  const ContactStations& contacts = system.Contacts();
  const std::vector<double> reached = contacts.LargestPenetrations();
  std::vector<double> stiffness = contacts.BoundStiffnesses();
  bool any_power_law = false;
  double deepest = 0.0;  // The largest ratio of a zone's penetration to its bound's.
  for (std::size_t z = 0; z < reached.size(); ++z) {
    const NormalLaw& law = system.Zones()[z].law.normal;
    if (!law.HasBoundPenetration()) continue;
    any_power_law = true;
    const double depth = std::max(reached[z], law.bound_penetration_m);
    stiffness[z] = law.TangentStiffness(depth);
    // Of exponent 1 the tangent stiffness is constant: no depth takes the bound past its own.
    if (!law.IsLinear() && reached[z] > law.bound_penetration_m) b.exceeded = true;
    if (reached[z] / law.bound_penetration_m > deepest) {
      deepest = reached[z] / law.bound_penetration_m;
      b.deepest_zone = static_cast<int>(z);
      b.largest_penetration_m = reached[z];
      b.bound_penetration_m = law.bound_penetration_m;
    }
  }
  if (!any_power_law) return b;
  b.dt_sharp_reached_s = 2.0 / std::sqrt(SharpOmegaSquared(system, stiffness));
  return b;
}

}  // namespace shockmap

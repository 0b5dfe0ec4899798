#pragma once
// A beam's make-up along its length (docs/scenes.md, "Non-uniform beams"): consecutive
// sections from the base up, each with its own EI and rho A, and point masses at heights, as a
// fuel pin's end plugs, fuel column, plenum and its spring's seat.

#include <compare>
#include <vector>

namespace shockmap {

struct BeamSection {
  double length_m = 0.0;
  double ei_n_m2 = 0.0;
  double rho_a_kg_per_m = 0.0;

  auto operator<=>(const BeamSection&) const = default;
};

// A rigid mass at one height: `mass_kg` on the deflection, `rotary_inertia_kg_m2` (about the
// bending axis) on the rotation.
struct BeamPointMass {
  double height_m = 0.0;
  double mass_kg = 0.0;
  double rotary_inertia_kg_m2 = 0.0;

  auto operator<=>(const BeamPointMass&) const = default;
};

// A beam from its base (height 0) to length_m: its sections in order from the base, their
// lengths summing to length_m (to round-off: the last one ends at length_m), and its point
// masses at heights in [0, length_m].
struct SectionedBeam {
  double length_m = 0.0;
  std::vector<BeamSection> sections;
  std::vector<BeamPointMass> point_masses;
};

}  // namespace shockmap

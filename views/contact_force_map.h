#pragma once
// The map of the maximum contact force in every zone of a scene over a run (paper Fig. 5b):
// zones drawn where they sit, by height and lateral position, coloured by their largest force;
// scenes bending in both planes get a second panel, the cross-section seen from above, each
// location coloured by its largest force over the heights.

#include <filesystem>
#include <string>
#include <vector>

#include "core/scene.h"

namespace shockmap {

// Draws the map into `file` (.png or .svg), with its data and gnuplot script beside it;
// `quantity` names what the forces are (in the title and on the colour bar).
// Preconditions: one force per zone of the scene. Throws InputError when the scene has no
// zones or the file cannot be written.
void DrawContactForceMap(const Scene& scene, const std::vector<double>& max_force_n,
                         const std::filesystem::path& file,
                         const std::string& quantity = "maximum contact force");

}  // namespace shockmap

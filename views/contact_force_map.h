#pragma once
// The map of the maximum contact force in every zone of a scene over a run (paper Fig. 5b):
// zones between beams drawn where they sit and coloured by their largest force. A planar scene
// gets one panel by height and lateral position; a scene bending in both planes one
// cross-section per zone height (a bundle's wire heights). Zones against a stop, whose forces
// are often far larger, get their own panel and axis (force against height, each labelled).
// The legend names only the kinds of zone present.

#include <filesystem>
#include <string>
#include <vector>

#include "core/scene.h"

namespace shockmap {

// Draws the map into `file` (.png or .svg), with its data (FILE.zones.dat, and FILE.beams.dat
// for both planes) and gnuplot script beside it; the script runs from its own folder.
// `quantity` names what the forces are (in the title and on the colour bar).
// Preconditions: one force per zone of the scene. Throws InputError when the scene has no
// zones or the file cannot be written.
void DrawContactForceMap(const Scene& scene, const std::vector<double>& max_force_n,
                         const std::filesystem::path& file,
                         const std::string& quantity = "maximum contact force");

}  // namespace shockmap

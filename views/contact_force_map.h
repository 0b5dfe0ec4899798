#pragma once
// The map of the maximum contact force in every zone of a scene over a run (paper Fig. 5b):
// zones between beams drawn where they sit and coloured by their largest force. A planar scene
// gets one panel by height and lateral position; a scene bending in both planes one
// cross-section per zone height (a bundle's wire heights). Zones against a stop, whose forces
// are often far larger, get their own panel and axis (force against height, each labelled).
// The legend names only the kinds of zone present. Any other value per zone (a wear volume) is
// drawn the same way, with its name and unit.

#include <filesystem>
#include <string>
#include <vector>

#include "core/scene.h"

namespace shockmap {

// What a map's values are: their name (in the title, on the colour bar and on the stops' axis)
// and unit.
struct MapQuantity {
  std::string name = "maximum contact force";
  std::string unit = "N";
};

// Draws the map into `file` (.png or .svg), with its data (FILE.zones.dat, and FILE.beams.dat
// for both planes) and gnuplot script beside it; the script runs from its own folder.
// Preconditions: one value per zone of the scene, >= 0. Throws InputError when the scene has
// no zones or the file cannot be written.
void DrawContactForceMap(const Scene& scene, const std::vector<double>& max_force_n,
                         const std::filesystem::path& file, const MapQuantity& quantity = {});

}  // namespace shockmap

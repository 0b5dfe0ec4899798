#pragma once
// The pictures of `shockmap sizing` (docs/ensembles.md, "Pictures"), drawn with gnuplot: per
// clearance state at its refined setting, the paper's Fig. 5b map coloured by the sizing value
// (and, where the members have wear volumes, the same map of the wear volume's); per state and
// zone family (the hottest wire, pad, pin-wrapper contact: specs/zone_family.h), the
// convergence of its hottest zone's estimate with the number of members (its interval as a band)
// and the histogram of that zone's maximum; per family, across states, the sizing force and wear
// work rate, and across settings, the sizing force against the setting.

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/ensemble_sizing.h"
#include "core/scene.h"

namespace shockmap {

// A picture drawn: the PNG (its data and script beside it) and what it shows.
struct SizingPicture {
  std::filesystem::path image;
  std::string caption;
};

// Writes the pictures into `folder` and returns them in drawing order. `scene` is the study's
// scene (its zones in the stored order). Throws InputError when a file cannot be written,
// PlotError when gnuplot fails.
std::vector<SizingPicture> DrawSizingPictures(const EnsembleSizing& sizing,
                                              const StoredEnsemble& stored, const Scene& scene,
                                              const std::filesystem::path& folder);

}  // namespace shockmap

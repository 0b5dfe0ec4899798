#pragma once
// Eigensolutions of FE beams kept for the process (docs/performance.md, "References and study
// points"): the points of a study share few meshes, and the clamped-free basis does not depend
// on the contact stiffness, so the eigenproblem (paper eq. 6) is solved once per mesh instead
// of once per point, by the first thread that asks while the others wait for it. A cached
// solution is the one a fresh solve returns, bit for bit.

#include <memory>
#include <string>

#include "core/beam_fe.h"
#include "core/modal_basis.h"

namespace shockmap {

// The most recently used solutions kept, by their shapes' size.
inline constexpr double kModalBasisCacheBytes = 64e6;

// Every mode of `model` (ComputeLowestModes(model, model.Size())), from the cache when
// `model_key` is in it (thread-safe; what the solve throws, every thread waiting for it throws).
// The key must name everything the model depends on: beam properties (every section's, every
// point mass's), elements, end conditions and end springs.
std::shared_ptr<const ModalBasis> AllModesCached(const std::string& model_key,
                                                 const FeBeamModel& model);

}  // namespace shockmap

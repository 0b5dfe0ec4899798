#include "core/modal_basis_cache.h"

#include "core/solution_cache.h"

namespace shockmap {

std::shared_ptr<const ModalBasis> AllModesCached(const std::string& model_key,
                                                 const FeBeamModel& model) {
  static SolutionCache<std::string, ModalBasis> cache(kModalBasisCacheBytes);
  return cache.Get(
      model_key, [&] { return ComputeLowestModes(model, model.Size()); },
      [](const ModalBasis& basis) { return basis.shapes.size() * sizeof(double); });
}

}  // namespace shockmap

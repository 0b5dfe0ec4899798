#include "core/modal_basis_cache.h"

#include <algorithm>
#include <list>

namespace shockmap {
namespace {

struct CachedModes {
  std::string key;
  std::shared_ptr<const ModalBasis> modes;
  double bytes = 0.0;
};

// Most recently used first.
class ModesCache {
 public:
  std::shared_ptr<const ModalBasis> Find(const std::string& key) {
    const auto it = std::find_if(entries_.begin(), entries_.end(),
                                 [&](const CachedModes& e) { return e.key == key; });
    if (it == entries_.end()) return nullptr;
    entries_.splice(entries_.begin(), entries_, it);
    return entries_.front().modes;
  }

  void Keep(const std::string& key, std::shared_ptr<const ModalBasis> modes) {
    const double bytes = static_cast<double>(modes->shapes.size()) * sizeof(double);
    if (bytes > kModalBasisCacheBytes) return;
    entries_.push_front({key, std::move(modes), bytes});
    bytes_ += bytes;
    while (bytes_ > kModalBasisCacheBytes) {
      bytes_ -= entries_.back().bytes;
      entries_.pop_back();
    }
  }

 private:
  std::list<CachedModes> entries_;
  double bytes_ = 0.0;
};

}  // namespace

std::shared_ptr<const ModalBasis> AllModesCached(const std::string& model_key,
                                                 const FeBeamModel& model) {
  thread_local ModesCache cache;
  if (auto found = cache.Find(model_key)) return found;
  auto modes = std::make_shared<const ModalBasis>(ComputeLowestModes(model, model.Size()));
  cache.Keep(model_key, modes);
  return modes;
}

}  // namespace shockmap

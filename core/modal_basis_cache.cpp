#include "core/modal_basis_cache.h"

#include <algorithm>
#include <future>
#include <list>
#include <mutex>

namespace shockmap {
namespace {

using SharedModes = std::shared_future<std::shared_ptr<const ModalBasis>>;

struct CachedModes {
  std::string key;
  SharedModes modes;
  double bytes = 0.0;
};

// Most recently used first. Not thread-safe: AllModesCached holds its lock around each call.
class ModesCache {
 public:
  const SharedModes* Find(const std::string& key) {
    const auto it = Entry(key);
    if (it == entries_.end()) return nullptr;
    entries_.splice(entries_.begin(), entries_, it);
    return &entries_.front().modes;
  }

  void Keep(const std::string& key, SharedModes modes, double bytes) {
    if (bytes > kModalBasisCacheBytes) return;
    entries_.push_front({key, std::move(modes), bytes});
    bytes_ += bytes;
    while (bytes_ > kModalBasisCacheBytes) {
      bytes_ -= entries_.back().bytes;
      entries_.pop_back();
    }
  }

  void Forget(const std::string& key) {
    const auto it = Entry(key);
    if (it == entries_.end()) return;
    bytes_ -= it->bytes;
    entries_.erase(it);
  }

 private:
  std::list<CachedModes>::iterator Entry(const std::string& key) {
    return std::find_if(entries_.begin(), entries_.end(),
                        [&](const CachedModes& e) { return e.key == key; });
  }

  std::list<CachedModes> entries_;
  double bytes_ = 0.0;
};

}  // namespace

std::shared_ptr<const ModalBasis> AllModesCached(const std::string& model_key,
                                                 const FeBeamModel& model) {
  static std::mutex mutex;
  static ModesCache cache;
  std::promise<std::shared_ptr<const ModalBasis>> solution;
  SharedModes modes;
  bool solve = false;
  {
    std::lock_guard lock(mutex);
    if (const SharedModes* found = cache.Find(model_key)) {
      modes = *found;
    } else {
      modes = solution.get_future().share();
      const double size = model.Size();
      cache.Keep(model_key, modes, size * size * sizeof(double));
      solve = true;
    }
  }
  if (!solve) return modes.get();  // Waits while the thread that asked first solves it.
  try {
    solution.set_value(std::make_shared<const ModalBasis>(ComputeLowestModes(model, model.Size())));
  } catch (...) {
    solution.set_exception(std::current_exception());
    std::lock_guard lock(mutex);
    cache.Forget(model_key);
  }
  return modes.get();
}

}  // namespace shockmap

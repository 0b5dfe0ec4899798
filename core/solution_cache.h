#pragma once
// A process's cache of costly solutions (eigensolutions of beams and of FE structures,
// docs/performance.md "Study points"): each one solved once per key, by the first thread that
// asks while the others asking for the same key wait for it, the most recently used kept within
// a byte budget. A solution found is the object the solve returned.

#include <algorithm>
#include <cstdint>
#include <exception>
#include <future>
#include <list>
#include <memory>
#include <mutex>
#include <utility>

namespace shockmap {

// `Key` is equality-comparable and copyable; keys are compared one by one (a cache holds few).
template <class Key, class Value>
class SolutionCache {
 public:
  explicit SolutionCache(double budget_bytes) : budget_bytes_(budget_bytes) {}

  // The solution kept under `key`, else solve()'s (a Value), kept when bytes(solution) fits the
  // budget, evicting the least recently used. Thread-safe; what solve() throws, every thread
  // waiting for that key throws, and nothing is kept.
  template <class Solve, class Bytes>
  std::shared_ptr<const Value> Get(const Key& key, Solve&& solve, Bytes&& bytes) {
    std::promise<std::shared_ptr<const Value>> solution;
    Shared shared;
    std::uint64_t serial = 0;
    {
      std::lock_guard lock(mutex_);
      if (const Shared* found = Find(key)) {
        shared = *found;
      } else {
        shared = solution.get_future().share();
        serial = ++serials_;
        entries_.push_front({key, shared, serial, 0.0});
      }
    }
    if (serial == 0) return shared.get();  // Waits while the thread that asked first solves it.
    try {
      auto solved = std::make_shared<const Value>(solve());
      const double size = bytes(*solved);
      solution.set_value(std::move(solved));
      std::lock_guard lock(mutex_);
      Account(serial, size);
    } catch (...) {
      solution.set_exception(std::current_exception());
      std::lock_guard lock(mutex_);
      Forget(serial);
    }
    return shared.get();
  }

 private:
  using Shared = std::shared_future<std::shared_ptr<const Value>>;
  struct Entry {
    Key key;
    Shared solution;
    std::uint64_t serial = 0;  // Names the entry of one solve, whatever was evicted meanwhile.
    double bytes = 0.0;        // 0 while being solved.
  };
  using Iterator = typename std::list<Entry>::iterator;

  Iterator EntryOf(std::uint64_t serial) {
    return std::find_if(entries_.begin(), entries_.end(),
                        [&](const Entry& e) { return e.serial == serial; });
  }

  const Shared* Find(const Key& key) {
    const Iterator it = std::find_if(entries_.begin(), entries_.end(),
                                     [&](const Entry& e) { return e.key == key; });
    if (it == entries_.end()) return nullptr;
    entries_.splice(entries_.begin(), entries_, it);
    return &entries_.front().solution;
  }

  // Sets the solved entry's size (it may have been evicted meanwhile), then evicts the least
  // recently used beyond the budget; a solution larger than the budget is not kept.
  void Account(std::uint64_t serial, double size) {
    const Iterator it = EntryOf(serial);
    if (it == entries_.end()) return;
    if (size > budget_bytes_) {
      entries_.erase(it);
      return;
    }
    it->bytes = size;
    bytes_ += size;
    while (bytes_ > budget_bytes_) {
      bytes_ -= entries_.back().bytes;
      entries_.pop_back();
    }
  }

  void Forget(std::uint64_t serial) {
    const Iterator it = EntryOf(serial);
    if (it == entries_.end()) return;
    bytes_ -= it->bytes;
    entries_.erase(it);
  }

  const double budget_bytes_;
  std::mutex mutex_;
  std::list<Entry> entries_;  // Most recently used first.
  double bytes_ = 0.0;
  std::uint64_t serials_ = 0;
};

}  // namespace shockmap

#pragma once
// The order in which a run hands out its tasks. A task may wait for another one (after[i]):
// it becomes ready once that task's result has been consumed. Ready tasks go out in the order
// they became ready: first those that wait for nothing, in index order, then each waiting one
// as its task is consumed, in index order among those released together. So the points of a
// reference start as soon as it is stored, while the references, listed first, go out before
// any point. Not thread-safe: its owner guards it.

#include <cstddef>
#include <deque>
#include <limits>
#include <vector>

namespace shockmap {

class TaskQueue {
 public:
  static constexpr std::size_t kNoWait = std::numeric_limits<std::size_t>::max();

  // after[i]: the task i waits for (another index below after.size()), or kNoWait.
  explicit TaskQueue(const std::vector<std::size_t>& after) : released_(after.size()) {
    for (std::size_t i = 0; i < after.size(); ++i) {
      if (after[i] == kNoWait) {
        ready_.push_back(i);
      } else {
        released_[after[i]].push_back(i);
      }
    }
  }

  bool HasReady() const { return !ready_.empty(); }
  // Precondition: HasReady().
  std::size_t Take() {
    const std::size_t i = ready_.front();
    ready_.pop_front();
    return i;
  }
  // Task i's result was consumed: the tasks waiting for it are ready.
  void Consumed(std::size_t i) {
    for (std::size_t waiting : released_[i]) ready_.push_back(waiting);
    released_[i].clear();
  }

 private:
  std::deque<std::size_t> ready_;
  std::vector<std::vector<std::size_t>> released_;  // By task: the tasks waiting for it.
};

}  // namespace shockmap

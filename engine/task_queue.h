#pragma once
// The order in which a run hands out its tasks. A task may wait for another one (after[i]):
// it becomes ready once that task's result has been consumed. Ready tasks go out in the order
// they became ready: first those that wait for nothing, in index order, then each waiting one
// as its task is consumed, in index order among those released together. So the points of a
// reference start as soon as it is stored, while the references, listed first, go out before
// any point. A task may also need a result a taker can already hold (group[i]: a worker rank
// keeps the references it computed or was sent); a taker holding some asks for a task needing
// one of them first (Take(held)). Not thread-safe: its owner guards it.

#include <cstddef>
#include <deque>
#include <limits>
#include <list>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

namespace shockmap {

// Which groups of a TaskQueue each taker holds, and which some taker holds: the arguments of
// TaskQueue::Take(held, held_anywhere).
class GroupHolders {
 public:
  explicit GroupHolders(std::size_t takers) : by_taker_(takers) {}
  // Returns whether `taker` did not hold `group` before.
  bool Hold(std::size_t taker, std::size_t group) {
    held_anywhere_.insert(group);
    return by_taker_[taker].insert(group).second;
  }
  const std::set<std::size_t>& HeldBy(std::size_t taker) const { return by_taker_[taker]; }
  const std::set<std::size_t>& HeldAnywhere() const { return held_anywhere_; }

 private:
  std::vector<std::set<std::size_t>> by_taker_;
  std::set<std::size_t> held_anywhere_;
};

class TaskQueue {
 public:
  static constexpr std::size_t kNoWait = std::numeric_limits<std::size_t>::max();

  // after[i]: the task i waits for (another index below after.size()), or kNoWait. group[i]:
  // what task i needs that a taker may hold (kNoWait: nothing), the index of the task it waits
  // for when it waits for one, else any other number; empty: `after`.
  explicit TaskQueue(const std::vector<std::size_t>& after,
                     const std::vector<std::size_t>& group = {})
      : group_(group.empty() ? after : group),
        released_(after.size()),
        taken_(after.size(), false) {
    for (std::size_t i = 0; i < after.size(); ++i) {
      if (after[i] == kNoWait) {
        MakeReady(i);
      } else {
        released_[after[i]].push_back(i);
      }
    }
  }

  bool HasReady() const { return ready_count_ > 0; }
  // The next ready task in the queue's order. Precondition: HasReady().
  std::size_t Take() { return Mark(Front()); }
  // For a taker holding the groups in `held`, among those some taker holds (`held_anywhere`):
  // the next ready task if it needs nothing or one of them, else the first ready task needing
  // one of them (the lowest held group first), else the first ready task of the first group no
  // taker holds (in the order the groups became ready), else the next ready task. So the tasks
  // that need nothing (the references) keep their order, a point goes where its reference
  // already is when it can, and a taker holding none takes up a group nobody holds rather than
  // one that others hold. Precondition: HasReady().
  std::size_t Take(const std::set<std::size_t>& held,
                   const std::set<std::size_t>& held_anywhere = {}) {
    const std::size_t front = Front();
    if (group_[front] == kNoWait || held.contains(group_[front])) return Mark(front);
    for (const std::size_t group : held) {
      if (const auto task = FirstReadyIn(group)) return Mark(*task);
    }
    for (auto group = groups_in_order_.begin(); group != groups_in_order_.end();) {
      const auto task = FirstReadyIn(*group);
      if (!task) {  // Taken: forgotten until a task of it is ready again.
        ready_in_group_.erase(*group);
        group = groups_in_order_.erase(group);
      } else if (held_anywhere.contains(*group)) {
        ++group;
      } else {
        return Mark(*task);
      }
    }
    return Mark(front);
  }
  // Whether some task waits for task i.
  bool IsWaitedFor(std::size_t i) const { return !released_[i].empty(); }
  // Task i's result was consumed: the tasks waiting for it are ready.
  void Consumed(std::size_t i) {
    for (const std::size_t waiting : released_[i]) MakeReady(waiting);
  }

 private:
  void MakeReady(std::size_t i) {
    ready_.push_back(i);
    if (group_[i] != kNoWait) {
      const auto [bucket, first] = ready_in_group_.try_emplace(group_[i]);
      if (first) groups_in_order_.push_back(group_[i]);
      bucket->second.push_back(i);
    }
    ++ready_count_;
  }
  // The first ready task of a group not yet taken, if any.
  std::optional<std::size_t> FirstReadyIn(std::size_t group) {
    const auto bucket = ready_in_group_.find(group);
    if (bucket == ready_in_group_.end()) return std::nullopt;
    std::deque<std::size_t>& tasks = bucket->second;
    while (!tasks.empty() && taken_[tasks.front()]) tasks.pop_front();
    if (tasks.empty()) return std::nullopt;
    return tasks.front();
  }
  // The first ready task not yet taken (tasks taken out of order stay in ready_ until here).
  std::size_t Front() {
    while (taken_[ready_.front()]) ready_.pop_front();
    return ready_.front();
  }
  std::size_t Mark(std::size_t i) {
    taken_[i] = true;
    --ready_count_;
    return i;
  }

  std::vector<std::size_t> group_;
  std::vector<std::vector<std::size_t>> released_;  // By task: the tasks waiting for it.
  // Ready tasks in order, all and by group; they may hold tasks already taken.
  std::deque<std::size_t> ready_;
  std::unordered_map<std::size_t, std::deque<std::size_t>> ready_in_group_;
  std::list<std::size_t> groups_in_order_;  // Those with ready tasks, as they became ready.
  std::size_t ready_count_ = 0;             // Ready and not taken.
  std::vector<bool> taken_;
};

}  // namespace shockmap

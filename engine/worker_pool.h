#pragma once
// Workers compute, the calling thread consumes: RunOnWorkers(after, jobs, compute, consume,
// poll) runs compute(i) for every task i of `after` on `jobs` threads, each once the task it
// waits for is consumed, and hands every result to consume() on the calling thread, in
// completion order. Only the calling thread ever sees consume() and poll(), so it can own the
// one database connection; the same split maps onto MPI ranks (workers) and rank 0.

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "engine/task_queue.h"

namespace shockmap {

// How often the calling thread polls while it waits for results.
inline constexpr std::chrono::milliseconds kPollPeriod{200};

// compute must not throw (turn failures into results). Task i starts once the task after[i]
// waits for (TaskQueue) has been consumed, in the queue's order. poll() runs on the calling
// thread after every result and at least every kPollPeriod while it waits; when it returns true
// no new task starts, and the tasks already started are finished and consumed. Returns how many
// results were consumed (after.size() unless poll stopped it). `after` must have no cycle.
template <typename Compute, typename Consume, typename Poll>
std::size_t RunOnWorkers(const std::vector<std::size_t>& after, int jobs, Compute compute,
                         Consume consume, Poll poll) {
  using Result = decltype(compute(std::size_t{}));
  const std::size_t count = after.size();
  std::mutex mutex;  // Guards everything below but the workers.
  std::condition_variable result_ready, task_ready;
  TaskQueue queue(after);
  std::size_t taken = 0;
  bool stopping = false;
  std::deque<std::pair<std::size_t, Result>> results;
  const auto n_workers = std::min(static_cast<std::size_t>(std::max(1, jobs)), count);
  std::size_t running = n_workers;
  auto work = [&] {
    for (;;) {
      std::size_t i = 0;
      {
        std::unique_lock lock(mutex);
        task_ready.wait(lock, [&] { return stopping || taken == count || queue.HasReady(); });
        if (stopping || taken == count) break;
        i = queue.Take();
        if (++taken == count) task_ready.notify_all();
      }
      Result r = compute(i);
      const std::lock_guard lock(mutex);
      results.emplace_back(i, std::move(r));
      result_ready.notify_one();
    }
    const std::lock_guard lock(mutex);
    --running;
    result_ready.notify_one();
  };
  auto stop = [&] {
    const std::lock_guard lock(mutex);
    stopping = true;
    task_ready.notify_all();
  };
  std::vector<std::jthread> workers;
  for (std::size_t w = 0; w < n_workers; ++w) workers.emplace_back(work);
  // Destroyed before the workers are joined: when consume() or poll() throws, no worker waits on.
  struct StopOnExit {
    decltype(stop)& stop_workers;
    ~StopOnExit() { stop_workers(); }
  } stop_on_exit{stop};
  std::size_t consumed = 0;
  for (;;) {
    std::unique_lock lock(mutex);
    result_ready.wait_for(lock, kPollPeriod, [&] { return !results.empty() || running == 0; });
    if (results.empty()) {
      if (running == 0) break;
      lock.unlock();
      if (poll()) stop();
      continue;
    }
    auto [i, r] = std::move(results.front());
    results.pop_front();
    lock.unlock();
    consume(std::move(r));
    ++consumed;
    lock.lock();
    queue.Consumed(i);
    task_ready.notify_all();
    lock.unlock();
    if (poll()) stop();
  }
  return consumed;
}

}  // namespace shockmap

#pragma once
// Workers compute, the calling thread consumes: RunOnWorkers(n, jobs, compute, consume, poll)
// runs compute(i) for i in [0, n) on `jobs` threads and hands every result to consume() on the
// calling thread, in completion order. Only the calling thread ever sees consume() and poll(),
// so it can own the one database connection; the same split maps onto MPI ranks (workers) and
// rank 0.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace shockmap {

// How often the calling thread polls while it waits for results.
inline constexpr std::chrono::milliseconds kPollPeriod{200};

// compute must not throw (turn failures into results). poll() runs on the calling thread after
// every result and at least every kPollPeriod while it waits; when it returns true no new task
// starts, and the tasks already started are finished and consumed. Returns how many results
// were consumed (n unless poll stopped it).
template <typename Compute, typename Consume, typename Poll>
std::size_t RunOnWorkers(std::size_t count, int jobs, Compute compute, Consume consume, Poll poll) {
  using Result = decltype(compute(std::size_t{}));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stopping{false};
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<Result> results;
  const auto n_workers = std::min(static_cast<std::size_t>(std::max(1, jobs)), count);
  std::size_t running = n_workers;  // Guarded by mutex.
  auto work = [&] {
    while (!stopping) {
      const std::size_t i = next++;
      if (i >= count) break;
      Result r = compute(i);
      const std::lock_guard lock(mutex);
      results.push_back(std::move(r));
      ready.notify_one();
    }
    const std::lock_guard lock(mutex);
    --running;
    ready.notify_one();
  };
  std::vector<std::jthread> workers;
  for (std::size_t w = 0; w < n_workers; ++w) workers.emplace_back(work);
  std::size_t consumed = 0;
  for (;;) {
    std::unique_lock lock(mutex);
    ready.wait_for(lock, kPollPeriod, [&] { return !results.empty() || running == 0; });
    if (results.empty()) {
      if (running == 0) break;
      lock.unlock();
      if (poll()) stopping = true;
      continue;
    }
    Result r = std::move(results.front());
    results.pop_front();
    lock.unlock();
    consume(std::move(r));
    ++consumed;
    if (poll()) stopping = true;
  }
  return consumed;
}

}  // namespace shockmap

#pragma once
// Workers compute, the calling thread consumes: RunOnWorkers(n, jobs, compute, consume) runs
// compute(i) for i in [0, n) on `jobs` threads and hands every result to consume() on the
// calling thread, in completion order. Only the calling thread ever sees consume(), so it can
// own the one database connection; the same split maps onto MPI ranks (workers) and rank 0.

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace shockmap {

// compute must not throw (turn failures into results).
template <typename Compute, typename Consume>
void RunOnWorkers(std::size_t count, int jobs, Compute compute, Consume consume) {
  using Result = decltype(compute(std::size_t{}));
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<Result> results;
  auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      Result r = compute(i);
      {
        const std::lock_guard lock(mutex);
        results.push_back(std::move(r));
      }
      ready.notify_one();
    }
  };
  std::vector<std::jthread> workers;
  const auto n_workers = static_cast<std::size_t>(std::max(1, jobs));
  for (std::size_t w = 0; w < std::min(n_workers, count); ++w) workers.emplace_back(work);
  for (std::size_t consumed = 0; consumed < count; ++consumed) {
    std::unique_lock lock(mutex);
    ready.wait(lock, [&] { return !results.empty(); });
    Result r = std::move(results.front());
    results.pop_front();
    lock.unlock();
    consume(std::move(r));
  }
}

}  // namespace shockmap

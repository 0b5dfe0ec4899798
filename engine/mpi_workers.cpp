// RemoteWorkers over MPI (built with SHOCKMAP_MPI). Only each process's calling thread makes MPI
// calls (MPI_THREAD_FUNNELED); a worker rank's compute threads hand their results to it. Every
// message is [task index: u64][bytes]; sends are non-blocking so that rank 0 handing a task to
// a rank and that rank returning a large reference never wait on each other. Waiting sleeps
// (from 20 us up to 0.25 ms) instead of spinning: on a shared node rank 0 leaves the cores to
// the workers.

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <list>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "engine/byte_codec.h"
#include "engine/remote_workers.h"

namespace shockmap {
namespace {

enum Tag : int { kTask = 1, kResult = 2, kQuit = 3, kBye = 4 };

struct Message {
  std::string bytes;
  int source = 0;
  int tag = 0;
};

// A message from `source` (or any) with `tag` (or any), if one is waiting.
std::optional<Message> Receive(int source, int tag) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status);
  if (flag == 0) return std::nullopt;
  int n = 0;
  MPI_Get_count(&status, MPI_BYTE, &n);
  Message m{std::string(static_cast<std::size_t>(n), '\0'), status.MPI_SOURCE, status.MPI_TAG};
  MPI_Recv(m.bytes.data(), n, MPI_BYTE, m.source, m.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return m;
}

// Non-blocking sends whose buffers live until MPI is done with them.
class Sends {
 public:
  void Post(int to, int tag, std::string bytes) {
    Pending& p = pending_.emplace_back(Pending{std::move(bytes), MPI_REQUEST_NULL});
    MPI_Isend(p.bytes.data(), static_cast<int>(p.bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD,
              &p.request);
  }
  void Progress() {
    pending_.remove_if([](Pending& p) {
      int done = 0;
      MPI_Test(&p.request, &done, MPI_STATUS_IGNORE);
      return done != 0;
    });
  }
  bool Empty() const { return pending_.empty(); }

 private:
  struct Pending {
    std::string bytes;
    MPI_Request request;
  };
  std::list<Pending> pending_;  // A list: requests keep their address.
};

// Waits longer the longer nothing happens, up to 0.25 ms: a task waits at most that long for
// rank 0 to notice its rank is free, at about 1 % of a core.
class Backoff {
 public:
  void Reset() { wait_ = kShortest; }
  std::chrono::microseconds Next() {
    const auto wait = wait_;
    wait_ = std::min(wait_ * 2, kLongest);
    return wait;
  }
  void Wait() { std::this_thread::sleep_for(Next()); }

 private:
  static constexpr std::chrono::microseconds kShortest{20}, kLongest{250};
  std::chrono::microseconds wait_ = kShortest;
};

std::string Framed(std::uint64_t index, std::string_view body) {
  ByteWriter out;
  out.Put(index);
  std::string bytes = out.Take();
  bytes.append(body);
  return bytes;
}

std::uint64_t IndexOf(const std::string& framed) {
  ByteReader in(framed);
  return in.Get<std::uint64_t>();
}

std::string HostName() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  return host;
}

class MpiWorkers final : public RemoteWorkers {
 public:
  MpiWorkers(int threads, int rank, int size) : threads_(threads), rank_(rank), size_(size) {
    char mine[256] = {};
    const std::string host = HostName();
    host.copy(mine, sizeof mine - 1);
    std::vector<char> all(256 * static_cast<std::size_t>(size));
    MPI_Allgather(mine, 256, MPI_CHAR, all.data(), 256, MPI_CHAR, MPI_COMM_WORLD);
    for (int r = 0; r < size; ++r) hosts_.emplace_back(all.data() + 256 * r);
  }
  ~MpiWorkers() override {
    if (rank_ == 0) EndJob();
    MPI_Finalize();
  }

  int Rank() const override { return rank_; }
  int WorkerRanks() const override { return size_ - 1; }
  int ThreadsPerRank() const override { return threads_; }
  PointOrigin OriginOf(int rank) const override {
    return {hosts_.at(static_cast<std::size_t>(rank)), rank};
  }
  MessageTotals Totals() const override { return totals_; }

  std::vector<AbandonedTask> Run(std::size_t count, const EncodeTask& encode,
                                 const ConsumeResult& consume,
                                 const std::function<bool()>& poll) override;
  void Serve(const Execute& execute) override;

 private:
  void EndJob();
  // What a worker rank's compute threads and its MPI thread share.
  struct WorkerQueues {
    std::mutex mutex;
    std::condition_variable ready, finished;  // A task to compute; a result (or error) to send.
    std::deque<std::string> tasks, results;
    bool quit = false;
    std::string error;
  };
  // A worker's MPI thread: takes tasks and sends results until rank 0 says quit.
  void Relay(WorkerQueues& q);

  int threads_, rank_, size_;
  std::vector<std::string> hosts_;
  Sends sends_;
  MessageTotals totals_;
};

std::vector<AbandonedTask> MpiWorkers::Run(std::size_t count, const EncodeTask& encode,
                                           const ConsumeResult& consume,
                                           const std::function<bool()>& poll) {
  std::deque<int> idle;  // One entry per idle thread, the ranks taking turns.
  for (int t = 0; t < threads_; ++t) {
    for (int r = 1; r < size_; ++r) idle.push_back(r);
  }
  std::map<std::size_t, int> out;  // Task index -> the rank computing it.
  std::size_t next = 0;
  bool stopped = false;
  Backoff backoff;
  for (;;) {
    for (; !stopped && next < count && !idle.empty(); ++next) {
      std::string task = Framed(next, encode(next, idle.front()));
      ++totals_.tasks;
      totals_.task_bytes += static_cast<double>(task.size());
      totals_.largest_task = std::max(totals_.largest_task, static_cast<double>(task.size()));
      sends_.Post(idle.front(), kTask, std::move(task));
      out[next] = idle.front();
      idle.pop_front();
    }
    sends_.Progress();
    if (out.empty() || stopped) break;
    if (auto m = Receive(MPI_ANY_SOURCE, kResult)) {
      const std::size_t index = IndexOf(m->bytes);
      if (out.erase(index) == 0) throw std::runtime_error("result of a task never handed out");
      ++totals_.results;
      totals_.result_bytes += static_cast<double>(m->bytes.size());
      totals_.largest_result =
          std::max(totals_.largest_result, static_cast<double>(m->bytes.size()));
      consume(index, std::string_view(m->bytes).substr(sizeof(std::uint64_t)), m->source);
      idle.push_back(m->source);
      backoff.Reset();
    } else {
      backoff.Wait();
    }
    stopped = poll();
  }
  std::vector<AbandonedTask> abandoned;
  for (const auto& [index, rank] : out) abandoned.push_back({index, rank});
  return abandoned;
}

// Tells every worker to quit and waits for each one's goodbye, discarding late results.
void MpiWorkers::EndJob() {
  for (int r = 1; r < size_; ++r) sends_.Post(r, kQuit, "");
  Backoff backoff;
  for (int byes = 0; byes < size_ - 1 || !sends_.Empty();) {
    sends_.Progress();
    if (auto m = Receive(MPI_ANY_SOURCE, MPI_ANY_TAG)) {
      byes += m->tag == kBye ? 1 : 0;
      backoff.Reset();
    } else {
      backoff.Wait();
    }
  }
}

void MpiWorkers::Serve(const Execute& execute) {
  WorkerQueues q;
  auto work = [&] {
    for (;;) {
      std::unique_lock lock(q.mutex);
      q.ready.wait(lock, [&] { return q.quit || !q.tasks.empty(); });
      if (q.quit) return;
      std::string task = std::move(q.tasks.front());
      q.tasks.pop_front();
      lock.unlock();
      std::string result, error;
      try {
        result =
            Framed(IndexOf(task), execute(std::string_view(task).substr(sizeof(std::uint64_t))));
      } catch (const std::exception& e) {
        error = e.what();
      }
      lock.lock();
      if (error.empty())
        q.results.push_back(std::move(result));
      else
        q.error = std::move(error);
      q.finished.notify_one();
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int t = 0; t < threads_; ++t) pool.emplace_back(work);
    Relay(q);
    const std::lock_guard lock(q.mutex);
    q.quit = true;
    q.ready.notify_all();
  }  // The threads finish the task they hold; its result is dropped.
  while (!sends_.Empty()) sends_.Progress();
  MPI_Send(nullptr, 0, MPI_BYTE, 0, kBye, MPI_COMM_WORLD);
}

void MpiWorkers::Relay(WorkerQueues& q) {
  Backoff backoff;
  for (;;) {
    std::optional<Message> m = Receive(0, MPI_ANY_TAG);
    if (m && m->tag == kQuit) return;
    std::deque<std::string> done;
    {
      std::unique_lock lock(q.mutex);
      if (m) {
        q.tasks.push_back(std::move(m->bytes));
        q.ready.notify_one();
        backoff.Reset();
      } else {
        // A result is sent the moment it is ready; a task is looked for after the wait.
        q.finished.wait_for(lock, backoff.Next(),
                            [&] { return !q.results.empty() || !q.error.empty(); });
      }
      if (!q.error.empty()) {
        std::fprintf(stderr, "shockmap: rank %d: %s\n", rank_, q.error.c_str());
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
      done.swap(q.results);
    }
    for (std::string& r : done) sends_.Post(0, kResult, std::move(r));
    if (!done.empty()) backoff.Reset();
    sends_.Progress();
  }
}

}  // namespace

std::unique_ptr<RemoteWorkers> JoinMpiJob(int threads) {
  // Only a process an MPI launcher started initializes MPI: a plain run stays a plain process.
  if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr && std::getenv("PMIX_RANK") == nullptr &&
      std::getenv("PMI_SIZE") == nullptr) {
    return nullptr;
  }
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return std::make_unique<MpiWorkers>(threads, rank, size);
}

}  // namespace shockmap

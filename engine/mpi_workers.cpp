// RemoteWorkers over MPI (built with SHOCKMAP_MPI). Only each process's calling thread makes MPI
// calls (MPI_THREAD_FUNNELED); a worker rank's compute threads hand their results to it. Every
// message is [task index: u64][bytes]; sends are non-blocking so that rank 0 handing a task to
// a rank and that rank returning a large reference never wait on each other. Waiting sleeps
// (from 20 us up to 0.25 ms) instead of spinning: on a shared node rank 0 leaves the cores to
// the workers.
// A worker rank's MPI thread also sends a heartbeat when it has sent nothing for
// kWorkerHeartbeatPeriodS, so rank 0 tells a stopped, hung or unreachable rank (silent for the
// rank timeout) from one busy on a long task.

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
#include <set>
#include <stdexcept>
#include <thread>

#include "engine/byte_codec.h"
#include "engine/mpi_job.h"
#include "engine/task_queue.h"

namespace shockmap {
namespace {

enum Tag : int { kTask = 1, kResult = 2, kQuit = 3, kBye = 4, kAlive = 5, kFinalize = 6 };

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The time left until a worker's next heartbeat is due (none left: zero).
std::chrono::microseconds UntilHeartbeat(Clock::time_point last_sent) {
  const double left_s = std::max(0.0, kWorkerHeartbeatPeriodS - SecondsSince(last_sent));
  return std::chrono::microseconds(static_cast<long>(left_s * 1e6));
}

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
    Pending& p = pending_.emplace_back(Pending{std::move(bytes), to, MPI_REQUEST_NULL});
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
  // No send is pending but to the ranks in `ignored` (which may never receive it).
  bool EmptyBut(const std::set<int>& ignored) const {
    return std::ranges::all_of(pending_, [&](const Pending& p) { return ignored.contains(p.to); });
  }

 private:
  struct Pending {
    std::string bytes;
    int to;
    MPI_Request request;
  };
  std::list<Pending> pending_;  // A list: requests keep their address.
};

// How a process waits for its next message (kSpinAfterMessageS, kShortestSleepS,
// kLongestSleepS). It spins because answers and tasks follow each other within a short task's
// time and a sleeping process notices a message late: on the 2-core test machine a sleep of
// 20 us lasts about 100 us, and under -np 2 a message waited 400 to 600 us for a sleeping rank
// (studies/quick.json's 319 tasks took 0.75 s sleeping, 0.46 s spinning; docs/cluster.md).
// Asleep, a message waits at most kLongestSleepS, at about 1 % of a core.
class Backoff {
 public:
  // A message came (or went): spin again.
  void Reset() {
    wait_ = kShortest;
    last_ = Clock::now();
  }
  // How long to sleep now: zero while spinning (yield instead).
  std::chrono::microseconds Next() {
    if (SecondsSince(last_) < kSpinAfterMessageS) return std::chrono::microseconds(0);
    const auto wait = wait_;
    wait_ = std::min(wait_ * 2, kLongest);
    return wait;
  }
  void Wait() {
    const auto wait = Next();
    if (wait.count() == 0) {
      std::this_thread::yield();
    } else {
      std::this_thread::sleep_for(wait);
    }
  }

 private:
  static constexpr std::chrono::microseconds kShortest{static_cast<long>(kShortestSleepS * 1e6)};
  static constexpr std::chrono::microseconds kLongest{static_cast<long>(kLongestSleepS * 1e6)};
  std::chrono::microseconds wait_ = kShortest;
  Clock::time_point last_ = Clock::now();
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
  MpiWorkers(int threads, double rank_timeout_s, int rank, int size)
      : threads_(threads),
        rank_timeout_s_(rank_timeout_s),
        rank_(rank),
        size_(size),
        heard_(static_cast<std::size_t>(size), Clock::now()) {
    char mine[256] = {};
    const std::string host = HostName();
    host.copy(mine, sizeof mine - 1);
    std::vector<char> all(256 * static_cast<std::size_t>(size));
    MPI_Allgather(mine, 256, MPI_CHAR, all.data(), 256, MPI_CHAR, MPI_COMM_WORLD);
    for (int r = 0; r < size; ++r) hosts_.emplace_back(all.data() + 256 * r);
  }
  ~MpiWorkers() override {
    if (rank_ == 0) EndJob();
    if (!lost_.empty()) {
      std::fflush(nullptr);
      MPI_Abort(MPI_COMM_WORLD, exit_code_);  // MPI_Finalize would wait for the lost ranks.
    }
    MPI_Finalize();
  }

  int Rank() const override { return rank_; }
  int WorkerRanks() const override { return size_ - 1; }
  int ThreadsPerRank() const override { return threads_; }
  PointOrigin OriginOf(int rank) const override {
    return {hosts_.at(static_cast<std::size_t>(rank)), rank};
  }
  MessageTotals Totals() const override { return totals_; }
  void SetExitCode(int exit_code) override { exit_code_ = exit_code; }

  std::vector<AbandonedTask> Run(const std::vector<std::size_t>& after,
                                 const std::vector<std::size_t>& group, const EncodeTask& encode,
                                 const ConsumeResult& consume, const std::function<bool()>& poll,
                                 const Describe& describe) override;
  void Serve(const Execute& execute) override;

 private:
  // The tasks out on each rank, the idle threads (one entry each, the ranks taking turns), the
  // tasks of lost ranks, handed out again before new ones, the tasks not yet handed out, and by
  // rank the groups it holds (the waited-for tasks it computed, and the group of every task it
  // was handed: the engine sends a reference along the first time), so that a rank is given
  // the points of the references it holds first.
  struct Schedule {
    std::map<std::size_t, int> out;  // Task index -> the rank computing it.
    std::deque<int> idle;
    std::deque<std::size_t> handed_back;
    TaskQueue waiting;
    GroupHolders held;  // By rank.
  };
  // Passes a worker rank's result to consume() and its thread back to the idle ones.
  void TakeResult(const Message& m, Schedule& schedule, const ConsumeResult& consume);
  // Counts as lost every rank silent for the rank timeout and hands its tasks back; throws
  // NoWorkerRankLeft when no worker rank is left. Call only with no message waiting, so that a
  // rank 0 busy elsewhere has read every heartbeat before it judges.
  void LoseSilentRanks(Schedule& schedule, const Describe& describe);
  void EndJob();
  // What a worker rank's compute threads and its MPI thread share.
  struct WorkerQueues {
    std::mutex mutex;
    std::condition_variable ready, finished;  // A task to compute; a result (or error) to send.
    std::deque<std::string> tasks, results;
    bool quit = false;
    std::string error;
  };
  // A worker's MPI thread: takes tasks and sends results (or a heartbeat when it has sent
  // nothing for kWorkerHeartbeatPeriodS) until rank 0 says quit.
  void Relay(WorkerQueues& q);
  // A worker rank, after its goodbye: waits until rank 0 says that the job finalizes (or ends
  // it with MPI_Abort, which kills this rank meanwhile).
  void AwaitFinalize();

  int threads_;
  double rank_timeout_s_;
  int rank_, size_;
  std::vector<std::string> hosts_;
  std::vector<Clock::time_point> heard_;  // On rank 0: when each rank's last message came.
  std::set<int> lost_;                    // On rank 0: worker ranks never given work again.
  std::vector<std::string> lost_reasons_;
  int exit_code_ = EXIT_FAILURE;  // MPI_Abort's, when a rank was lost.
  Sends sends_;
  MessageTotals totals_;
};

std::vector<AbandonedTask> MpiWorkers::Run(const std::vector<std::size_t>& after,
                                           const std::vector<std::size_t>& group,
                                           const EncodeTask& encode, const ConsumeResult& consume,
                                           const std::function<bool()>& poll,
                                           const Describe& describe) {
  Schedule schedule{{}, {}, {}, TaskQueue(after, group), GroupHolders(size_)};
  auto& [out, idle, handed_back, waiting, held] = schedule;
  // Silence counts from now: rank 0 may have been away (storing references) since the last run.
  std::fill(heard_.begin(), heard_.end(), Clock::now());
  for (int t = 0; t < threads_; ++t) {
    for (int r = 1; r < size_; ++r) {
      if (!lost_.contains(r)) idle.push_back(r);
    }
  }
  bool stopped = false;
  Backoff backoff;
  for (;;) {
    while (!stopped && !idle.empty() && (!handed_back.empty() || waiting.HasReady())) {
      const int rank = idle.front();
      std::size_t index = 0;
      if (handed_back.empty()) {
        index = waiting.Take(held.HeldBy(rank), held.HeldAnywhere());
      } else {
        index = handed_back.front();
        handed_back.pop_front();
      }
      if (group[index] != TaskQueue::kNoWait) held.Hold(rank, group[index]);
      std::string task = Framed(index, encode(index, rank));
      ++totals_.tasks;
      totals_.task_bytes += static_cast<double>(task.size());
      totals_.largest_task = std::max(totals_.largest_task, static_cast<double>(task.size()));
      sends_.Post(rank, kTask, std::move(task));
      out[index] = rank;
      idle.pop_front();
    }
    sends_.Progress();
    if (out.empty() || stopped) break;
    if (auto m = Receive(MPI_ANY_SOURCE, MPI_ANY_TAG)) {
      heard_[static_cast<std::size_t>(m->source)] = Clock::now();
      // Else a heartbeat, or a lost rank's late result: its task went to another rank.
      if (m->tag == kResult && !lost_.contains(m->source)) TakeResult(*m, schedule, consume);
      backoff.Reset();
    } else {
      LoseSilentRanks(schedule, describe);
      backoff.Wait();
    }
    stopped = poll();
  }
  std::vector<AbandonedTask> abandoned;
  for (const auto& [index, rank] : out) abandoned.push_back({index, rank});
  return abandoned;
}

void MpiWorkers::TakeResult(const Message& m, Schedule& schedule, const ConsumeResult& consume) {
  const std::size_t index = IndexOf(m.bytes);
  const auto task = schedule.out.find(index);
  if (task == schedule.out.end() || task->second != m.source) {
    throw std::runtime_error("result of a task never handed out");
  }
  schedule.out.erase(task);
  ++totals_.results;
  totals_.result_bytes += static_cast<double>(m.bytes.size());
  totals_.largest_result = std::max(totals_.largest_result, static_cast<double>(m.bytes.size()));
  consume(index, std::string_view(m.bytes).substr(sizeof(std::uint64_t)), m.source);
  schedule.waiting.Consumed(index);
  if (schedule.waiting.IsWaitedFor(index)) schedule.held.Hold(m.source, index);
  schedule.idle.push_back(m.source);
}

void MpiWorkers::LoseSilentRanks(Schedule& schedule, const Describe& describe) {
  for (int r = 1; r < size_; ++r) {
    const double silent_s = SecondsSince(heard_[static_cast<std::size_t>(r)]);
    if (lost_.contains(r) || silent_s < rank_timeout_s_) continue;
    lost_.insert(r);
    std::erase(schedule.idle, r);
    std::string held;
    for (auto task = schedule.out.begin(); task != schedule.out.end();) {
      if (task->second != r) {
        ++task;
        continue;
      }
      held += (held.empty() ? "" : ", ") + describe(task->first);
      schedule.handed_back.push_back(task->first);
      task = schedule.out.erase(task);
    }
    char silence[32];
    std::snprintf(silence, sizeof silence, "%.1f", silent_s);
    lost_reasons_.push_back("rank " + std::to_string(r) + " (host " +
                            hosts_[static_cast<std::size_t>(r)] + ") sent nothing for " + silence +
                            " s, holding " + (held.empty() ? "no task" : held));
    if (static_cast<int>(lost_.size()) == size_ - 1) {
      std::string all;
      for (const std::string& reason : lost_reasons_) all += (all.empty() ? "" : "; ") + reason;
      throw NoWorkerRankLeft("no worker rank answers: " + all);
    }
    std::fprintf(stderr, "shockmap: %s: it gets no more work, its tasks go to the other ranks\n",
                 lost_reasons_.back().c_str());
  }
}

// Tells every worker rank not lost to quit and waits for each one's goodbye, discarding late
// results and heartbeats. A rank silent for the rank timeout meanwhile (stopped after its last
// task) is lost, not waited for. Then, when no rank was lost, tells the worker ranks to finalize.
// When one was, the live worker ranks stay out of MPI_Finalize, whose fence could not complete:
// Open MPI 4.1's mpirun, aborting a job whose ranks wait in that fence, often deadlocks or
// crashes in its own PMIx_server_finalize once every rank has ended (docs/cluster.md).
void MpiWorkers::EndJob() {
  std::set<int> waiting;
  for (int r = 1; r < size_; ++r) {
    if (lost_.contains(r)) continue;
    sends_.Post(r, kQuit, "");
    waiting.insert(r);
  }
  std::fill(heard_.begin(), heard_.end(), Clock::now());
  Backoff backoff;
  while (!waiting.empty() || !sends_.EmptyBut(lost_)) {
    sends_.Progress();
    if (auto m = Receive(MPI_ANY_SOURCE, MPI_ANY_TAG)) {
      heard_[static_cast<std::size_t>(m->source)] = Clock::now();
      if (m->tag == kBye) waiting.erase(m->source);
      backoff.Reset();
      continue;
    }
    for (auto r = waiting.begin(); r != waiting.end();) {
      if (SecondsSince(heard_[static_cast<std::size_t>(*r)]) < rank_timeout_s_) {
        ++r;
        continue;
      }
      std::fprintf(stderr,
                   "shockmap: rank %d (host %s) did not answer the end of the job for %.1f s\n", *r,
                   hosts_[static_cast<std::size_t>(*r)].c_str(), rank_timeout_s_);
      lost_.insert(*r);
      r = waiting.erase(r);
    }
    backoff.Wait();
  }
  if (!lost_.empty()) return;
  for (int r = 1; r < size_; ++r) MPI_Send(nullptr, 0, MPI_BYTE, r, kFinalize, MPI_COMM_WORLD);
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
  AwaitFinalize();
}

void MpiWorkers::AwaitFinalize() {
  Backoff backoff;
  while (!Receive(0, kFinalize)) backoff.Wait();
}

void MpiWorkers::Relay(WorkerQueues& q) {
  Backoff backoff;
  Clock::time_point last_sent = Clock::now();
  int in_flight = 0;  // Tasks taken whose results are not sent yet.
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
        ++in_flight;
      } else {
        // A result is sent the moment it is ready; a task is looked for after the wait. While
        // every compute thread is busy and nothing is left to send, no task can come (rank 0
        // hands a rank one task per thread): the wait lasts until a result or the heartbeat,
        // so that looking for tasks takes no time from the computation.
        const bool busy = in_flight >= threads_ && sends_.Empty();
        const auto wait = busy ? UntilHeartbeat(last_sent) : backoff.Next();
        if (wait.count() > 0) {
          q.finished.wait_for(lock, wait, [&] { return !q.results.empty() || !q.error.empty(); });
        } else {
          lock.unlock();
          std::this_thread::yield();
          lock.lock();
        }
      }
      if (!q.error.empty()) {
        std::fprintf(stderr, "shockmap: rank %d: %s\n", rank_, q.error.c_str());
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
      done.swap(q.results);
    }
    for (std::string& r : done) sends_.Post(0, kResult, std::move(r));
    in_flight -= static_cast<int>(done.size());
    if (!done.empty()) {
      backoff.Reset();
      last_sent = Clock::now();
    }
    if (SecondsSince(last_sent) >= kWorkerHeartbeatPeriodS) {
      sends_.Post(0, kAlive, "");
      last_sent = Clock::now();
    }
    sends_.Progress();
  }
}

}  // namespace

std::unique_ptr<RemoteWorkers> JoinMpiJob(int threads, double rank_timeout_s) {
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
  return std::make_unique<MpiWorkers>(threads, rank_timeout_s, rank, size);
}

}  // namespace shockmap

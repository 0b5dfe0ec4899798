#include "bench/cluster_model/cluster_simulation.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

#include "engine/remote_workers.h"
#include "engine/study_engine.h"

namespace shockmap {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// The first instant at or after t_s at which a process that last got a message at reset_s looks
// for one: at once within kSpinAfterMessageS, then after each of its sleeps.
double NextLook(double reset_s, double t_s, double overshoot_s) {
  if (t_s <= reset_s + kSpinAfterMessageS) return t_s;
  double look = reset_s + kSpinAfterMessageS, sleep = kShortestSleepS;
  while (look < t_s && sleep < kLongestSleepS) {
    look += sleep + overshoot_s;
    sleep = std::min(2.0 * sleep, kLongestSleepS);
  }
  if (look >= t_s) return look;
  const double period = kLongestSleepS + overshoot_s;
  return look + std::ceil((t_s - look) / period) * period;
}

// Messages through one link, one at a time.
class Link {
 public:
  Link(double bandwidth_bytes_per_s, double latency_s)
      : bandwidth_(bandwidth_bytes_per_s), latency_(latency_s) {}
  // When a message of `bytes` sent at t_s arrives.
  double Send(double t_s, double bytes) {
    free_s_ = std::max(free_s_, t_s) + bytes / bandwidth_;
    return free_s_ + latency_;
  }

 private:
  double bandwidth_, latency_, free_s_ = 0.0;
};

// Busy processes sharing the cores equally: each job advances by the same service per second,
// min(1, cores / (jobs + spinners)), so jobs end in the order of the service at which they end.
// A spinner holds its share of a core without a job (a process looking for messages).
class SharedCores {
 public:
  explicit SharedCores(int cores) : cores_(cores) {}
  // Call after AdvanceTo(now).
  void AddSpinners(long change) { spinners_ += change; }
  void Start(int owner, double work_s) { jobs_.push({service_s_ + work_s, owner}); }
  double NextEnd() const {
    return jobs_.empty() ? kNever : now_s_ + (jobs_.top().first - service_s_) / Rate();
  }
  void AdvanceTo(double t_s) {
    if (!jobs_.empty()) service_s_ += (t_s - now_s_) * Rate();
    now_s_ = t_s;
  }
  // Ends the job ending next; returns its owner.
  int EndNext() {
    const int owner = jobs_.top().second;
    service_s_ = std::max(service_s_, jobs_.top().first);
    jobs_.pop();
    return owner;
  }

 private:
  double Rate() const {
    const auto busy = static_cast<double>(jobs_.size()) + static_cast<double>(spinners_);
    return cores_ <= 0 || busy <= cores_ ? 1.0 : cores_ / busy;
  }
  int cores_;
  long spinners_ = 0;
  double now_s_ = 0.0, service_s_ = 0.0;
  using Job = std::pair<double, int>;  // Service at which it ends, its owner (0: rank 0).
  std::priority_queue<Job, std::vector<Job>, std::greater<>> jobs_;
};

class Simulation {
 public:
  Simulation(const StudyCosts& costs, const ClusterSetup& setup)
      : costs_(costs),
        setup_(setup),
        queue_(WaitedFor(costs)),
        cores_(setup.cores),
        out_(setup.bandwidth_bytes_per_s, setup.latency_s),
        in_(setup.bandwidth_bytes_per_s, setup.latency_s),
        worker_reset_s_(static_cast<std::size_t>(setup.worker_ranks) + 1, 0.0),
        spinning_(static_cast<std::size_t>(setup.worker_ranks) + 1, false),
        held_(static_cast<std::size_t>(setup.worker_ranks) + 1) {
    for (int r = 1; r <= setup.worker_ranks; ++r) idle_.push_back(r);
    for (const TaskCost& t : costs.tasks) result_.work_s += t.compute_s;
  }

  SimulatedRun Run() {
    Turn();
    for (;;) {
      const double cpu = cores_.NextEnd();
      const double event = events_.empty() ? kNever : events_.top().t_s;
      if (cpu == kNever && event == kNever) break;
      if (cpu <= event) {
        Advance(cpu);
        const int owner = cores_.EndNext();
        if (owner == 0) {
          Rank0Done();
        } else {
          WorkerDone(owner);
        }
      } else {
        const Event e = events_.top();
        events_.pop();
        Advance(e.t_s);
        Handle(e);
      }
    }
    result_.efficiency = result_.work_s / (setup_.worker_ranks * result_.wall_s);
    return result_;
  }

 private:
  enum class EventType { kWorkerStarts, kAnswerArrives, kRank0Looks, kSpinEnds };
  struct Event {
    double t_s;
    std::size_t order;  // Equal times: in the order scheduled.
    EventType type;
    int rank;
    std::size_t task;
    bool operator>(const Event& o) const { return t_s != o.t_s ? t_s > o.t_s : order > o.order; }
  };
  enum class Rank0Job { kNone, kConsume, kStoreGroup, kStoreLast };

  static std::vector<std::size_t> WaitedFor(const StudyCosts& costs) {
    std::vector<std::size_t> after;
    for (std::size_t i = 0; i < costs.tasks.size(); ++i) {
      const std::size_t a = costs.tasks[i].after;
      if (a != TaskQueue::kNoWait && a >= i) {
        throw std::invalid_argument("task " + std::to_string(i) + " waits for task " +
                                    std::to_string(a) + ", not one before it");
      }
      after.push_back(a);
    }
    return after;
  }

  void Advance(double t_s) {
    cores_.AdvanceTo(t_s);
    if (rank0_job_ != Rank0Job::kNone) result_.rank0_busy_s += t_s - now_s_;
    now_s_ = t_s;
  }
  void Schedule(double t_s, EventType type, int rank = 0, std::size_t task = 0) {
    events_.push({std::max(t_s, now_s_), next_order_++, type, rank, task});
  }
  double GroupCost(std::size_t points) const {
    return costs_.group_s + static_cast<double>(points) * costs_.stored_point_s;
  }
  void StartRank0(Rank0Job job, double work_s) {
    Spin(0, false);
    rank0_job_ = job;
    cores_.Start(0, work_s);
  }
  // Rank 0 (0) or a worker rank looking for messages without pause, or no longer.
  void Spin(int rank, bool on) {
    if (spinning_[rank] == on) return;
    spinning_[rank] = on;
    cores_.AddSpinners(on ? 1 : -1);
    if (on) Schedule(Reset(rank) + kSpinAfterMessageS, EventType::kSpinEnds, rank);
  }
  double Reset(int rank) const { return rank == 0 ? rank0_reset_s_ : worker_reset_s_[rank]; }
  // Rank 0 with nothing to do: it spins until kSpinAfterMessageS after the last message.
  void Rank0Idle() {
    if (rank0_job_ == Rank0Job::kNone && now_s_ < rank0_reset_s_ + kSpinAfterMessageS)
      Spin(0, true);
  }

  void Handle(const Event& e) {
    switch (e.type) {
      case EventType::kWorkerStarts:
        Spin(e.rank, false);
        cores_.Start(e.rank, costs_.tasks[e.task].compute_s + setup_.task_overhead_s);
        computing_[e.rank] = e.task;
        break;
      case EventType::kAnswerArrives:
        inbox_.push_back({e.rank, e.task});
        if (rank0_job_ == Rank0Job::kNone) {
          Schedule(NextLook(rank0_reset_s_, now_s_, setup_.sleep_overshoot_s),
                   EventType::kRank0Looks);
        }
        break;
      case EventType::kRank0Looks:
        if (rank0_job_ == Rank0Job::kNone) Look();
        break;
      case EventType::kSpinEnds:
        if (spinning_[e.rank] && now_s_ >= Reset(e.rank) + kSpinAfterMessageS) Spin(e.rank, false);
        break;
    }
  }

  // Rank 0 looking for work (after a sleep, or its turn's hand-out): reads an answer if one
  // came, else stores the group if it is due, else waits.
  void Look() {
    if (!inbox_.empty()) {
      Consume();
    } else if (GroupDue()) {
      StartRank0(Rank0Job::kStoreGroup, GroupCost(finished_));
    } else if (finished_ > 0) {
      Schedule(NextLook(rank0_reset_s_, last_store_s_ + kGroupLatencyS, setup_.sleep_overshoot_s),
               EventType::kRank0Looks);
    }
    Rank0Idle();
  }
  bool GroupDue() const { return finished_ > 0 && now_s_ >= last_store_s_ + kGroupLatencyS; }

  // Rank 0 idle: hands tasks out, then looks for work.
  void Turn() {
    HandOut();
    if (consumed_ == costs_.tasks.size()) {
      if (finished_ > 0) {
        StartRank0(Rank0Job::kStoreLast, GroupCost(finished_));
      } else {
        result_.wall_s = now_s_;
      }
      return;
    }
    Look();
  }

  void HandOut() {
    while (!idle_.empty() && queue_.HasReady()) {
      const int rank = idle_.front();
      const std::size_t task = queue_.Take(held_.HeldBy(rank), held_.HeldAnywhere());
      idle_.pop_front();
      double bytes = costs_.task_bytes;
      const std::size_t reference = costs_.tasks[task].after;
      if (reference != TaskQueue::kNoWait && held_.Hold(rank, reference)) {
        bytes += costs_.tasks[reference].answer_bytes;
      }
      result_.bytes_sent += bytes;
      const double arrives = out_.Send(now_s_, bytes);
      Schedule(NextLook(worker_reset_s_[rank], arrives, setup_.sleep_overshoot_s),
               EventType::kWorkerStarts, rank, task);
    }
  }

  void Consume() {
    consuming_ = inbox_.front();
    inbox_.pop_front();
    rank0_reset_s_ = now_s_;
    const TaskCost& t = costs_.tasks[consuming_.second];
    storing_with_ = !t.reference && finished_ + 1 >= kMaxGroup;
    StartRank0(Rank0Job::kConsume, t.consume_s + (storing_with_ ? GroupCost(finished_ + 1) : 0.0));
  }

  void Rank0Done() {
    const Rank0Job job = rank0_job_;
    rank0_job_ = Rank0Job::kNone;
    switch (job) {
      case Rank0Job::kConsume: {
        const auto [rank, task] = consuming_;
        if (costs_.tasks[task].reference) {
          held_.Hold(rank, task);
        } else {
          ++finished_;
        }
        if (storing_with_) Stored();
        queue_.Consumed(task);
        ++consumed_;
        idle_.push_back(rank);
        if (GroupDue()) {
          StartRank0(Rank0Job::kStoreGroup, GroupCost(finished_));
          return;
        }
        break;
      }
      case Rank0Job::kStoreGroup:
        Stored();
        break;
      case Rank0Job::kStoreLast:
        Stored();
        result_.wall_s = now_s_;
        return;
      case Rank0Job::kNone:
        break;
    }
    Turn();
  }

  void Stored() {
    finished_ = 0;
    last_store_s_ = now_s_;
    ++result_.groups;
  }

  void WorkerDone(int rank) {
    const std::size_t task = computing_.at(rank);
    computing_.erase(rank);
    worker_reset_s_[rank] = now_s_;
    Spin(rank, true);
    Schedule(in_.Send(now_s_, costs_.tasks[task].answer_bytes), EventType::kAnswerArrives, rank,
             task);
  }

  const StudyCosts& costs_;
  const ClusterSetup& setup_;
  TaskQueue queue_;
  SharedCores cores_;
  Link out_, in_;  // Rank 0's link: tasks out, answers in.
  std::priority_queue<Event, std::vector<Event>, std::greater<>> events_;
  std::size_t next_order_ = 0;
  double now_s_ = 0.0;
  // Rank 0.
  Rank0Job rank0_job_ = Rank0Job::kNone;
  double rank0_reset_s_ = 0.0, last_store_s_ = 0.0;
  std::deque<std::pair<int, std::size_t>> inbox_;  // Answers arrived: rank, task.
  std::pair<int, std::size_t> consuming_{0, 0};
  bool storing_with_ = false;  // The answer consumed fills the group, which is stored with it.
  std::size_t finished_ = 0;   // Points kept for the next group.
  std::size_t consumed_ = 0;
  std::deque<int> idle_;
  // Worker ranks.
  std::vector<double> worker_reset_s_;
  std::vector<bool> spinning_;            // By rank, 0 included.
  GroupHolders held_;                     // By rank: the reference tasks it holds.
  std::map<int, std::size_t> computing_;  // By rank: its task.
  SimulatedRun result_;
};

}  // namespace

SimulatedRun SimulateRun(const StudyCosts& costs, const ClusterSetup& setup) {
  if (setup.worker_ranks < 1) throw std::invalid_argument("no worker rank");
  return Simulation(costs, setup).Run();
}

}  // namespace shockmap

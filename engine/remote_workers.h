#pragma once
// Workers in other processes (MPI ranks 1..N-1, engine/mpi_workers.cpp) that parsed the same
// study file. Rank 0 calls Run and alone touches the database; the other ranks call Serve.
// A task and its result travel as bytes.

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "db/study_database.h"

namespace shockmap {

// A task handed out and not answered when the run stopped.
struct AbandonedTask {
  std::size_t index = 0;
  int rank = 0;
};

// Every worker rank went silent (RemoteWorkers::Run): the study cannot go on. The message names
// each rank, its host and the tasks it held.
struct NoWorkerRankLeft : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What rank 0 sent and received: tasks (with the references they carry) and results.
struct MessageTotals {
  long tasks = 0, results = 0;
  double task_bytes = 0, result_bytes = 0;
  double largest_task = 0, largest_result = 0;
};

class RemoteWorkers {
 public:
  using EncodeTask = std::function<std::string(std::size_t index, int rank)>;
  using ConsumeResult = std::function<void(std::size_t index, std::string_view bytes, int rank)>;
  using Execute = std::function<std::string(std::string_view task)>;
  using Describe = std::function<std::string(std::size_t index)>;

  virtual ~RemoteWorkers() = default;

  // This process's rank; rank 0 runs the study, the others serve it.
  virtual int Rank() const = 0;
  // Worker ranks (N - 1) and the threads each runs tasks on.
  virtual int WorkerRanks() const = 0;
  virtual int ThreadsPerRank() const = 0;
  virtual PointOrigin OriginOf(int rank) const = 0;
  // Since the job started, on rank 0.
  virtual MessageTotals Totals() const = 0;

  // On rank 0: hands task i (encode(i, rank)) to a worker rank as soon as one of its threads is
  // idle and the task it waits for, after[i], has been consumed (in TaskQueue's order; a rank
  // is given first the tasks whose group[i], what they need, it holds: the waited-for tasks it
  // computed and the groups of the tasks it was handed), and passes each result to consume() on
  // the calling thread, in completion order. poll() runs after every result and every
  // millisecond while waiting; once it returns true, Run returns at once with the tasks still out:
  // a stopped job does not wait, since under an MPI launcher SIGTERM is followed by SIGKILL within
  // a second (a dead worker rank would never answer anyway). A worker rank silent for the job's
  // rank timeout (stopped, hung or unreachable) is lost: Run prints on stderr its rank, host and
  // the tasks it held (each named by describe(i)), hands those to the other ranks and never gives
  // it work again; a late result from it is dropped, so every task is consumed once. Throws
  // NoWorkerRankLeft when the last worker rank is lost, std::runtime_error on a malformed message.
  virtual std::vector<AbandonedTask> Run(const std::vector<std::size_t>& after,
                                         const std::vector<std::size_t>& group,
                                         const EncodeTask& encode, const ConsumeResult& consume,
                                         const std::function<bool()>& poll,
                                         const Describe& describe) = 0;

  // The exit code of a job that lost a rank, which ends in MPI_Abort (see engine/mpi_job.h): 1
  // unless set, on rank 0, before the object is destroyed (the code of the error that ends the
  // run).
  virtual void SetExitCode(int exit_code) = 0;

  // On ranks 1..N-1: runs every task rank 0 sends on ThreadsPerRank() threads and sends back
  // execute(task), until rank 0 ends the job. execute must not throw.
  virtual void Serve(const Execute& execute) = 0;
};

// How long rank 0 waits for word from a worker rank before it counts the rank as lost; a
// worker rank's MPI thread sends at least every kWorkerHeartbeatPeriodS, however long its
// tasks take.
inline constexpr double kDefaultRankTimeoutS = 60.0;
inline constexpr double kWorkerHeartbeatPeriodS = 0.5;

// How a rank waits for its next message (engine/mpi_workers.cpp, Backoff): it yields its core
// for kSpinAfterMessageS after the last message, then sleeps kShortestSleepS, twice that, and
// so on up to kLongestSleepS between looks.
inline constexpr double kSpinAfterMessageS = 2e-3;
inline constexpr double kShortestSleepS = 20e-6, kLongestSleepS = 250e-6;

}  // namespace shockmap

#pragma once
// A discrete-event model of a study run as an MPI job (docs/cluster.md, "A model of the
// cluster, checked"): what rank 0's engine (engine/study_engine.h) and MpiWorkers
// (engine/mpi_workers.cpp) do, with measured costs in place of the computations.
// - Rank 0 hands tasks out in the engine's order (TaskQueue: references longest first, a point
//   once its reference is stored, first to a rank that holds its reference), one to each
//   idle worker rank; a score task carries its reference the first time a rank that did not
//   compute it needs it. Each turn it reads one
//   answer and consumes it (a reference decoded and stored; an outcome decoded and kept, the
//   group stored once it holds kMaxGroup), then stores the group kGroupLatencyS after the
//   previous one, then hands out again; the last group is stored at the end.
// - Rank 0 and each worker rank's messaging thread look for a message without pause within
//   kSpinAfterMessageS of the last one (rank 0: the last it read; a worker: the last answer it
//   sent), then after sleeps of kShortestSleepS doubling up to kLongestSleepS
//   (engine/remote_workers.h), each lasting `sleep_overshoot_s` longer than asked.
// - Rank 0's messages leave one at a time on its link, the answers arrive one at a time on it:
//   bytes / bandwidth each, then the latency.
// - When more processes are busy (rank 0 at work, workers computing) than there are cores, they
//   share the cores equally.

#include <cstddef>
#include <vector>

#include "engine/task_queue.h"

namespace shockmap {

struct TaskCost {
  double compute_s = 0.0;                  // On one worker rank alone on its core.
  std::size_t after = TaskQueue::kNoWait;  // The reference task it waits for.
  double answer_bytes = 0.0;               // Its answer: a reference or an outcome.
  double consume_s = 0.0;                  // Rank 0's work as the answer arrives.
  bool reference = false;  // Stored at once and kept by the rank that computed it; else a point.
};

struct StudyCosts {
  std::vector<TaskCost> tasks;  // References first, then points, as the engine lists them.
  double task_bytes = 0.0;      // A task message without a reference.
  double group_s = 0.0;         // Rank 0's work per stored group (its transaction) ...
  double stored_point_s = 0.0;  // ... and per point in it.
};

struct ClusterSetup {
  int worker_ranks = 1;  // One compute thread each.
  int cores = 0;         // Shared by rank 0 and the worker ranks; 0: a core each.
  double bandwidth_bytes_per_s = 1.25e9;
  double latency_s = 2e-6;
  double sleep_overshoot_s = 0.0;
  // A worker rank's own cost per task beyond the computation (the task read, its answer
  // written and sent, its threads woken): added to each task's compute_s.
  double task_overhead_s = 0.0;
};

struct SimulatedRun {
  double wall_s = 0.0;      // From the first task handed out to the last group stored.
  double work_s = 0.0;      // The tasks' compute_s, summed.
  double efficiency = 0.0;  // work_s / (worker_ranks x wall_s).
  double rank0_busy_s = 0.0;
  std::size_t groups = 0;
  double bytes_sent = 0.0;  // Tasks, references included.
};

// Throws std::invalid_argument when a task waits for one that is not a task before it, or
// the setup has no worker rank.
SimulatedRun SimulateRun(const StudyCosts& costs, const ClusterSetup& setup);

}  // namespace shockmap

// The cluster model's simulation (bench/cluster_model/cluster_simulation.h) against cases whose
// wall time is known: equal tasks on ranks of their own, cores shared, a saturated writer, a
// reference sent once to each rank that scores against it, a point given where its reference is.

#include "bench/cluster_model/cluster_simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "engine/remote_workers.h"
#include "engine/study_engine.h"

namespace shockmap {
namespace {

StudyCosts EqualPoints(std::size_t n, double compute_s) {
  StudyCosts c;
  c.tasks.assign(n, TaskCost{compute_s, TaskQueue::kNoWait, 0.0, 0.0, false});
  return c;
}

// `ranks` worker ranks behind a link of 1e9 bytes/s without latency.
ClusterSetup OnAGigabyteLink(int ranks) {
  ClusterSetup setup;
  setup.worker_ranks = ranks;
  setup.bandwidth_bytes_per_s = 1e9;
  setup.latency_s = 0.0;
  return setup;
}

// N tasks of 1 ms on P ranks of their own: ceil(N / P) rounds; a rank's next task follows its
// answer at once (both sides spin within kSpinAfterMessageS of their last message), so the wall
// time is that of the rounds to the nanosecond, and the efficiency N / (P ceil(N / P)).
TEST(ClusterSimulation, EqualTasksTakeTheirRounds) {
  for (const int ranks : {1, 3, 8, 40}) {
    ClusterSetup setup;
    setup.worker_ranks = ranks;
    setup.latency_s = 0.0;
    const SimulatedRun run = SimulateRun(EqualPoints(40, 1e-3), setup);
    const double rounds = std::ceil(40.0 / ranks);
    EXPECT_NEAR(run.wall_s, 1e-3 * rounds, 1e-9) << ranks << " ranks";
    EXPECT_NEAR(run.efficiency, 40.0 / (ranks * rounds), 1e-6) << ranks << " ranks";
  }
}

// Three ranks on two cores, no overhead: the three tasks of 1 s share the cores and end
// together at 1.5 s (rank 0 takes a share while it spins at the start, and reads the answers
// after a sleep: within 1 ms).
TEST(ClusterSimulation, RanksBeyondTheCoresShareThem) {
  ClusterSetup setup;
  setup.worker_ranks = 3;
  setup.cores = 3;
  EXPECT_NEAR(SimulateRun(EqualPoints(3, 1.0), setup).wall_s, 1.0, 1e-3);
  setup.cores = 2;
  EXPECT_NEAR(SimulateRun(EqualPoints(3, 1.0), setup).wall_s, 1.5, 1e-3);
}

// A writer slower than the workers: rank 0 reads each answer in 1 ms while 100 ranks answer
// every 10 ms; the run takes the writer's time, N ms (within one task), and rank 0 is busy
// nearly all of it.
TEST(ClusterSimulation, ASaturatedWriterSetsTheWallTime) {
  StudyCosts costs = EqualPoints(2000, 0.01);
  for (TaskCost& t : costs.tasks) t.consume_s = 1e-3;
  ClusterSetup setup;
  setup.worker_ranks = 100;
  const SimulatedRun run = SimulateRun(costs, setup);
  EXPECT_GT(run.wall_s, 2.0);
  EXPECT_LT(run.wall_s, 2.0 + 0.02);
  EXPECT_GT(run.rank0_busy_s / run.wall_s, 0.98);
  EXPECT_NEAR(run.efficiency, 20.0 / (100 * run.wall_s), 1e-9);
}

// Points wait for their reference; it goes to every rank that scores one of them and did not
// compute it, once: 4 points on 4 ranks take the reference's 1 s, then a point's 1 s after
// the reference crossed rank 0's link (3 copies of 1e8 bytes at 1e9 bytes/s, one after the
// other: the last point starts 0.3 s late).
TEST(ClusterSimulation, AReferenceIsSentOnceToEachRankThatNeedsIt) {
  StudyCosts costs;
  costs.task_bytes = 100.0;
  costs.tasks.push_back({1.0, TaskQueue::kNoWait, 1e8, 0.0, true});
  for (int i = 0; i < 4; ++i) costs.tasks.push_back({1.0, 0, 100.0, 0.0, false});
  const SimulatedRun run = SimulateRun(costs, OnAGigabyteLink(4));
  EXPECT_DOUBLE_EQ(run.bytes_sent, 5 * 100.0 + 3 * 1e8);
  // The reference's answer crosses the link too (0.1 s), and the slowest point starts after
  // the three copies (0.3 s); ranks idle for longer than kSpinAfterMessageS notice a message
  // at most kLongestSleepS late, twice on that path.
  EXPECT_GE(run.wall_s, 1.0 + 0.1 + 0.3 + 1.0);
  EXPECT_LE(run.wall_s, 1.0 + 0.1 + 0.3 + 1.0 + 3 * kLongestSleepS);
}

// Two references computed at once on two ranks, ten points each: a rank is given the points of
// the reference it holds, so no reference crosses the link (before, the first reference's points
// went to both ranks, and so did the second's: both references were sent).
TEST(ClusterSimulation, ARankScoresThePointsOfTheReferenceItHolds) {
  StudyCosts costs;
  costs.task_bytes = 100.0;
  for (int r = 0; r < 2; ++r) costs.tasks.push_back({1.0, TaskQueue::kNoWait, 1e8, 0.0, true});
  for (std::size_t reference : {0, 1}) {
    for (int i = 0; i < 10; ++i) costs.tasks.push_back({0.1, reference, 100.0, 0.0, false});
  }
  const SimulatedRun run = SimulateRun(costs, OnAGigabyteLink(2));
  EXPECT_DOUBLE_EQ(run.bytes_sent, 2 * 100.0 + 20 * 100.0);
  // The references' answers cross rank 0's link one after the other (0.1 s each): the second
  // rank's points start 0.2 s after its reference's end.
  EXPECT_GE(run.wall_s, 1.0 + 0.2 + 10 * 0.1);
  EXPECT_LE(run.wall_s, 1.0 + 0.2 + 10 * 0.1 + 0.01);
}

// Points arriving slower than kGroupLatencyS apart are stored one group per arrival; faster,
// in groups of kMaxGroup.
TEST(ClusterSimulation, PointsAreStoredInTheEnginesGroups) {
  ClusterSetup setup;
  setup.worker_ranks = 1;
  EXPECT_EQ(SimulateRun(EqualPoints(5, 0.2), setup).groups, 5u);
  EXPECT_EQ(SimulateRun(EqualPoints(2 * kMaxGroup, 1e-5), setup).groups, 2u);
}

TEST(ClusterSimulation, RefusesATaskWaitingForALaterOne) {
  StudyCosts costs = EqualPoints(2, 1.0);
  costs.tasks[0].after = 1;
  EXPECT_THROW(SimulateRun(costs, ClusterSetup{}), std::invalid_argument);
  EXPECT_THROW(SimulateRun(EqualPoints(1, 1.0), ClusterSetup{0}), std::invalid_argument);
}

}  // namespace
}  // namespace shockmap

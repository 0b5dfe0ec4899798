// The cluster model (docs/cluster.md, "A model of the cluster, checked"): measures what each
// task of a study costs on this machine (task_costs.h), then simulates the study as an MPI job
// (cluster_simulation.h) and prints the wall time and efficiency it predicts.
//
//   cluster_model STUDY.json [--measure-points N] [--costs-out FILE]   measure, then predict
//   cluster_model --costs FILE                                         predict from a measure
// Predictions: --ranks (worker ranks; a core each, or --cores shared by all), --tasks-per-rank T
// (the study's tasks repeated until each worker rank has at least T), --check NP=SECONDS,...
// (the point phase's wall time `study run` printed under `mpirun -np NP`: the model against it).

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench/cluster_model/cluster_simulation.h"
#include "bench/cluster_model/task_costs.h"
#include "specs/study_file.h"

namespace shockmap {
namespace {

nlohmann::json ToJson(const MeasuredCosts& m) {
  nlohmann::json tasks = nlohmann::json::array();
  for (const TaskCost& t : m.costs.tasks) {
    tasks.push_back({t.compute_s, t.after == TaskQueue::kNoWait ? -1 : static_cast<long>(t.after),
                     t.answer_bytes, t.consume_s, t.reference});
  }
  return {{"references", m.references},
          {"points", m.points},
          {"points_measured", m.points_measured},
          {"task_bytes", m.costs.task_bytes},
          {"group_s", m.costs.group_s},
          {"stored_point_s", m.costs.stored_point_s},
          {"tasks", tasks}};
}

MeasuredCosts FromJson(const nlohmann::json& j) {
  MeasuredCosts m;
  m.references = j.at("references");
  m.points = j.at("points");
  m.points_measured = j.at("points_measured");
  m.costs.task_bytes = j.at("task_bytes");
  m.costs.group_s = j.at("group_s");
  m.costs.stored_point_s = j.at("stored_point_s");
  for (const auto& t : j.at("tasks")) {
    const long after = t.at(1);
    m.costs.tasks.push_back({t.at(0),
                             after < 0 ? TaskQueue::kNoWait : static_cast<std::size_t>(after),
                             t.at(2), t.at(3), t.at(4)});
  }
  return m;
}

// How much longer than asked MpiWorkers' sleeps of 20 to 250 us last here (mean).
double SleepOvershootS() {
  using Clock = std::chrono::steady_clock;
  double over = 0.0;
  int n = 0;
  for (int round = 0; round < 40; ++round) {
    for (const int us : {20, 40, 80, 160, 250}) {
      const auto start = Clock::now();
      std::this_thread::sleep_for(std::chrono::microseconds(us));
      over += std::chrono::duration<double>(Clock::now() - start).count() - us * 1e-6;
      ++n;
    }
  }
  return over / n;
}

// The study's tasks repeated `copies` times in the engine's order: every reference's copies
// (longest first), then each copy's points, waiting for their copy's references.
StudyCosts Repeated(const MeasuredCosts& m, std::size_t copies) {
  StudyCosts r = m.costs;
  r.tasks.clear();
  for (std::size_t k = 0; k < m.references; ++k) {
    for (std::size_t c = 0; c < copies; ++c) r.tasks.push_back(m.costs.tasks[k]);
  }
  for (std::size_t c = 0; c < copies; ++c) {
    for (std::size_t j = m.references; j < m.costs.tasks.size(); ++j) {
      TaskCost t = m.costs.tasks[j];
      if (t.after != TaskQueue::kNoWait) t.after = t.after * copies + c;
      r.tasks.push_back(t);
    }
  }
  return r;
}

struct Flags {
  std::string study, costs_in, costs_out, check;
  std::size_t measure_points = 0, tasks_per_rank = 0;
  std::vector<int> ranks = {10, 100, 1000, 10000};
  ClusterSetup setup;
  bool measure_sleep = true;
};

MeasuredCosts Costs(const Flags& f) {
  if (!f.costs_in.empty()) return FromJson(nlohmann::json::parse(std::ifstream(f.costs_in)));
  const std::string scratch =
      (std::filesystem::temp_directory_path() / fmt::format("cluster_model_{}.db", ::getpid()))
          .string();
  const MeasuredCosts m = MeasureStudy(ReadStudyFile(f.study), scratch, f.measure_points);
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(scratch + suffix);
  if (!f.costs_out.empty()) std::ofstream(f.costs_out) << ToJson(m).dump() << "\n";
  return m;
}

void PrintCosts(const MeasuredCosts& m) {
  double references = 0.0, points = 0.0, consume = 0.0;
  for (std::size_t i = 0; i < m.costs.tasks.size(); ++i) {
    (i < m.references ? references : points) += m.costs.tasks[i].compute_s;
    consume += m.costs.tasks[i].consume_s;
  }
  fmt::print(
      "measured: {} references {:.3f} s, {} points {:.3f} s ({} measured, {:.3g} ms each), rank 0 "
      "{:.3f} s to read answers, a group {:.3g} ms + {:.3g} us per point, task {:.0f} B\n",
      m.references, references, m.points, points, m.points_measured,
      1e3 * points / std::max<double>(1.0, static_cast<double>(m.points)), consume,
      1e3 * m.costs.group_s, 1e6 * m.costs.stored_point_s, m.costs.task_bytes);
}

// The real runs' point phases, "NP=SECONDS,..." in increasing NP.
std::vector<std::pair<int, double>> Measured(const std::string& list) {
  std::vector<std::pair<int, double>> runs;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto eq = item.find('=');
    runs.push_back({std::stoi(item.substr(0, eq)), std::stod(item.substr(eq + 1))});
  }
  return runs;
}

double ModelWall(const StudyCosts& costs, ClusterSetup setup, int np) {
  setup.worker_ranks = np - 1;
  return SimulateRun(costs, setup).wall_s;
}

// The task overhead that makes the model's wall time that of the first run (bisection: the
// wall time grows with it), then the model against every run.
void Check(Flags& f, const StudyCosts& costs) {
  const auto runs = Measured(f.check);
  const auto [np0, wall0] = runs.front();
  double low = 0.0, high = 0.1;
  for (int i = 0; i < 60; ++i) {
    f.setup.task_overhead_s = 0.5 * (low + high);
    (ModelWall(costs, f.setup, np0) < wall0 ? low : high) = f.setup.task_overhead_s;
  }
  fmt::print("task overhead fitted on -np {}: {:.0f} us per task\n", np0,
             1e6 * f.setup.task_overhead_s);
  fmt::print("{:>4} {:>12} {:>12} {:>15}\n", "-np", "measured s", "model s", "model/measured");
  for (const auto& [np, measured] : runs) {
    const double model = ModelWall(costs, f.setup, np);
    fmt::print("{:>4} {:>12.3f} {:>12.3f} {:>15.3f}\n", np, measured, model, model / measured);
  }
}

void Predict(const Flags& f, const MeasuredCosts& m) {
  fmt::print("{:>7} {:>7} {:>10} {:>10} {:>8} {:>8} {:>12}\n", "ranks", "copies", "tasks", "wall s",
             "E", "rank 0", "sent MB");
  for (const int ranks : f.ranks) {
    const std::size_t copies =
        f.tasks_per_rank == 0
            ? 1
            : std::max<std::size_t>(
                  1, (f.tasks_per_rank * ranks + m.costs.tasks.size() - 1) / m.costs.tasks.size());
    const StudyCosts costs = Repeated(m, copies);
    ClusterSetup setup = f.setup;
    setup.worker_ranks = ranks;
    const SimulatedRun run = SimulateRun(costs, setup);
    fmt::print("{:>7} {:>7} {:>10} {:>10.3f} {:>7.1f}% {:>7.1f}% {:>12.1f}\n", ranks, copies,
               costs.tasks.size(), run.wall_s, 100.0 * run.efficiency,
               100.0 * run.rank0_busy_s / run.wall_s, run.bytes_sent / 1e6);
  }
}

}  // namespace
}  // namespace shockmap

int main(int argc, char** argv) {
  using namespace shockmap;
  Flags f;
  CLI::App app{"The cluster model: a study's measured task costs, simulated as an MPI job"};
  app.add_option("study", f.study, "the study file to measure");
  app.add_option("--costs", f.costs_in, "costs measured before (--costs-out), instead of a study");
  app.add_option("--costs-out", f.costs_out, "where to write the measured costs (JSON)");
  app.add_option("--measure-points", f.measure_points,
                 "measure only the first N points; the others repeat their costs (0: all)");
  app.add_option("--ranks", f.ranks, "worker rank counts to predict")->delimiter(',');
  app.add_option("--tasks-per-rank", f.tasks_per_rank,
                 "repeat the study until each worker rank has at least this many tasks");
  app.add_option("--cores", f.setup.cores, "cores shared by every rank (0: one each)");
  app.add_option("--bandwidth", f.setup.bandwidth_bytes_per_s, "bytes/s of rank 0's link");
  app.add_option("--latency", f.setup.latency_s, "s per message");
  f.setup.sleep_overshoot_s = -1.0;
  app.add_option("--sleep-overshoot", f.setup.sleep_overshoot_s,
                 "s a sleep lasts beyond what it asks (default: measured here)");
  app.add_option("--check", f.check,
                 "NP=SECONDS,...: point phases of real `mpirun -np NP` runs, in increasing NP; the "
                 "task overhead is fitted on the first");
  app.add_option("--task-overhead", f.setup.task_overhead_s, "s per task on a worker rank");
  CLI11_PARSE(app, argc, argv);
  if (f.study.empty() == f.costs_in.empty()) {
    fmt::print(stderr, "cluster_model: give a study file or --costs, not both\n");
    return 2;
  }
  const MeasuredCosts m = Costs(f);
  PrintCosts(m);
  if (f.setup.sleep_overshoot_s < 0.0) f.setup.sleep_overshoot_s = SleepOvershootS();
  fmt::print("sleeps last {:.1f} us longer than asked\n", 1e6 * f.setup.sleep_overshoot_s);
  if (!f.check.empty()) Check(f, m.costs);
  Predict(f, m);
  return 0;
}

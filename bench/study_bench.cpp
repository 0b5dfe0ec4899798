// Cost of a canonical study and of one of its points (docs/performance.md, "References and
// study points").
//   StudyGrid        studies/perf_grid.json (8 R_k from 1 to 1e6 by 5 R_ftrunc from 10 to 1000,
//                    dt = 5e-6 s, 100 elements, 0.06 s, references at max(2000, 30 sqrt(R_k)) f1)
//                    run in-process with one worker into a fresh database, as
//                    `shockmap study run --jobs 1` does (CPU: of the whole process, the worker
//                    thread included)
//   StudyPoint/R_k   one point of that grid's settings at R_ftrunc = 300 scored against its
//                    reference (computed once, outside the timing), the worker's modal basis
//                    already cached; R_k = 3000 is the goal row

#include <benchmark/benchmark.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/canonical_study.h"
#include "engine/study_run.h"

namespace shockmap {
namespace {

std::string Source(const std::string& relative) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
}

void RemoveDatabase(const std::filesystem::path& path) {
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
}

void StudyGrid(benchmark::State& state) {
  const StudyFile study = ReadStudyFile(Source("studies/perf_grid.json"));
  const auto path = std::filesystem::temp_directory_path() / "shockmap_study_bench.db";
  StudyRunOptions options;
  options.database_path = path.string();
  options.jobs = 1;
  options.progress = false;
  std::size_t points = 0;
  for (auto _ : state) {
    state.PauseTiming();
    RemoveDatabase(path);
    state.ResumeTiming();
    points = RunStudy(study, options).points_computed;
  }
  RemoveDatabase(path);
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(StudyGrid)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

// The grid's settings at one (R_k, R_ftrunc = 300).
StudySpec PointSpec(double r_k) {
  const nlohmann::json json = {
      {"kind", "canonical"},
      {"name", "study_bench_point"},
      {"scoring",
       {{"window_s", 0.06}, {"reference", {{"r_fref_min", 2000}, {"r_fref_per_sqrt_rk", 30}}}}},
      {"grids",
       {{{"rk", r_k}, {"rftrunc", 300}, {"n_elements", 100}, {"dt", {{"seconds", 5e-6}}}}}}};
  return std::get<StudySpec>(ParseStudyFile(json, "study_bench_point"));
}

void ScorePoint(benchmark::State& state) {
  const CanonicalStudy study(PointSpec(static_cast<double>(state.range(0))));
  const StudyPoint& point = study.Points().at(0);
  const CanonicalStudy::Reference reference = study.ComputeReference(point);
  study.Score(point, reference, 1);  // Fills this thread's basis cache.
  CanonicalStudy::Outcome outcome;
  for (auto _ : state) {
    outcome = study.Score(point, reference, 1);
    benchmark::DoNotOptimize(outcome.score);
  }
  if (!outcome.score) {
    state.SkipWithError(outcome.message.c_str());
    return;
  }
  state.counters["modes"] = outcome.score->n_modes;
  state.counters["steps"] = static_cast<double>(outcome.score->steps);
  state.counters["integration_s"] = outcome.score->wall_s;
}
BENCHMARK(ScorePoint)
    ->Name("StudyPoint")
    ->ArgName("rk")
    ->Arg(1)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(3000)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace shockmap

BENCHMARK_MAIN();

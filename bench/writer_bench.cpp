// The one writer's throughput (Google Benchmark): what rank 0 of an MPI job (or the calling
// thread of a local run) does per finished point, with synthetic results and no physics:
// decode the outcome's bytes as they arrive from a worker rank, then store it through
// StoreOutcomes in groups of the argument's size, one transaction each (the engine's groups
// hold up to kMaxGroup points when results arrive faster than kGroupLatencyS; 1 is a point
// arriving alone), over a study of the second argument's count of points stored over and over
// (with 2000 a page changes several times between two checkpoints; with 40 000 a point is
// stored about once between two, as in a study).
//   Writer/Canonical/N/P a scored point of studies/quick.json (a typical shocks_json)
//   Writer/Scene/N/P     a scored point of studies/bundle_row_truncation.json
// items_per_second is results stored per wall-clock second (the CPU column: per second of
// the writer's own time, what it reaches on a core of its own); bytes_per_result is the
// outcome's message; longest_store_ms the longest group's transaction (one that checkpoints).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "engine/canonical_study.h"
#include "engine/scene_study.h"
#include "engine/study_engine.h"

namespace shockmap {
namespace {

std::string Source(const std::string& relative) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
}

CanonicalStudy::Reference SyntheticReference(const CanonicalStudy&) {
  ReferenceRun run;
  run.tip_m = run.force_n = {0.0, 1e-5, {0.0}};
  return {"bench-reference", 1000.0, 0.1, std::make_shared<const ReferenceRun>(std::move(run))};
}

SceneStudy::Reference SyntheticReference(const SceneStudy&) {
  SceneStudy::Reference r;
  r.reference_key = "bench-reference";
  r.status = "ok";
  r.displacement_m = r.force_n = {0.0};
  return r;
}

CanonicalStudy::Outcome SyntheticOutcome(const CanonicalStudy&, std::int64_t reference_id) {
  ScoreRow s;
  s.reference_id = reference_id;
  s.err = 0.0123;
  s.srf = 0.987;
  s.n_modes = 12;
  s.n_elements = 40;
  s.n_dofs = 80;
  s.dt_requested_s = s.dt_used_s = 1e-6;
  s.steps = 30000;
  s.n_shocks = 3;
  s.first_shock_start_s = 0.001;
  s.first_shock_impulse_n_s = 0.02;
  s.first_shock_peak_n = 150.0;
  s.first_shock_duration_s = 1e-4;
  s.first_shock_rebounds = 2;
  s.shocks_json = std::string(
      R"([{"start_s":0.00123,"end_s":0.00145,"peak_force_n":153.2,"peak_time_s":0.00131,)"
      R"("impulse_n_s":0.0213,"rebounds":2,"truncated":false}])");
  return {RunStatus::kOk, "", s};
}

SceneStudy::Outcome SyntheticOutcome(const SceneStudy&, std::int64_t reference_id) {
  SceneScoreRow s;
  s.reference_id = reference_id;
  s.err = 0.02;
  s.srf = 1.01;
  s.coordinates = 60;
  s.zones = 8;
  s.steps = 200000;
  s.largest_force_n = 420.0;
  s.largest_force_zone = "pin_3";
  s.n_shocks = 5;
  s.first_shock_peak_n = 400.0;
  s.first_shock_impulse_n_s = 0.03;
  return {RunStatus::kOk, "", s};
}

template <typename Kind>
void Writer(benchmark::State& state, const Kind& kind) {
  const auto path = std::filesystem::temp_directory_path() / "shockmap_writer_bench.db";
  std::filesystem::remove(path);
  StudyDatabase db(path.string());
  const auto n_points = static_cast<std::int64_t>(state.range(1));
  std::vector<NewPoint> rows;
  for (std::int64_t i = 0; i < n_points; ++i) {
    NewPoint p = kind.Describe(kind.Points()[i % kind.Points().size()]);
    p.point_key += '#';
    p.point_key += std::to_string(i);
    rows.push_back(std::move(p));
  }
  const std::int64_t run =
      db.RegisterRun({kind.Header().name, kind.Header().spec_json, kind.Table(), rows,
                      Provenance{"bench", "", "", "bench", 1, 1}})
          .run_id;
  const std::int64_t reference = kind.StoreReference(db, SyntheticReference(kind), run);
  ByteWriter out;
  EncodeOutcome(kind, SyntheticOutcome(kind, reference), out);
  const std::string bytes = out.Take();
  const PointOrigin origin{"worker-host", 1};
  const auto group_size = static_cast<std::size_t>(state.range(0));
  std::vector<FinishedPoint<Kind>> group;
  std::int64_t i = 0;
  double longest_store_s = 0.0;
  for (auto _ : state) {
    ByteReader in(bytes);
    group.push_back({1 + i++ % n_points, origin, DecodeOutcome(kind, in)});
    if (group.size() == group_size) {
      const auto start = std::chrono::steady_clock::now();
      StoreOutcomes<Kind>(kind, db, run, group);
      longest_store_s =
          std::max(longest_store_s,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      group.clear();
    }
  }
  if (!group.empty()) StoreOutcomes<Kind>(kind, db, run, group);
  state.SetItemsProcessed(state.iterations());
  state.counters["bytes_per_result"] = static_cast<double>(bytes.size());
  state.counters["longest_store_ms"] = 1e3 * longest_store_s;
  db.EndRun(run, RunEnd::kCompleted);
  std::filesystem::remove(path);
  std::filesystem::remove(path.string() + "-wal");
  std::filesystem::remove(path.string() + "-shm");
}

void Canonical(benchmark::State& state) {
  Writer(state, CanonicalStudy(std::get<StudySpec>(ReadStudyFile(Source("studies/quick.json")))));
}
void Scene(benchmark::State& state) {
  Writer(state, SceneStudy(std::get<SceneStudySpec>(
                    ReadStudyFile(Source("studies/bundle_row_truncation.json")))));
}

BENCHMARK(Canonical)
    ->Name("Writer/Canonical")
    ->Args({1, 2000})
    ->Args({kMaxGroup, 2000})
    ->Args({kMaxGroup, 40000})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(Scene)
    ->Name("Writer/Scene")
    ->Args({1, 2000})
    ->Args({kMaxGroup, 2000})
    ->Args({kMaxGroup, 40000})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
}  // namespace shockmap

BENCHMARK_MAIN();

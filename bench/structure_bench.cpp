// Cost of a structure from an FE code (docs/structures.md, docs/performance.md): a clamped block
// of 20-node bricks (tests/brick_block_deck.h) of about 10 000 and 100 000 free DOFs, run
// side by side with CalculiX on the same deck, one iteration each (each takes seconds to
// minutes). Run one benchmark per process (--benchmark_filter) for its peak memory.
//   StructureImport/size       `structure import`'s path: ccx's matrix storage run on the deck,
//                              then its .sti .mas .dof read and checked (mass factorized)
//   StructureModes/size/count  the `count` lowest modes of the imported structure (its import
//                              not timed)
//   CalculixFrequency/size/count  ccx's own *FREQUENCY for `count` modes on the same deck, as a
//                              child process (one solver thread: OMP_NUM_THREADS=1)
// size 0 is the 10 000-DOF block (9 504 free DOFs), 1 the 100 000-DOF one (98 640). Counters:
// dofs, peak_rss_mb (this process's peak resident memory so far), child_peak_rss_mb (the largest
// ccx run's), child_cpu_s (ccx's CPU time: on a shared machine the wall time is not the cost).

#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "core/structure_modes.h"
#include "formats/calculix_job.h"
#include "tests/brick_block_deck.h"

namespace shockmap {
namespace {

testing::BrickBlock Block(int size) {
  testing::BrickBlock block;
  if (size == 0) {
    block.nx = 24, block.ny = 5, block.nz = 5;
    block.lx = 1.2, block.ly = 0.25, block.lz = 0.25;
  } else {
    block.nx = 60, block.ny = 12, block.nz = 10;
    block.lx = 1.2, block.ly = 0.24, block.lz = 0.2;
  }
  return block;
}

// A scratch folder holding block.inp (the model part only) for one size, removed at exit.
struct Scratch {
  std::filesystem::path dir;
  explicit Scratch(int size) {
    dir = std::filesystem::temp_directory_path() /
          ("shockmap_structure_bench_" + std::to_string(::getpid()) + "_" + std::to_string(size));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "model.inp") << Block(size).ModelDeck();
  }
  ~Scratch() { std::filesystem::remove_all(dir); }
};

Scratch& ScratchOf(int size) {
  static std::map<int, std::unique_ptr<Scratch>> scratch;
  auto& s = scratch[size];
  if (!s) s = std::make_unique<Scratch>(size);
  return *s;
}

double CpuSeconds(int who) {
  rusage usage{};
  getrusage(who, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double PeakRssMb(int who) {
  rusage usage{};
  getrusage(who, &usage);
  return usage.ru_maxrss / 1024.0;
}

void Counters(benchmark::State& state, int dofs) {
  state.counters["dofs"] = dofs;
  state.counters["peak_rss_mb"] = PeakRssMb(RUSAGE_SELF);
  state.counters["child_peak_rss_mb"] = PeakRssMb(RUSAGE_CHILDREN);
}

bool HaveCalculix(benchmark::State& state) {
  if (FindCalculixExecutable()) return true;
  state.SkipWithError("CalculiX's ccx is not installed (apt-get install calculix-ccx)");
  return false;
}

void StructureImport(benchmark::State& state) {
  if (!HaveCalculix(state)) return;
  const Scratch& scratch = ScratchOf(static_cast<int>(state.range(0)));
  int dofs = 0;
  const double child_cpu = CpuSeconds(RUSAGE_CHILDREN);
  for (auto _ : state) {
    const FeStructure s = ImportCalculixDeck(scratch.dir / "model.inp");
    dofs = s.Size();
  }
  state.counters["child_cpu_s"] = CpuSeconds(RUSAGE_CHILDREN) - child_cpu;
  Counters(state, dofs);
}

void StructureModes(benchmark::State& state) {
  if (!HaveCalculix(state)) return;
  const Scratch& scratch = ScratchOf(static_cast<int>(state.range(0)));
  const FeStructure s = ImportCalculixDeck(scratch.dir / "model.inp");
  const int count = static_cast<int>(state.range(1));
  double f_highest = 0.0;
  for (auto _ : state) {
    const ModalBasis modes = LowestStructureModes(s, count);
    f_highest = modes.HighestFrequencyHz();
  }
  state.counters["f_highest_hz"] = f_highest;
  Counters(state, s.Size());
}

void CalculixFrequency(benchmark::State& state) {
  if (!HaveCalculix(state)) return;
  const Scratch& scratch = ScratchOf(static_cast<int>(state.range(0)));
  const int count = static_cast<int>(state.range(1));
  std::ifstream model(scratch.dir / "model.inp");
  std::ofstream(scratch.dir / "frequency.inp") << model.rdbuf() << "*STEP\n*FREQUENCY\n"
                                               << count << "\n*END STEP\n";
  const auto ccx = FindCalculixExecutable();
  const double child_cpu = CpuSeconds(RUSAGE_CHILDREN);
  for (auto _ : state) {
    const int status = RunCalculixJob(*ccx, scratch.dir, "frequency");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      state.SkipWithError("ccx failed: see frequency.log");
      return;
    }
  }
  state.counters["child_cpu_s"] = CpuSeconds(RUSAGE_CHILDREN) - child_cpu;
  Counters(state, Block(static_cast<int>(state.range(0))).FreeDofs());
}

BENCHMARK(StructureImport)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(StructureModes)
    ->Args({0, 200})
    ->Args({1, 200})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();
BENCHMARK(CalculixFrequency)
    ->Args({0, 200})
    ->Args({1, 200})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace shockmap

int main(int argc, char** argv) {
  // ccx's solvers on one thread, as shockmap's.
  setenv("OMP_NUM_THREADS", "1", 1);
  setenv("CCX_NPROC_EQUATION_SOLVER", "1", 1);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

#pragma once
// The exit codes of `shockmap`, one table for every command (README "Exit codes").

namespace shockmap {

// The command did what was asked; a numerical divergence is a result, so it exits 0 too.
inline constexpr int kExitSuccess = 0;
// An internal failure, gnuplot missing or failing, a worker rank's error or silence under MPI
// (docs/cluster.md, "Faults"), or a verdict against the user's expectation (`criteria check`:
// the study contradicts its baseline).
inline constexpr int kExitFailure = 1;
// Bad input the user can fix: a flag, file, key or database, or an output that could not be
// written (standard output included). Nothing stored is changed.
inline constexpr int kExitBadInput = 2;
// A study run stopped by signal N (SIGINT, SIGTERM, SIGHUP) exits 128 + N, as a shell reports it.
inline constexpr int kExitSignalBase = 128;

}  // namespace shockmap

#pragma once
// Runs CalculiX (ccx) on an input deck as a child process, without a shell, for the tests and
// benchmarks that check shockmap against it as an independent FE code.

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

namespace shockmap::testing {

// The ccx executable: $SHOCKMAP_CCX when set (an absolute path), else the first `ccx` on the
// PATH that is an executable file; nullopt when there is none.
std::optional<std::filesystem::path> FindCalculix();

// The message of a test skipped because FindCalculix found nothing.
std::string CalculixMissingMessage();

struct CalculixRun {
  enum class Status {
    kCompleted,    // ccx exited 0 and its log holds no "*ERROR".
    kNotFound,     // No ccx (see FindCalculix).
    kCannotStart,  // The log file or the child process could not be made.
    kFailed,       // ccx exited non-zero, or exited 0 after printing "*ERROR".
    kTimedOut,     // Still running after the time limit: killed.
    kKilled,       // Ended by a signal it did not get from us.
  };
  Status status = Status::kNotFound;
  int exit_code = -1;         // ccx's exit code when it exited, else -1.
  std::filesystem::path log;  // jobname.log beside the deck: ccx's stdout and stderr.
  std::string log_text;       // The log's last 4 kB.
  double wall_seconds = 0.0;

  bool Completed() const { return status == Status::kCompleted; }
  // For a failure message: the job, the status, the exit code, the log from its first "*ERROR"
  // (else its last lines).
  std::string Describe() const;
};

struct CalculixOptions {
  // Solver threads (OMP_NUM_THREADS, CCX_NPROC_EQUATION_SOLVER): 1 keeps a test off the other
  // core of a shared machine.
  int threads = 1;
  std::chrono::seconds time_limit{600};
};

// Runs `ccx -i jobname` in `directory` (which holds jobname.inp), stdin from /dev/null, stdout
// and stderr into directory/jobname.log; waits for it (killing it past the time limit, or when
// this process dies) and reports how it ended. Never throws for ccx's own failures.
CalculixRun RunCalculix(const std::filesystem::path& directory, const std::string& jobname,
                        const CalculixOptions& options = {});

}  // namespace shockmap::testing

#pragma once
// What a signal must not leave behind: the temporary files of this process (an output being
// written, an image being drawn) and the child drawing one. Once the handlers are installed, a
// SIGINT, SIGTERM or SIGHUP kills and reaps the registered children, removes the registered
// files, then ends the process by the same signal (its default action).

#include <sys/types.h>

#include <filesystem>

namespace shockmap {

// Installs `handler` for `signal` unless the signal is ignored: one the process inherited
// ignored (SIGHUP under nohup) stays ignored, as its parent asked.
void HandleUnlessIgnored(int signal, void (*handler)(int));

// Installs the handlers of SIGINT, SIGTERM and SIGHUP, each unless it is ignored, and ignores
// SIGXFSZ: a write past the file-size limit (ulimit -f) then fails with EFBIG ("File too
// large"), which the writer reports with its path and cleans up after, instead of the signal
// ending the process silently with its temporary files left. The CLI calls it before any
// command; a study run replaces them with its own (engine/stop_request.h), which
// let the run stop cleanly.
void InstallSignalCleanup();

// While alive, `path` is removed when a signal ends the process; destroyed, it forgets the path
// (it never removes the file itself). At most 64 files and 64 children are registered at once;
// past that a registration is a no-op.
class RemovedOnSignal {
 public:
  explicit RemovedOnSignal(const std::filesystem::path& path);
  ~RemovedOnSignal();
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

 private:
  int slot_;
};

// While alive, the child `pid` is killed (SIGKILL) and reaped when a signal ends the process,
// before the files are removed, so that it cannot write them again.
class KilledOnSignal {
 public:
  explicit KilledOnSignal(pid_t pid);
  ~KilledOnSignal();
  KilledOnSignal(const KilledOnSignal&) = delete;
  KilledOnSignal& operator=(const KilledOnSignal&) = delete;

 private:
  int slot_;
};

}  // namespace shockmap

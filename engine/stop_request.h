#pragma once
// A study run asked to stop by SIGINT, SIGTERM or SIGHUP: no new point starts, the points in
// flight are finished and stored, and the run ends with its row closed. A second signal ends
// the process at once (the default action); the next run then takes over its points.

namespace shockmap {

// Installs the handlers (idempotent), each unless its signal is ignored: a run started under
// nohup goes on through SIGHUP. The CLI calls it before a study run.
void InstallStopHandlers();

// For a process that runs several studies and keeps its own handlers between them (the Python
// module): while at least one of these lives, the stop handlers are installed; the first to
// live forgets the signal that stopped an earlier run, the last to die puts the handlers it
// found back. Safe to hold from several threads at once.
class StopHandlersDuringRun {
 public:
  StopHandlersDuringRun();
  ~StopHandlersDuringRun();
  StopHandlersDuringRun(const StopHandlersDuringRun&) = delete;
  StopHandlersDuringRun& operator=(const StopHandlersDuringRun&) = delete;
};

// The signal that asked to stop, or 0.
int StopSignal();

// "SIGTERM", "SIGINT", "SIGHUP" or "signal N".
const char* SignalName(int signal);

}  // namespace shockmap

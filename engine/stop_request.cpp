#include "engine/stop_request.h"

#include <csignal>
#include <string>

#include "formats/signal_cleanup.h"

namespace shockmap {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void OnStopSignal(int signal) {
  g_stop_signal = signal;
  std::signal(signal, SIG_DFL);  // A second signal ends the process.
}

}  // namespace

void InstallStopHandlers() {
  for (int s : {SIGINT, SIGTERM, SIGHUP}) HandleUnlessIgnored(s, OnStopSignal);
}

int StopSignal() { return g_stop_signal; }

const char* SignalName(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

}  // namespace shockmap

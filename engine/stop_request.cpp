#include "engine/stop_request.h"

#include <signal.h>

#include <array>
#include <csignal>
#include <mutex>
#include <string>

#include "formats/signal_cleanup.h"

namespace shockmap {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void OnStopSignal(int signal) {
  g_stop_signal = signal;
  std::signal(signal, SIG_DFL);  // A second signal ends the process.
}

constexpr std::array kStopSignals{SIGINT, SIGTERM, SIGHUP};

// The handlers StopHandlersDuringRun found, and how many of them live.
std::mutex g_scoped_mutex;
int g_scoped_count = 0;
std::array<struct sigaction, kStopSignals.size()> g_found_handlers;

}  // namespace

void InstallStopHandlers() {
  for (int s : kStopSignals) HandleUnlessIgnored(s, OnStopSignal);
}

StopHandlersDuringRun::StopHandlersDuringRun() {
  const std::lock_guard lock(g_scoped_mutex);
  if (g_scoped_count++ > 0) return;
  for (std::size_t i = 0; i < kStopSignals.size(); ++i) {
    sigaction(kStopSignals[i], nullptr, &g_found_handlers[i]);
  }
  g_stop_signal = 0;
  InstallStopHandlers();
}

StopHandlersDuringRun::~StopHandlersDuringRun() {
  const std::lock_guard lock(g_scoped_mutex);
  if (--g_scoped_count > 0) return;
  for (std::size_t i = 0; i < kStopSignals.size(); ++i) {
    sigaction(kStopSignals[i], &g_found_handlers[i], nullptr);
  }
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

#include "formats/signal_cleanup.h"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>

namespace shockmap {
namespace {

constexpr int kSlots = 64;
constexpr int kNoSlot = -1;

// A file slot is claimed (kClaimed) while its path is copied in, then published (kFilled);
// the handler reads only published slots, with nothing but async-signal-safe calls.
enum SlotState : int { kFree, kClaimed, kFilled };

struct FileSlot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX] = {};
};

std::array<FileSlot, kSlots> g_files;
std::array<std::atomic<pid_t>, kSlots> g_children{};

extern "C" void CleanUpAndDie(int signal) {
  for (auto& child : g_children) {
    const pid_t pid = child.load();
    if (pid <= 0) continue;
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  for (FileSlot& file : g_files) {
    if (file.state.load() == kFilled) ::unlink(file.path);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

int ClaimFileSlot(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() >= PATH_MAX) return kNoSlot;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (g_files[i].state.compare_exchange_strong(expected, kClaimed)) {
      std::memcpy(g_files[i].path, text.c_str(), text.size() + 1);
      g_files[i].state.store(kFilled);
      return i;
    }
  }
  return kNoSlot;
}

int ClaimChildSlot(pid_t pid) {
  for (int i = 0; i < kSlots; ++i) {
    pid_t expected = 0;
    if (g_children[i].compare_exchange_strong(expected, pid)) return i;
  }
  return kNoSlot;
}

}  // namespace

void HandleUnlessIgnored(int signal, void (*handler)(int)) {
  struct sigaction current = {};
  if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) return;
  std::signal(signal, handler);
}

void InstallSignalCleanup() {
  for (int s : {SIGINT, SIGTERM, SIGHUP}) HandleUnlessIgnored(s, CleanUpAndDie);
  std::signal(SIGXFSZ, SIG_IGN);
}

RemovedOnSignal::RemovedOnSignal(const std::filesystem::path& path) : slot_(ClaimFileSlot(path)) {}

RemovedOnSignal::~RemovedOnSignal() {
  if (slot_ != kNoSlot) g_files[slot_].state.store(kFree);
}

KilledOnSignal::KilledOnSignal(pid_t pid) : slot_(ClaimChildSlot(pid)) {}

KilledOnSignal::~KilledOnSignal() {
  if (slot_ != kNoSlot) g_children[slot_].store(0);
}

}  // namespace shockmap

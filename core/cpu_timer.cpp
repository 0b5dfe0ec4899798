#include "core/cpu_timer.h"

#include <chrono>
#include <ctime>

namespace shockmap {
namespace {

double WallNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double CpuNow() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

CpuTimer::CpuTimer() : wall_start_(WallNow()), cpu_start_(CpuNow()) {}
double CpuTimer::WallSeconds() const { return WallNow() - wall_start_; }
double CpuTimer::CpuSeconds() const { return CpuNow() - cpu_start_; }

}  // namespace shockmap

#pragma once
// Wall and CPU time of a piece of work, measured on the calling thread.

namespace shockmap {

class CpuTimer {
 public:
  CpuTimer();
  double WallSeconds() const;
  // CPU time of this thread only, so parallel workers each measure their own work.
  double CpuSeconds() const;

 private:
  double wall_start_;
  double cpu_start_;
};

}  // namespace shockmap

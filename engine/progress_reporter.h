#pragma once
// Progress of a study on stderr: a live bar on a terminal, periodic plain lines otherwise.

#include <chrono>
#include <cstdio>

namespace shockmap {

class ProgressReporter {
 public:
  // `total` points to compute; writes to `out` (stderr in the CLI), nothing when `enabled` is
  // false.
  ProgressReporter(long total, std::FILE* out, bool enabled);
  void Update(long done, long diverged, long failed);
  void Finish(long done, long diverged, long failed);

 private:
  void Print(long done, long diverged, long failed, bool final_line);

  long total_;
  std::FILE* out_;
  bool enabled_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
};

}  // namespace shockmap

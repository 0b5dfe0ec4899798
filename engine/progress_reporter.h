#pragma once
// Progress of one phase of work on stderr: a live bar on a terminal, a plain line every few
// seconds otherwise (logs, CI, an MPI launcher's output). One reporter per phase: the study
// engine opens one for references and one for points (so every study kind gets both), and
// `simulate` one for the simulated time of a transient run.

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace shockmap {

// A caller following a phase in its own way (the Python module's callback): the phase's name,
// the work done and the total, at most every 0.1 s and once at the phase's end.
using ProgressListener = std::function<void(std::string_view phase, double done, double total)>;

class ProgressReporter {
 public:
  // `phase` names the work ("references", "points", "simulate bundle_hex"), `unit` follows the
  // numbers ("done" where the phase names what is counted, "s simulated"); writes to `out`, nothing
  // when `enabled` is false or total <= 0; `listener`, when given, is told too.
  ProgressReporter(std::string phase, std::string unit, double total, std::FILE* out, bool enabled,
                   ProgressListener listener = {});
  // `detail` follows the numbers ("diverged 3, failed 0"). Prints at most every 0.1 s on a
  // terminal and every 5 s otherwise, so a caller may call it after every item.
  void Update(double done, std::string_view detail = {});
  // The phase's last line, always printed when enabled.
  void Finish(double done, std::string_view detail = {});
  // The ETA is the rate since the estimate's start: the first update with work done (the wait
  // for the first item is no rate), or the last StartEstimate. Until an item more is done and
  // kEstimateAfter_s has passed since that start, and while held, the line says
  // "ETA estimating". Hold it while the phase waits on another (the points on their
  // references), and start it again, with the work done then, when the wait is over.
  void HoldEstimate();
  void StartEstimate(double done);

  static constexpr double kEstimateAfter_s = 1.0;

 private:
  void Report(double done, std::string_view detail, bool final_line);
  void Print(double done, std::string_view detail, bool final_line);
  // "ETA 3 min 20 s", or "ETA estimating" (see HoldEstimate).
  std::string Eta(double done, std::chrono::steady_clock::time_point now) const;

  std::string phase_;
  std::string unit_;
  double total_;
  std::FILE* out_;
  bool enabled_;
  bool terminal_;
  ProgressListener listener_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  bool estimate_held_ = false;
  bool estimate_started_ = false;
  std::chrono::steady_clock::time_point estimate_start_;
  double estimate_start_done_ = 0.0;
};

// "12 s", "3 min 20 s", "1 h 05 min": a duration for a progress line.
std::string FormatDuration(double seconds);

}  // namespace shockmap

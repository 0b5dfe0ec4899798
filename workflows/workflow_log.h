#pragma once
// What a workflow tells its caller as it goes: the command line prints it, Python passes it to
// the user's callable or drops it. Each part may be empty (then nothing is told).

#include <functional>
#include <string>

#include "engine/progress_reporter.h"

namespace shockmap {

struct WorkflowLog {
  std::function<void(const std::string& line)> say;   // A line of what is done.
  std::function<void(const std::string& line)> warn;  // What was left out, and why.
  ProgressListener progress;                          // (phase, done, total) of a long step.

  void Say(const std::string& line) const {
    if (say) say(line);
  }
  void Warn(const std::string& line) const {
    if (warn) warn(line);
  }
  void Progress(std::string_view phase, double done, double total) const {
    if (progress) progress(phase, done, total);
  }
};

}  // namespace shockmap

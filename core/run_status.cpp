#include "core/run_status.h"

namespace shockmap {

std::string ToString(RunStatus s) {
  switch (s) {
    case RunStatus::kOk:
      return "ok";
    case RunStatus::kDiverged:
      return "diverged";
    case RunStatus::kFailed:
      return "failed";
  }
  return "unknown";
}

std::optional<RunStatus> RunStatusFromString(std::string_view s) {
  for (auto r : {RunStatus::kOk, RunStatus::kDiverged, RunStatus::kFailed}) {
    if (ToString(r) == s) return r;
  }
  return std::nullopt;
}

}  // namespace shockmap

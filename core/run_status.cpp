#include "core/run_status.h"

namespace shockmap {

std::string ToString(RunStatus s) {
  switch (s) {
    case RunStatus::kOk:
      return "ok";
    case RunStatus::kDiverged:
      return "diverged";
    case RunStatus::kUnstable:
      return "unstable";
    case RunStatus::kFailed:
      return "failed";
    case RunStatus::kReferenceUnconverged:
      return "reference_unconverged";
  }
  return "unknown";
}

std::optional<RunStatus> RunStatusFromString(std::string_view s) {
  for (auto r : kAllRunStatuses) {
    if (ToString(r) == s) return r;
  }
  return std::nullopt;
}

}  // namespace shockmap

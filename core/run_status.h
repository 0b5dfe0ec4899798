#pragma once
// Outcome of a numerical run. Numerical failure is a status, not an exception.

#include <optional>
#include <string>
#include <string_view>

namespace shockmap {

enum class RunStatus {
  kOk,        // Reached the end time.
  kDiverged,  // Non-finite state or energy past the growth limit: the numbers mean nothing.
  kFailed,    // A solve failed (singular matrix, contact iteration not converged).
};

std::string ToString(RunStatus s);
std::optional<RunStatus> RunStatusFromString(std::string_view s);

}  // namespace shockmap

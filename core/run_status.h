#pragma once
// Outcome of a numerical run, or of a point scored against the reference. Numerical failure is
// a status, not an exception.

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace shockmap {

enum class RunStatus {
  kOk,        // Reached the end time.
  kDiverged,  // Non-finite state or energy past the growth limit: the numbers mean nothing.
  kFailed,    // A solve failed (singular matrix, contact iteration not converged).
  // The run reached its end, but the reference's two truncations disagree beyond the tolerance:
  // nothing is scored (a comparison's outcome, never a transient run's).
  kReferenceUnconverged,
};

inline constexpr std::array kAllRunStatuses = {
    RunStatus::kOk, RunStatus::kDiverged, RunStatus::kFailed, RunStatus::kReferenceUnconverged};

// The text stored in the database and JSON: "ok", "diverged", "failed",
// "reference_unconverged".
std::string ToString(RunStatus s);
// The inverse of ToString; nullopt for any other text (the caller names the bad field), as the
// other enumerations' FromString do.
std::optional<RunStatus> RunStatusFromString(std::string_view s);

}  // namespace shockmap

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
  // Reached the end time undamped, but its energy grew past kUnstableEnergyRatio
  // (docs/physics.md §3.1): a run past its stability bound that had not yet blown up. Its
  // scores are stored and it fails the criteria by its status.
  kUnstable,
  kFailed,  // A solve failed (singular matrix, contact iteration not converged).
  // The run reached its end, but the reference's two truncations disagree beyond the tolerance:
  // nothing is scored (a comparison's outcome, never a transient run's).
  kReferenceUnconverged,
};

inline constexpr std::array kAllRunStatuses = {RunStatus::kOk, RunStatus::kDiverged,
                                               RunStatus::kUnstable, RunStatus::kFailed,
                                               RunStatus::kReferenceUnconverged};

// The energy-growth limit of an undamped run that reached its end: max over the run of
// (E + dissipated) / (E0 + load work) above it is `unstable`. Measured on the quick study
// (docs/physics.md §3.1): runs below the sharp bound stay at or below 3.4, runs beyond it that
// reach the end of the window have grown 6-fold or more.
inline constexpr double kUnstableEnergyRatio = 5.0;

// The text stored in the database and JSON: "ok", "diverged", "unstable", "failed",
// "reference_unconverged".
std::string ToString(RunStatus s);
// The inverse of ToString; nullopt for any other text (the caller names the bad field), as the
// other enumerations' FromString do.
std::optional<RunStatus> RunStatusFromString(std::string_view s);

}  // namespace shockmap

#pragma once
// How far a truncated reference is from its limit (docs/physics.md §2): it is judged against
// finer truncations, never a coarser one alone, on what it is used for.

#include <optional>

namespace shockmap {

// Truncations are compared three times apart.
inline constexpr double kReferenceCheckRatio = 3.0;

// The finer truncation a reference at r_fref is checked against, and the coarser one that gives
// the observed order.
double FinerTruncation(double r_fref);
double CoarserTruncation(double r_fref);  // At least 1.

struct ReferenceConvergence {
  double r_fref = 0.0;        // The reference scored against.
  double r_fref_check = 0.0;  // The finer truncation it was checked against (3 r_fref).
  // The estimate compared with the tolerance (scoring.reference.tolerance): the largest of the
  // three errors below.
  double difference = 0.0;
  double wall_check_s = 0.0;  // CPU time of the truncations solved for the estimate.
  // The reference's estimated errors, each its difference from the finer truncation doubled
  // (times 3^p / (3^p - 1) when the tip's observed order p is regular but below log_3 2):
  // max_t |u_R - u_3R| / max_t |u_R| over the window; |I_R - I_3R| / I_3R of the first shock;
  // and the Err (eq. 8) of the reference's tip scored against the finer one's.
  double tip_error = 0.0;
  double impulse_error = 0.0;
  double induced_err = 0.0;
  // log_3 of d(R / 3, R) / d(R, 3R) on the tip, when the coarser truncation was solved.
  std::optional<double> order;
  // The truncation the tip's order predicts would meet the tolerance, when it is regular.
  std::optional<double> r_fref_needed;
};

}  // namespace shockmap

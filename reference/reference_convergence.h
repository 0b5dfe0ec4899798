#pragma once
// How far a truncated reference is from its limit (docs/physics.md §2): it is judged against
// finer truncations, never a coarser one alone, on what it is used for, by Roache's grid
// convergence index with the order observed over three truncations.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shockmap {

// What a reference is checked against (scoring.reference.check).
enum class ReferenceCheck {
  // kFiner (default): 3 R_fref, with R_fref / 3 and R_fref / 9 for the observed order; each
  // quantity's error is its grid convergence index (below), a bound, and R_fref is raised until
  // it meets the tolerance.
  kFiner,
  // kCoarser: R_fref / 3 alone, as a script would check it; the estimate is the difference
  // d(R / 3, R) itself, with no order and no factor of safety, and R_fref is not raised. That
  // difference measures the coarser truncation's error rather than the reference's: it is no
  // bound (docs/physics.md §2).
  kCoarser,
};

// "finer", "coarser".
std::string ToString(ReferenceCheck check);
// Inverse of ToString; std::nullopt for any other string.
std::optional<ReferenceCheck> ReferenceCheckFromString(std::string_view name);

// Truncations are compared three times apart.
inline constexpr double kReferenceCheckRatio = 3.0;

// The finer truncation a reference at r_fref is checked against, and the coarser one that gives
// the observed order.
double FinerTruncation(double r_fref);
double CoarserTruncation(double r_fref);  // At least 1.

// Roache's factors of safety: with an order observed in the asymptotic range, and without one.
// docs/fidelity.md measures the first against the difference from a reference nine times finer.
inline constexpr double kSafetyFactorObserved = 1.25;
inline constexpr double kSafetyFactorUnobserved = 3.0;
// An observed order below this is not taken as asymptotic; without an observed order the index
// assumes this one.
inline constexpr double kLowestRegularOrder = 1.0;

// One quantity of a reference at R and its grid convergence index: with d = |X_R - X_3R| and
// p the observed order, the error of X_R is at most Fs d 3^p / (3^p - 1) (Richardson's
// |X_R - X_inf| with the factor of safety Fs).
struct QuantityConvergence {
  double difference = 0.0;      // d, from the finer truncation.
  std::optional<double> order;  // p, when observed in the asymptotic range.
  double error = 0.0;           // The grid convergence index.
  // The order at which the truncations reduced the difference at best, asymptotic or not:
  // log_3(|d_first| / |d_k|) / k for the smallest |d_k| after the first (k truncations finer),
  // when it is below |d_first|; nullopt with fewer than two differences or without progress.
  // What a raise of a reference may expect (compare/reference_decision.h).
  std::optional<double> progress_order;
};

// The index from a quantity's differences X_b - X_a between successive truncations three
// apart, the coarsest pair first and (R, 3R) last: d(R / 9, R / 3), d(R / 3, R), d(R, 3R).
// The convergence is taken as asymptotic when all differences have one sign and each observed
// order log_3(d_k / d_k+1) is at least kLowestRegularOrder; the index then uses the smallest of
// them. With fewer than three differences, or otherwise, the order is not observed (Fs = 3,
// p = kLowestRegularOrder). The progress order is set from the same differences.
QuantityConvergence GridConvergenceIndex(const std::vector<double>& differences);

struct ReferenceConvergence {
  double r_fref = 0.0;        // The reference scored against.
  double r_fref_check = 0.0;  // The finer truncation it was checked against (3 r_fref).
  // The estimate compared with the tolerance (scoring.reference.tolerance): the largest error
  // of the three quantities below.
  double difference = 0.0;
  double wall_check_s = 0.0;  // CPU time of the truncations solved for the estimate.
  // max_t |u_R - u_3R| / max_t |u_R| over the window, on the reference's output grid.
  QuantityConvergence tip;
  // |I_R - I_3R| / I_3R of the first shocks' impulses (in closed form).
  QuantityConvergence impulse;
  // The Err (eq. 8) of the reference's tip scored against the finer one's.
  QuantityConvergence induced_err;
  // The truncation the deciding quantity's order predicts would meet the tolerance, when that
  // order is observed.
  std::optional<double> r_fref_needed;

  // The quantity with the largest error, which `difference` is.
  const QuantityConvergence& Deciding() const;
};

}  // namespace shockmap

#pragma once
// Time-step bounds of explicit central differences on the modal model (docs/physics.md §3, paper
// eq. 11).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/point_contact.h"

namespace shockmap {

struct StabilityBounds {
  double dt_paper_s = 0.0;  // 1 / (4 f_trunc), the paper's rule (eq. 11).
  double dt_sharp_s = 0.0;  // 2 / omega_max of the contact-stiffened modal stiffness.
  double omega_max_rad_s = 0.0;
};

// omega_max^2 is the largest eigenvalue of diag(omega^2) + sum_c k_c phi_c phi_c^T, every
// contact closed at once with k_c its law's bound stiffness (NormalLaw::BoundStiffness): the
// stiffest state the explicit scheme can meet. Contact damping is not part of the bound.
// `contacts` rows are in modal coordinates.
StabilityBounds ComputeStabilityBounds(const Eigen::VectorXd& omega_rad_s, double f_trunc_hz,
                                       const std::vector<PointContact>& contacts);

enum class DtRule { kPaper, kSharp };
std::string ToString(DtRule rule);
std::optional<DtRule> DtRuleFromString(std::string_view s);

// dt given absolutely, or as a factor of one of the bounds.
struct TimeStepRequest {
  std::optional<double> dt_s;  // Absolute; when set, factor and rule are ignored.
  // A tenth of the sharp bound: at 0.5 the time-step error dominates Err at R_ftrunc = 300,
  // R_k = 3000 (measured Err 0.074 at 0.5 against 0.022 at 0.1 over a 0.035 s window).
  double factor = 0.1;
  DtRule rule = DtRule::kSharp;

  bool IsValid(std::string* error) const;
  double Resolve(const StabilityBounds& bounds) const;
};

}  // namespace shockmap

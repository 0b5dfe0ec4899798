#include "core/stability_bounds.h"

#include <Eigen/Eigenvalues>

#include "core/validity.h"

namespace shockmap {

StabilityBounds ComputeStabilityBounds(const Eigen::VectorXd& omega_rad_s, double f_trunc_hz,
                                       const std::vector<PointContact>& contacts) {
  Eigen::MatrixXd k = omega_rad_s.array().square().matrix().asDiagonal();
  for (const auto& c : contacts) k.noalias() += c.law.BoundStiffness() * c.row * c.row.transpose();
  StabilityBounds b;
  b.dt_paper_s = 1.0 / (4.0 * f_trunc_hz);
  if (k.rows() > 0) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k, Eigen::EigenvaluesOnly);
    b.omega_max_rad_s = std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
  }
  b.dt_sharp_s =
      b.omega_max_rad_s > 0.0 ? 2.0 / b.omega_max_rad_s : std::numeric_limits<double>::infinity();
  return b;
}

std::string ToString(DtRule rule) { return rule == DtRule::kPaper ? "paper" : "sharp"; }

std::optional<DtRule> DtRuleFromString(std::string_view s) {
  for (auto r : {DtRule::kPaper, DtRule::kSharp}) {
    if (ToString(r) == s) return r;
  }
  return std::nullopt;
}

bool TimeStepRequest::IsValid(std::string* error) const {
  if (dt_s) return RequirePositive("dt_s", *dt_s, error);
  return RequirePositive("dt_factor", factor, error);
}

double TimeStepRequest::Resolve(const StabilityBounds& bounds) const {
  if (dt_s) return *dt_s;
  return factor * (rule == DtRule::kPaper ? bounds.dt_paper_s : bounds.dt_sharp_s);
}

}  // namespace shockmap

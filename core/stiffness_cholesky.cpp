#include "core/stiffness_cholesky.h"

#include <sstream>
#include <string>

#include "core/input_error.h"
#include "core/structure_factorization.h"

namespace shockmap {
namespace {

// A pivot below this share of its diagonal entry leaves a rigid motion to rounding.
constexpr double kSingularPivot = 1e-13;

// The refusal of a K that is not positive definite, naming the DOF of its weakest LDL^T pivot.
[[noreturn]] void RefuseStiffness(const FeStructure& s) {
  const auto [row, ratio] = ShiftedFactorization(s, 0.0).WeakestPivot();
  std::ostringstream message;
  message.precision(3);
  message << "structure '" << s.name << "': its stiffness is not positive definite";
  if (row >= 0) {
    message << " (the pivot of node " << s.dofs[row].node << " "
            << DofComponentName(s.dofs[row].component) << " is " << ratio << " of its diagonal)";
  }
  message << ": the supports must remove every rigid motion";
  throw InputError(message.str());
}

}  // namespace

StiffnessCholesky::StiffnessCholesky(const FeStructure& s) : mass_(&s.mass), factor_(s.stiffness) {
  if (!factor_.Succeeded()) RefuseStiffness(s);
  const Eigen::VectorXd pivots = factor_.PivotsByRow();
  if ((pivots.array().square() <= kSingularPivot * s.stiffness.diagonal().array().abs()).any()) {
    RefuseStiffness(s);
  }
}

Eigen::VectorXd StiffnessCholesky::Solve(const Eigen::VectorXd& rhs) const {
  return factor_.Solve(rhs);
}

void StiffnessCholesky::ApplyFlexibilityForm(const double* x, double* y) const {
  const Eigen::VectorXd u =
      factor_.SolveUpperPermuted(Eigen::Map<const Eigen::VectorXd>(x, Size()));
  Eigen::Map<Eigen::VectorXd>(y, Size()) = factor_.SolveLowerPermuted(*mass_ * u);
}

Eigen::MatrixXd StiffnessCholesky::ShapesOf(const Eigen::MatrixXd& v) const {
  return factor_.SolveUpperPermuted(v);
}

}  // namespace shockmap

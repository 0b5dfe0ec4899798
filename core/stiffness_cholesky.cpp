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

StiffnessCholesky::StiffnessCholesky(const FeStructure& s)
    : size_(s.Size()),
      mass_(&s.mass),
      factor_(std::make_unique<Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>>(s.stiffness)) {
  if (factor_->info() != Eigen::Success) RefuseStiffness(s);
  const Eigen::VectorXd pivots = factor_->matrixL().nestedExpression().diagonal();
  const Eigen::VectorXd diagonal = factor_->permutationP() * s.stiffness.diagonal();
  if ((pivots.array().square() <= kSingularPivot * diagonal.array().abs()).any()) {
    RefuseStiffness(s);
  }
}

Eigen::VectorXd StiffnessCholesky::Solve(const Eigen::VectorXd& rhs) const {
  return factor_->solve(rhs);
}

void StiffnessCholesky::ApplyFlexibilityForm(const double* x, double* y) const {
  const Eigen::VectorXd u = factor_->matrixU().solve(Eigen::Map<const Eigen::VectorXd>(x, size_));
  const Eigen::VectorXd m_u = factor_->permutationP() * (*mass_ * (factor_->permutationPinv() * u));
  Eigen::Map<Eigen::VectorXd>(y, size_) = factor_->matrixL().solve(m_u);
}

Eigen::MatrixXd StiffnessCholesky::ShapesOf(const Eigen::MatrixXd& v) const {
  return factor_->permutationPinv() * Eigen::MatrixXd(factor_->matrixU().solve(v));
}

}  // namespace shockmap

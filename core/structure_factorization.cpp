#include "core/structure_factorization.h"

#include <cmath>
#include <limits>

namespace shockmap {

ShiftedFactorization::ShiftedFactorization(const FeStructure& s, double sigma_rad2_s2)
    : sigma_(sigma_rad2_s2) {
  Eigen::SparseMatrix<double> shifted = s.stiffness;
  if (sigma_ != 0.0) shifted -= sigma_ * s.mass;
  diagonal_ = shifted.diagonal();
  factor_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>();
  factor_->analyzePattern(shifted);
  factor_->factorize(shifted);
  succeeded_ = factor_->info() == Eigen::Success;
}

int ShiftedFactorization::NegativePivots() const {
  return static_cast<int>((factor_->vectorD().array() < 0.0).count());
}

std::pair<int, double> ShiftedFactorization::WeakestPivot() const {
  // vectorD is in the permuted order: row i of the matrix is pivot P(i).
  const auto& permutation = factor_->permutationP().indices();
  std::pair<int, double> weakest{-1, std::numeric_limits<double>::infinity()};
  for (int i = 0; i < Size(); ++i) {
    const double scale = std::abs(diagonal_[i]) > 0.0 ? std::abs(diagonal_[i]) : 1.0;
    const double ratio = factor_->vectorD()[permutation[i]] / scale;
    if (ratio < weakest.second) weakest = {i, ratio};
  }
  return weakest;
}

Eigen::VectorXd ShiftedFactorization::Solve(const Eigen::VectorXd& rhs) const {
  return factor_->solve(rhs);
}

void ShiftedFactorization::Solve(const double* x, double* y) const {
  Eigen::Map<Eigen::VectorXd>(y, Size()) =
      factor_->solve(Eigen::Map<const Eigen::VectorXd>(x, Size()));
}

}  // namespace shockmap

#include "core/structure_factorization.h"

#include <cmath>
#include <limits>

namespace shockmap {

ShiftedFactorization::ShiftedFactorization(const FeStructure& s, double sigma_rad2_s2)
    : diagonal_(s.stiffness.diagonal() - sigma_rad2_s2 * s.mass.diagonal()),
      factor_(s.stiffness - sigma_rad2_s2 * s.mass, SparseCholesky::Form::kLdlt) {}

int ShiftedFactorization::NegativePivots() const {
  return static_cast<int>((factor_.PivotsByRow().array() < 0.0).count());
}

std::pair<int, double> ShiftedFactorization::WeakestPivot() const {
  if (!factor_.Succeeded()) return {factor_.FailedRow(), 0.0};
  std::pair<int, double> weakest{-1, std::numeric_limits<double>::infinity()};
  const Eigen::VectorXd pivots = factor_.PivotsByRow();
  for (int i = 0; i < pivots.size(); ++i) {
    const double scale = std::abs(diagonal_[i]) > 0.0 ? std::abs(diagonal_[i]) : 1.0;
    const double ratio = pivots[i] / scale;
    if (ratio < weakest.second) weakest = {i, ratio};
  }
  return weakest;
}

}  // namespace shockmap
